#pragma once
// Exact point location in a planar scene by horizontal ray shooting (docs/theory.md section 7, "Point
// location"): for a query point q, whether q lies on the boundary or inside an object, and the first edge
// met by each of the two horizontal rays from q, turned clockwise by an infinitesimal angle (the start of
// the walk in the visibility complex).
//
// Structure: the distinct vertex heights cut the plane into horizontal slabs; inside a slab the edges
// crossing it are disjoint and totally ordered from left to right. A segment tree over the slabs stores
// each non-horizontal edge in the O(log n) nodes whose slab ranges it spans, every node's edges sorted left
// to right; horizontal edges are kept per height, sorted by x. Every comparison is an exact
// filtered predicate (orientation2, dx_sign, dy_sign). Build O(n log^2 n) predicates, O(n log n) memory;
// query O(log^2 n) predicates.
#include "planar/scene2d.hpp"

#include <vector>

namespace exactvis {

struct PointLocation2D {
  const Scene2D* scene = nullptr;  // the located scene (must outlive the structure)
  // Vertices sorted by height; level i (the i-th distinct height) is by_height[level_start[i] ..
  // level_start[i + 1]).
  std::vector<int> by_height;
  std::vector<int> level_start;
  std::vector<int> level_of;                 // per vertex: its level
  std::vector<std::vector<int>> horizontal;  // per level: its horizontal edges, sorted by x
  std::vector<int> lower, upper;             // per edge: lower and upper endpoint (-1 for horizontal edges)
  int slabs = 0;                             // levels - 1; slab j lies between levels j and j + 1
  std::vector<std::vector<int>> node_edges;  // segment tree over the slabs (node 1 = root), left to right
};

// Builds the structure over the ring edges of `scene` (edge e runs from vertex e to next[e]); the frame, if
// any, is an ordinary ring. Keeps a pointer to the scene.
PointLocation2D point_location_2d(const Scene2D& scene);

// Where a point lies. east: the edge first met by the ray from q in direction (1, 0) turned clockwise by an
// infinitesimal, i.e. (1, -eps) (-1 if it meets none); west: likewise for (-1, 0) turned clockwise, i.e.
// (-1, +eps). Those rays pass no vertex, so each meets its edge in the edge's interior. inside_object
// (meaningful when !on_boundary): q lies in the interior of an object (strictly left of the east edge, as
// the rings are oriented); if the east ray meets nothing, q is outside every object.
struct LocatedPoint2D {
  bool on_boundary = false;  // q is a vertex or lies on an edge
  bool inside_object = false;
  int east = -1;
  int west = -1;
};

LocatedPoint2D locate_point(const PointLocation2D& location, const Point2& q);

}  // namespace exactvis
