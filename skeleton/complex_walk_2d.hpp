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
#include "planar/point_location_2d.hpp"
#include "skeleton/visibility_complex_2d.hpp"
#include "skeleton/visibility_polygon_2d.hpp"

#include <cstddef>
#include <array>
#include <functional>
#include <unordered_map>
#include <vector>

namespace exactvis {

// What the walk needs from the complex, prepared once per complex (O(n log^2 n + K log K + total pivots)).
struct ComplexWalkIndex2D {
  struct Neighbour {
    int vertex = -1;     // strictly visible vertex or ring neighbour
    int bitangent = -1;  // the free bitangent joining them, or -1
    int half = 0;        // half-turn of the direction to it: 0 for [0, pi), 1 for [pi, 2pi)
  };
  const Scene2D* scene = nullptr;                          // the scene the complex was built on (no frame)
  const VisibilityComplex2D* complex = nullptr;
  std::vector<std::vector<Neighbour>> neighbours;          // per vertex, sorted by direction (then distance)
  // A complex edge of v's tangent family, with the oriented tangent directions at v of the bitangents that
  // bound it (as vertex pairs from -> to; -1 where the family's range ends without a bitangent at v).
  struct PivotEdge {
    int edge = -1;
    int start_from = -1, start_to = -1, end_from = -1, end_to = -1;
    bool narrow = false;  // both bounds are bitangents at v and the turn from start to end is below pi
  };
  std::vector<std::vector<PivotEdge>> pivot_edges;         // per vertex: complex edges with that pivot
  struct PairHash {
    std::size_t operator()(const std::array<int, 2>& p) const {
      return std::hash<long long>()((static_cast<long long>(p[0]) << 32) ^ static_cast<unsigned>(p[1]));
    }
  };
  // end-object pair {X, Y} (sorted) -> pivots to test
  std::unordered_map<std::array<int, 2>, std::vector<int>, PairHash> candidates;
  std::vector<std::vector<int>> object_edges;              // per object: its ring edges
  PointLocation2D location;                                // start edges and input checks of q
  bool double_coordinates = false;                         // every vertex coordinate is a double
};

// Input: the scene and its complex (built by visibility_complex on that scene, without frame). The index
// keeps pointers to both: they must outlive it.
ComplexWalkIndex2D complex_walk_index(const Scene2D& scene, const VisibilityComplex2D& complex);

// Counters of one walk (to check the output-sensitive behaviour in benchmarks).
struct ComplexWalkStats2D {
  std::size_t events = 0;      // changes of a hit edge (front or back)
  std::size_t faces = 0;       // face visits (steps of the walk)
  std::size_t candidates = 0;         // candidate pivots of the faces visited
  std::size_t candidates_tested = 0;  // of those, tested with exact predicates (the rest lie certainly
                                      // outside the triangles swept until the next slide)
};

// The regularized visibility polygon of q, equal vertex for vertex to visibility_polygon(framed, q).
// `framed` must be with_frame(scene) of the index's scene (same vertex ids, frame ring appended) and q a
// free point inside it (std::invalid_argument otherwise). Cost: O(log^2 n) to check q and locate the start
// segment (the index's point location), then per step of the walk O(candidates of the face + log n), plus
// O(size of the object) to find the hit on an object appearing behind a silhouette.
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
