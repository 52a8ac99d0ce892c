#pragma once
// Rotational sweep around a center point: the combinatorial view of a 2D scene from one point.
//
// The sweep turns a ray around `center` counterclockwise from direction (1,0). It stops at every direction
// that contains a scene vertex ("event direction") and reports what the ray meets there. Edges collinear
// with the center (including edges incident to a center vertex) are ignored: they meet only one ray.
// Between two event directions the edges met by the ray do not change order (edges are disjoint), so a
// std::set ordered by distance along the ray holds them (Lee's visibility-graph sweep).
// Cost: O(n log n) for n vertices. Exact (filtered predicates only).
#include "planar/scene2d.hpp"

#include <vector>

namespace exactvis {

struct SweepEvent2D {
  std::vector<int> vertices;  // vertices in this direction, nearest first (never the center vertex)
  int crossing = -1;          // nearest edge crossing the ray at an interior point of the edge, or -1
  int before = -1;            // nearest edge in the open sector just before this direction, or -1
  int after = -1;             // nearest edge in the open sector just after this direction, or -1
};

// Input: scene, center (free point, or the scene vertex `center_vertex`, which must equal `center`).
// Output: the event directions in counterclockwise order from (1,0). Edge ids are vertex ids of their
// first vertex (edge e goes from e to scene.next[e]).
std::vector<SweepEvent2D> angular_sweep(const Scene2D& scene, const Point2& center, int center_vertex = -1);

// For two distinct edges e1, e2 (not collinear with `center`) that both cross some open sector of rays from
// `center`: true iff e1 is met first along every ray of that sector. Exact.
bool edge_closer(const Scene2D& scene, const Point2& center, int e1, int e2);

// True iff the nearest vertex w of an event is met before the edge `crossing` (or there is none), i.e.
// the open segment center-w meets no edge interior.
bool vertex_before_crossing(const Scene2D& scene, const Point2& center, int w, int crossing);

}  // namespace exactvis
