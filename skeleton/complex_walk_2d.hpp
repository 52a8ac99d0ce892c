#pragma once
// Visibility polygon of a point answered from the stored visibility complex: a walk along the curve of
// maximal free segments through the point (docs/theory.md, section 7, "Queries from the complex").
//
// The lines through q, turned counterclockwise over the directions [0, pi), cut out one maximal free
// segment each; as the line turns, the segment moves through faces of the complex. Within a face (end
// objects {X, Y}) its two hit points slide along X and Y, and the next change of either hit edge is
// - a slide: a hit point reaches the counterclockwise end of its edge (known from the scene), or
// - an appearance: the segment becomes tangent at a vertex w of a third object between q and a hit point;
//   the tangent segment then lies on an edge of the complex whose sample segment has the end objects
//   {X, Y}: so only the pivots of the complex edges with end objects {X, Y} (the face's candidates) are
//   tested, never all vertices.
// After a change, the new hit edge is found locally: at a blocking vertex from its two edges; beyond a
// silhouette vertex y from the complex (the visible vertex in that direction from y's sorted neighbours in
// the visibility graph, else the bitangent's stored end, else the end object of the complex edge of y's
// tangent family holding that direction, whose own edges are then scanned).
// Every decision is an exact filtered predicate; the result is vertex for vertex equal to
// visibility_polygon(with_frame(scene), q) (tested).
#include "skeleton/visibility_complex_2d.hpp"
#include "skeleton/visibility_polygon_2d.hpp"

#include <cstddef>
#include <array>
#include <map>
#include <vector>

namespace exactvis {

// What the walk needs from the complex, prepared once per complex (O(n + K log K + total pivots)).
struct ComplexWalkIndex2D {
  struct Neighbour {
    int vertex = -1;     // strictly visible vertex or ring neighbour
    int bitangent = -1;  // the free bitangent joining them, or -1
  };
  const Scene2D* scene = nullptr;                          // the scene the complex was built on (no frame)
  const VisibilityComplex2D* complex = nullptr;
  std::vector<std::vector<Neighbour>> neighbours;          // per vertex, sorted by direction (then distance)
  std::vector<std::vector<int>> pivot_edges;               // per vertex: complex edges with that pivot
  std::map<std::array<int, 2>, std::vector<int>> candidates;  // end-object pair {X, Y} -> pivots to test
  std::vector<std::vector<int>> object_edges;              // per object: its ring edges
};

// Input: the scene and its complex (built by visibility_complex on that scene, without frame). The index
// keeps pointers to both: they must outlive it.
ComplexWalkIndex2D complex_walk_index(const Scene2D& scene, const VisibilityComplex2D& complex);

// Counters of one walk (to check the output-sensitive behaviour in benchmarks).
struct ComplexWalkStats2D {
  std::size_t events = 0;      // changes of a hit edge (front or back)
  std::size_t faces = 0;       // face visits (steps of the walk)
  std::size_t candidates = 0;  // candidate pivots tested
};

// The regularized visibility polygon of q, equal vertex for vertex to visibility_polygon(framed, q).
// `framed` must be with_frame(scene) of the index's scene (same vertex ids, frame ring appended) and q a
// free point inside it (std::invalid_argument otherwise). Cost: O(n) to locate the start segment (an
// exact scan of all edges: no point location structure), then per step of the walk O(candidates of the
// face + log n), plus O(size of the object) to find the hit on an object appearing behind a silhouette.
// If `visible_edges` is given, it receives the ids of the edges of which q sees a part of positive length
// (sorted; frame edges included), equal to visible_edges(framed, q).
VisibilityPolygon2D visibility_polygon_in_complex(const ComplexWalkIndex2D& index, const Scene2D& framed,
                                                  const Point2& q, ComplexWalkStats2D* stats = nullptr,
                                                  std::vector<int>* visible_edges = nullptr);

// visibility_polygon_in_complex for many points, on all cores (oneTBB; the index is read-only). Throws
// std::invalid_argument for the first bad point, like the single query.
std::vector<VisibilityPolygon2D> visibility_polygons_in_complex(const ComplexWalkIndex2D& index,
                                                                const Scene2D& framed,
                                                                const std::vector<Point2>& points);

}  // namespace exactvis
