#pragma once
// Output-sensitive construction of the visibility graph of a 2D scene: one rotational sweep of the
// direction theta for all vertices at once (docs/theory.md, section 7, "Construction").
//
// Every vertex p keeps its *view*: what the ray from p in direction theta+ (just counterclockwise of the
// current direction) meets first: its own object, an edge interior, or infinity. The vertices viewing
// one edge (or infinity) are kept in a list ordered across the ray direction. A view changes only when
// the ray of p passes a vertex q; then p's new view is an edge of q or q's own view (inheritance, the
// rotation-tree principle). Such a q is either the counterclockwise end of p's viewed edge or p's
// neighbour in the list (a vertex appearing in the middle of p's view is, just before, a viewer of the
// same edge next to p), so each event is a visible pair or a local event at p's own edges, found in
// exact direction order with a priority queue: O((n + K) log n) for n vertices and K visible pairs,
// after an O(n log n) plane sweep for the views at the start direction.
#include "skeleton/visibility_graph_2d.hpp"

#include <vector>

namespace exactvis {

// Input: a scene (a frame, if present, takes part like any ring). Output: for every vertex p, the
// vertices w it sees strictly (open segment p-w in the open free space), each once, with the tangency
// flag and, for tangent pairs, the end of the maximal free segment beyond w (visibility_graph_2d.hpp).
// The two half-turns of directions run in parallel (two threads); `progress` (may be null) gets the swept
// fraction of the first half-turn.
std::vector<std::vector<VisibleFrom2D>> rotational_visible_pairs(const Scene2D& scene,
                                                                 void (*progress)(double) = nullptr);

// A ray from scene vertex `vertex` in direction `to - from` (points outside the scene; they must stay
// alive during the call). The direction must not run along an edge of the vertex.
struct RayQuery2D {
  int vertex = 0;
  const Point2* from = nullptr;
  const Point2* to = nullptr;
};

// The first boundary point met by each ray (as first_contact in visibility_complex_2d.hpp, without the
// contact point: kind, id and object only), all answered by one rotational sweep: O((n + k + m) log n)
// for m queries instead of O(n) per ray.
std::vector<SegmentEnd2D> rotational_first_contacts(const Scene2D& scene, const std::vector<RayQuery2D>& queries);

// Visibility polygons of many free points at once (see visibility_polygons in visibility_polygon_2d.hpp):
// the points take part in the sweep as viewers that block nothing; each one's polygon gets the two ray
// hits wherever its viewed edge changes. Input: a scene with a frame. Throws std::invalid_argument if a
// point lies on a boundary, inside an object or outside the frame. O((n + K + sum of output) log n).
std::vector<std::vector<Point2>> rotational_visibility_polygons(const Scene2D& scene,
                                                                const std::vector<Point2>& points);

}  // namespace exactvis
