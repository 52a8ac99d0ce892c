#pragma once
// Where from-region queries get their candidate occluders: a function from a box to (at least) every scene
// triangle whose bounding box meets it.
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace exactvis::region {

// Returns indices into Scene::triangles of (at least) every triangle whose bounding box meets `box`.
// Must be callable from several threads at once.
using CandidateFinder = std::function<std::vector<std::int64_t>(const Box3& box)>;

// Brute-force candidate finder (for tests and tiny scenes): O(n) per query. The scene must outlive it.
CandidateFinder brute_force_candidates(const Scene& scene);

// The index's candidates_in_box (the finder holds a copy of the index, which shares its tree).
CandidateFinder index_candidates(const TriangleIndex& index);

}  // namespace exactvis::region
