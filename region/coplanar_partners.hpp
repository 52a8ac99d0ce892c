#pragma once
// Pairs of scene triangles whose union is one convex quadrilateral (docs/theory.md §5.8, "Coplanar pairs as one
// occluder"): two triangles sharing an edge (the same two corners, by exact double coordinates), coplanar
// (exact orient3d), with the union strictly convex (the two diagonals cross at interior points, exact
// orientations in a projection the triangles do not degenerate in). Matched greedily in index order, so each
// triangle has at most one partner. The line-set CSG may then subtract such a pair as one quadrilateral
// occluder: the lines meeting the closed quadrilateral are exactly those meeting one of the two closed triangles.
#include "kernel/scene.hpp"

#include <cstdint>
#include <vector>

namespace exactvis::region {

// Input: a scene. Output: partner[t] = the index of t's partner triangle, or -1 (partner[partner[t]] == t).
// Exact; cost O(n log n).
std::vector<std::int64_t> coplanar_partners(const Scene& scene);

}  // namespace exactvis::region
