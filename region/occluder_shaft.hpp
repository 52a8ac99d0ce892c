#pragma once
// The occluders of one stabbing pair (S', T') (docs/theory.md §5.2): the candidate triangles that can meet a
// segment from S' to T', culled against the shaft conv(S' u T') and clipped to the wedge between the two
// polygon planes, each with the side functionals of its clipped polygon's edges (the CSG subtracts the lines
// passing through all of them on one side).
#include "region/hierarchy_candidates.hpp"
#include "region/coplanar_panels.hpp"
#include "region/cone_vector6.hpp"
#include "region/stabbing_pair.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace exactvis::region {

struct ShaftOccluder {
  std::int64_t triangle = -1;  // index into Scene::triangles (or into the exact triangle list)
  std::array<Point3, 3> corners_d;  // the triangle's corners as doubles (exactly the input for scene triangles)
  std::vector<ConeVector6> edges;  // functionals of the clipped polygon's edges, in loop order
  int blocked_samples = 0;     // sample segments it blocked (orders the CSG; set by the caller)
  bool whole = false;          // the whole triangle, unclipped (the clipping shortcut): edges[i] is the line from
                               // corners_d[i] to corners_d[i + 1]
  const std::vector<Point3>* panel_loop = nullptr;  // merged into this coplanar convex panel or pair
                                                    // (merge_coplanar_panels): edges are the loop's; the
                                                    // loop's corners (for sampling; owned by the panels)
};

// Replaces the occluders that are triangles of one usable panel (region/coplanar_panels.hpp) by that panel, one
// convex occluder at the position of the first of them (the order of the others kept), its edges the lines of
// the loop's sides in loop order; then does the same with the pairs (2-triangle panels) for the occluders left
// as triangles. With whole_panels false only the pairs are merged. A panel or pair is usable when none of its
// triangles is `target` or `excluded` (may be empty) and every loop corner lies strictly inside both polygon
// planes of the pair (so the whole panel does). The lines meeting it inside the wedge are blocked by its closed
// triangles (real occluders of the query), and include those meeting the listed triangles it replaces, so the
// CSG's free set changes by a null set only (docs/theory.md §5.8). Exact (filtered side tests on the loop's
// double corners). Cost: O(m log m) for m occluders, plus the loop corners' side tests of each panel met.
void merge_coplanar_panels(std::vector<ShaftOccluder>& occluders, const CoplanarPanels& panels,
                           const StabbingPair& pair, std::int64_t target,
                           const std::function<bool(std::int64_t)>& excluded, bool whole_panels = true);

// Planes through an edge of one polygon and a vertex of the other that support conv(S' u T'), plus the two
// polygon planes; each oriented so the hull is on the side value >= 0. Exact.
std::vector<Plane3> shaft_planes(const StabbingPair& pair);

// The candidates (indices into Scene::triangles, `target` skipped) that are not entirely on the closed outer
// side of a shaft plane and whose part between the two polygon planes has positive area off both planes
// (culling the others changes only a measure-zero set of segments, docs/theory.md §5.2), in candidate order.
// Exact (a filtered side test per corner and plane).
// Shortcut (docs/theory.md §5.4): a triangle whose three corners the filtered side tests put strictly inside
// both polygon planes is its own clipped polygon; its edge functionals are then computed from the double
// corners in the fixed layer (side_functional_of_doubles), without rational clipping. Same output.
std::vector<ShaftOccluder> shaft_occluders(const Scene& scene, const std::vector<std::int64_t>& candidates,
                                           std::int64_t target, const StabbingPair& pair);

// The same output as shaft_occluders(scene, finder(box), target, pair), with the candidates gathered by
// finder.pruned: a hierarchy box that the filtered side test certifies strictly outside one shaft plane is
// skipped with all its triangles (each would be culled above), so the cost follows the shaft's surroundings,
// not the number of triangles in `box` (docs/theory.md §5.2).
std::vector<ShaftOccluder> shaft_occluders(const Scene& scene, const HierarchyCandidates& finder, const Box3& box,
                                           std::int64_t target, const StabbingPair& pair);

// The same culling and clipping for occluders given as exact triangles (any rational corners; every one of
// them is an occluder); ShaftOccluder::triangle is then the index into `triangles` and corners_d the corners
// rounded to doubles (they only order the CSG through sampling). Exact.
std::vector<ShaftOccluder> shaft_occluders(const std::vector<std::array<RationalPoint3, 3>>& triangles,
                                           const StabbingPair& pair);

}  // namespace exactvis::region
