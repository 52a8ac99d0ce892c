#pragma once
// A planar scene for the 2D visibility complex: disjoint simple polygons with holes, as oriented rings.
//
// Conventions (docs/theory.md, section 7):
// - Object i is the i-th input polygon (outer ring, then its holes). Vertices are numbered in input order
//   (polygon by polygon, ring by ring); edge e is the ring edge from vertex e to next[e].
// - Every ring is re-oriented so that its object lies to the LEFT of each edge: outer rings counterclockwise,
//   holes clockwise. A ring with the obstacle on its right would make "free space" mean the other side.
// - Optionally a frame ring (a box, obstacle outside) bounds the free space; its object index is
//   `num_objects` and `frame_ring` names it. Queries that need a bounded free space add one.
#include "planar/point2d.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace exactvis {

// Invalid 2D scene (self-intersecting or overlapping polygons, duplicate vertices, ...); one-line what().
struct Scene2DError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Input polygon: rings[0] is the outer boundary, rings[1..] its holes; any orientation; no repeated
// closing vertex.
struct PolygonInput2D {
  std::vector<std::vector<Point2>> rings;
};

struct Ring2D {
  int first = 0, size = 0;  // vertices first .. first+size-1, in ring order (object on the left)
  int object = 0;
  bool hole = false;        // a hole of its object (free space inside)
};

struct Scene2D {
  std::vector<Point2> points;     // one per vertex
  std::vector<int> ring_of;       // per vertex
  std::vector<int> next, prev;    // per vertex, along its ring (object on the left of vertex -> next)
  std::vector<int> input_index;   // per vertex: position in its input ring (before re-orientation)
  std::vector<Ring2D> rings;
  int num_objects = 0;            // input polygons (the frame, if any, is not counted)
  int frame_ring = -1;            // index into rings of the bounding frame, or -1

  int num_vertices() const { return static_cast<int>(points.size()); }
  int object_of(int v) const { return rings[ring_of[v]].object; }
};

// Builds and validates a scene. Throws Scene2DError (one line) when: a ring has < 3 vertices or zero area,
// two vertices coincide, two edges intersect other than consecutive edges at their common vertex, or
// consecutive edges overlap, a hole is not inside its outer ring, holes nest, or polygons overlap.
Scene2D make_scene2d(const std::vector<PolygonInput2D>& polygons);

// The frame box of with_frame(scene, margin_ratio): the vertices' bounding box widened on every side by
// m = max(1, margin_ratio * larger side), corners rounded outward to integers (to the next double when that
// does not move them), so the box contains every vertex strictly. `representable` is false when a corner
// would lie beyond the largest double (about 1.8e308), or margin_ratio is not a finite number >= 0: such a
// frame cannot be built (docs/theory.md, section 7, "Coordinate range"). O(n).
struct FrameBox2D {
  double lo_x = 0, lo_y = 0, hi_x = 0, hi_y = 0;
  bool representable = false;
};
FrameBox2D frame_box(const Scene2D& scene, double margin_ratio);

// The scene plus a frame: the axis-parallel box frame_box(scene, margin_ratio) as a ring (obstacle outside).
// Throws Scene2DError (one line) when that box is not representable.
Scene2D with_frame(const Scene2D& scene, double margin_ratio = 0.5);

// Exact tests of p against the ring pts[first .. first+size-1] (closed, any orientation): inside_ring by
// crossing number (p must not lie on the ring), on_ring iff p lies on one of its edges (vertices included).
bool inside_ring(const std::vector<Point2>& pts, int first, int size, const Point2& p);
bool on_ring(const std::vector<Point2>& pts, int first, int size, const Point2& p);

// True iff p lies strictly inside the frame box of `framed` (a scene made by with_frame). Exact.
bool frame_contains(const Scene2D& framed, const Point2& p);

// with_frame(scene, margin_ratio), the margin widened (doubled plus one, repeatedly) until the frame contains
// every point of `points` strictly, or until the next widening would not be representable; callers check
// frame_contains when the points may lie beyond every representable frame. Throws as with_frame.
Scene2D with_frame_around(const Scene2D& scene, const std::vector<Point2>& points, double margin_ratio);

// True iff point p lies in the interior of some object (not on a boundary, not in free space).
// Exact. O(number of vertices).
bool inside_obstacle(const Scene2D& scene, const Point2& p);
// True iff p lies on some ring edge (including vertices). Exact.
bool on_boundary(const Scene2D& scene, const Point2& p);

}  // namespace exactvis
