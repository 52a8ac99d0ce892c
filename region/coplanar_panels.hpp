#pragma once
// Coplanar convex panels (docs/theory.md §5.8, "Coplanar panels as one occluder"): sets of scene triangles
// that lie in one plane, are edge-connected (shared edges: the same two corners, by exact double coordinates)
// and whose union is one convex polygon (a wall strip between windows, a roof fan, a subdivided floor, a
// triangle strip). The line-set CSG may subtract such a panel as one convex occluder: the lines meeting the
// closed polygon are exactly those meeting one of its closed triangles.
//
// The union test is exact and certifies Q = t_1 ∪ ... ∪ t_k for the reported loop Q: the triangles have one
// orientation in a projection along a coordinate axis that the plane does not contain, the edges left after
// cancelling each directed edge against its reverse form one closed loop (each once), and the loop with its
// collinear points dropped turns strictly one way with every corner on the closed inner side of every edge
// (so it is a convex polygon traversed once). The number of triangles covering a point off the edges is then
// the winding number of that loop around it: 1 inside Q, 0 outside.
#include "kernel/scene.hpp"

#include <cstdint>
#include <vector>

namespace exactvis::region {

struct CoplanarPanel {
  std::vector<std::int64_t> triangles;  // at least 2, increasing
  std::vector<Point3> loop;             // the union's corners (no collinear ones), in the triangles' orientation
};

struct CoplanarPanels {
  std::vector<CoplanarPanel> panels;
  std::vector<std::int32_t> panel_of;  // per scene triangle: index into panels, or -1
  // The fallback level: pairs, panels of exactly two triangles (coplanar, sharing an edge, convex union by the
  // same certificate), matched greedily in index order, at most one per triangle, inside one panel or across
  // two. A query uses a triangle's pair when its panel is absent or unusable there (the panel's loop crosses a
  // polygon plane of the stabbing pair, or the panel holds the target).
  std::vector<CoplanarPanel> pairs;
  std::vector<std::int32_t> pair_of;   // per scene triangle: index into pairs, or -1
};

// Input: the triangles (indices into scene.triangles, coplanar or not, any order). Output: the union's loop as
// described above when the union is one convex polygon in that sense, else empty. Exact; O(k log k).
std::vector<Point3> convex_union_loop(const Scene& scene, const std::vector<std::int64_t>& triangles);

// Input: a scene; max_greedy bounds the size of a panel grown greedily. Output: disjoint panels. Each
// connected set of coplanar edge-sharing triangles is one panel when its union is convex (any size); else
// panels are grown greedily from its lowest unassigned triangle, adding the lowest edge-adjacent triangle
// that keeps the union convex, up to max_greedy triangles. Triangles of no panel have panel_of -1. And the
// disjoint pairs: for each triangle t in increasing order without a pair, the first coplanar triangle o
// without a pair that shares t's edge 0, 1 or 2 (in that order; triangles on one edge in increasing order)
// such that t ∪ o passes the certificate. Exact; cost O(n log n) plus the greedy growth (O(max_greedy^2 log)
// per panel).
CoplanarPanels coplanar_panels(const Scene& scene, int max_greedy = 64);

}  // namespace exactvis::region
