#pragma once
// A convex polygon minus a union of convex polygons, exact, in a 2D chart (docs/theory.md section 11,
// "Visible part of the light without Boolean set operations"): the visible part of a light triangle once the
// hidden polygons of its blockers are known (shadows/backprojection).
//
// Method: the difference is kept as interior-disjoint convex cells, starting from the base polygon; each
// subtrahend H (counterclockwise, edge lines l_1..l_m, H on their left) replaces every cell C whose interior
// meets H's by the pieces C ∩ {l_1 <= 0}, C ∩ {l_1 >= 0} ∩ {l_2 <= 0}, ... (those of positive area). Sides
// are decided by a BoundedDouble filter with the exact rational sign as fallback, crossing points are exact
// rationals. A piece has positive area iff one of its cell's vertices lies strictly on its side (a convex
// cell of positive area meets every open half-plane holding one of its points in positive area), so no area
// is computed before the end. The cells depend on the order of the subtrahends; the output does not: it is
// the canonical boundary of their union (shadows/cell_union_boundary.hpp). Regularised: sets of zero area
// (a subtrahend touching the rest along a segment) are dropped, as CGAL's regularised Boolean operations do.
#include "shadows/cell_union_boundary.hpp"

#include <vector>

namespace exactvis::shadows {

// The points as a convex polygon: consecutive repeated and collinear vertices removed, counterclockwise.
// Input: the vertices of a convex polygon in order (either orientation). Output: empty when the polygon has
// zero area. Exact. Cost: O(n) filtered orientation tests.
std::vector<ChartPoint> normalized_convex_polygon(const std::vector<ChartPoint>& points);

// Input: base, counterclockwise convex with positive area; subtrahends, each counterclockwise convex with
// positive area and no collinear vertices (normalized_convex_polygon's output). Output: the canonical
// boundary of the closure of base minus the union of the subtrahends, and its exact area; `cells` the
// convex cells it was built from (a cost figure). Exact. Cost: per subtrahend, a box test and O(m) filtered
// side tests per current cell, and a split of each cell it overlaps into at most m + 1 pieces; then
// cell_union_boundary.
struct ConvexDifference {
  ChartRegion region;
  std::size_t cells = 0;
};
ConvexDifference convex_difference(const std::vector<ChartPoint>& base,
                                   const std::vector<std::vector<ChartPoint>>& subtrahends);

}  // namespace exactvis::shadows
