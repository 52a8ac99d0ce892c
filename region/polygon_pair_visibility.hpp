#pragma once
// Exact visibility between two convex polygons among occluders given as exact triangles (any rational
// corners): the unit the Quake 3 cluster check is reduced to (docs/theory.md §8, "Cluster visibility").
//
// Definition (as §5.1, with the target a polygon): T is visible from S iff the set of lines crossing relint S
// and relint T whose segment between them has an open interior missing every closed occluder triangle has
// positive measure. Method: T is fanned from its first vertex; each fan triangle t is a target of the
// stabbing pairs (S', t') of region/stabbing_pair.hpp and of the line-set CSG (region/line_set_csg.hpp) with
// every given triangle as an occluder (the fan's internal diagonals are in relint T up to a measure-zero set
// of lines, so T is visible iff some fan triangle is).
#include "region/convex_polygon_3.hpp"
#include "region/visibility_options.hpp"
#include "region/witness.hpp"

#include <array>
#include <optional>
#include <vector>

namespace exactvis::region {

struct PolygonPairVisibility {
  bool visible = false;
  std::optional<Witness> witness;  // p in relint S, q in relint T (of a fan triangle), open segment free
  VisibilityStats stats;
};

// Input: convex source and target polygons (positive area; validate_source_polygon's conditions), the
// occluders (callers pass those that can meet the segments: e.g. the ones whose box meets the polygons'
// enclosing box), options (samples per stabbing pair, seed). Output: the answer, with a witness re-checked
// exactly against every occluder. Cost: as the from-region query, per fan triangle.
PolygonPairVisibility visible_between_polygons(const Polygon3& source, const Polygon3& target,
                                               const std::vector<std::array<RationalPoint3, 3>>& occluders,
                                               const VisibilityOptions& options = {});

}  // namespace exactvis::region
