#pragma once
// Exact check of another tool's PVS for one view cell (issue #12, `exactvis validate`): which listed
// triangles are hidden (false visible: a conservative tool's overestimate) and which missing triangles are
// visible (false invisible: an aggressive tool's error), each false invisible one with a witness.
//
// Every triangle of the scene is decided once by the exact from-region query (region/cell_visibility.hpp:
// a listed triangle to see whether it is hidden, a missing one to see whether it is visible), so the exact
// PVS size comes for free; no separate PVS pass is made. Answers follow docs/theory.md §5.1 (positive
// measure of free lines); hidden is proved, visible carries an exactly re-checked witness.
#include "region/cell_visibility.hpp"

#include <cstdint>
#include <vector>

namespace exactvis::region {

struct PvsCheck {
  std::vector<bool> exactly_visible;            // per scene triangle (index order): the exact answer
  std::vector<bool> reported_visible;           // per scene triangle: listed by the other tool
  std::vector<std::int64_t> false_visible;      // indices into Scene::triangles, increasing
  std::vector<std::int64_t> false_invisible;    // indices into Scene::triangles, increasing
  std::vector<Witness> false_invisible_witness; // parallel to false_invisible
  std::int64_t exact = 0;                       // size of the exact PVS
  std::int64_t reported = 0;                    // distinct triangles listed
  VisibilityStats stats;                        // accumulated over the queries
};

// Input: the scene, its index, the cell (lo < hi in every coordinate), the triangles the other tool lists
// (indices into Scene::triangles, any order, repeats allowed) and the query options (threads, progress
// callback once per triangle). Output: see PvsCheck; independent of the thread count. Throws
// std::invalid_argument for an index out of range or an invalid cell. Cost: one exact from-region query per
// scene triangle (region/from_region_visibility.hpp), divided among the threads.
PvsCheck check_reported_pvs(const Scene& scene, const TriangleIndex& index, const RationalBox3& cell,
                            const std::vector<std::int64_t>& reported, const CellVisibilityOptions& options = {});

}  // namespace exactvis::region
