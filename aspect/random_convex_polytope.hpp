#pragma once
// Random closed convex polytopes for tests and benchmarks: the convex hull (CGAL convex_hull_3, exact
// predicates) of random integer points in a spherical shell, triangulated. Deterministic for a seed
// (std::mt19937 with our own integer mapping).
#include "kernel/scene.hpp"

#include <cstdint>
#include <vector>

namespace exactvis {

// The hull of `points` as a scene (one object; triangles fan-triangulated from each hull facet's first
// corner, ids 0..n-1). Input: at least four non-coplanar points.
Scene convex_hull_scene(const std::vector<Point3>& points);

// Input: number of random points (>= 4), integer coordinate range R (points with 0.6 R^2 <= |p|^2 <= R^2).
// Output: their hull; about 2 * points - 4 triangles when the points are in general position.
Scene random_convex_polytope(std::uint64_t seed, int points, int range);

}  // namespace exactvis
