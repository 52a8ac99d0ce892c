#pragma once
// A regular grid of view cells over a box (`exactvis pvs --grid NX,NY,NZ`), with exact rational corners.
#include "region/convex_polygon_3.hpp"

#include <array>
#include <vector>

namespace exactvis::region {

// Input: a box with lo < hi in every coordinate and counts n[k] >= 1. Output: the n[0] n[1] n[2] cells,
// x fastest: cell (i, j, k) has index i + n0 (j + n1 k) and corners lo + (i, j, k) * (hi - lo) / n exactly
// (neighbours share their faces exactly). Throws std::invalid_argument for a flat or inverted box or a count
// below 1. Cost: O(cells).
std::vector<RationalBox3> grid_cells(const RationalBox3& box, const std::array<long, 3>& n);

}  // namespace exactvis::region
