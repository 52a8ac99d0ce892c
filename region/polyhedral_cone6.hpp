#pragma once
// Open polyhedral cones of R^6 given by strict linear inequalities, kept in double description:
// the constraints AND the generators (extreme rays + lineality basis) of the closure, with exact integers.
//
// The line sets of from-region visibility are such cones intersected with the Plücker quadric: every
// constraint is side(x, e) > 0 for a real line e (an edge of the source, the target or an occluder).
// Splitting by one more hyperplane is one step of the double description method (Motzkin et al.; Fukuda and
// Prodon 1996): rays on the kept side stay, new rays are positive combinations of adjacent pairs across the
// hyperplane (combinatorial adjacency test).
#include "region/cone_vector6.hpp"
#include "region/incidence_set.hpp"

#include <boost/container/small_vector.hpp>

#include <array>
#include <optional>
#include <vector>

namespace exactvis::region {

// Vectors are ConeVector6 (region/cone_vector6): int64 components where they fit, GMP beyond, each with its
// double approximation, so that copying a cone and deciding its signs allocate nothing in the common case.
struct PolyhedralCone6 {
  // Open cone K = {x : w . x > 0 for every w in constraints}. Invariant: K is non-empty (full-dimensional).
  std::vector<ConeVector6> constraints;
  // Closure of K = cone(rays) + span(lineality).
  std::vector<ConeVector6> rays;
  std::vector<IncidenceSet> incidence;  // incidence[r][i] <=> constraints[i] . rays[r] == 0
  std::vector<ConeVector6> lineality;              // basis; every constraint vanishes on it
};

// R^6 itself (no constraint; lineality = the unit vectors).
PolyhedralCone6 whole_space_cone();

enum class HalfspaceRelation {
  Inside,    // w >= 0 on the closure: K is already inside {w > 0}
  Outside,   // w <= 0 on the closure: K does not meet {w > 0}
  Crossing,  // both sides
};

// Where the closure of K lies with respect to the hyperplane w . x = 0. Exact (layered signs of w . r).
HalfspaceRelation relation_to_halfspace(const PolyhedralCone6& cone, const ConeVector6& w);
HalfspaceRelation relation_to_halfspace(const PolyhedralCone6& cone, const IntVec6& w);

// K intersected with the open halfspace {w . x > 0}; std::nullopt when that is empty. The ray signs are
// layered (filter, fixed, gmp); new rays are eliminate()d (fixed layer unless it overflows), and only for
// the adjacent pairs that are combined.
std::optional<PolyhedralCone6> intersect_open_halfspace(const PolyhedralCone6& cone, const ConeVector6& w);
std::optional<PolyhedralCone6> intersect_open_halfspace(const PolyhedralCone6& cone, const IntVec6& w);

// The signs of w . r for every ray r of K, computed once, and the relation they give (the same as
// relation_to_halfspace). by_lineality: some lineality direction has w . b != 0 (then relation is Crossing
// and ray_signs is left empty). Cost: one layered sign per ray (and per lineality direction).
struct HyperplaneSigns {
  HalfspaceRelation relation = HalfspaceRelation::Outside;
  bool by_lineality = false;
  boost::container::small_vector<signed char, 64> ray_signs;
};
HyperplaneSigns hyperplane_signs(const PolyhedralCone6& cone, const ConeVector6& w);

// Both parts of a cone the hyperplane w . x = 0 crosses through its rays (signs.relation == Crossing and
// !signs.by_lineality): [0] = intersect_open_halfspace(cone, w), [1] = intersect_open_halfspace(cone,
// w.negated()), the same cones (constraints, rays in the same order, incidences). Each new ray on the
// hyperplane is computed once for both parts (the combination of an adjacent pair is the same vector from
// either side), and adjacency is tested once per pair. Cost: about half of the two calls.
std::array<PolyhedralCone6, 2> split_crossing(const PolyhedralCone6& cone, const ConeVector6& w,
                                              const HyperplaneSigns& signs);

// An interior point of K (sum of the rays; lineality adds nothing needed). Requires rays non-empty or
// lineality == whole space.
IntVec6 interior_point(const PolyhedralCone6& cone);

// True iff x lies in the closure of K (every constraint >= 0) / in K (every constraint > 0).
bool in_closure(const PolyhedralCone6& cone, const IntVec6& x);
bool in_open_cone(const PolyhedralCone6& cone, const IntVec6& x);

}  // namespace exactvis::region
