#pragma once
// Exact check of another tool's PVS for one view cell (issue #12, `exactvis validate`): which listed
// triangles are hidden (false visible: a conservative tool's overestimate) and which missing triangles are
// visible (false invisible: an aggressive tool's error), each false invisible one with a witness.
//
// The exact answer is the exact PVS method's (region/exact_pvs.hpp: every triangle decided once, a listed
// one to see whether it is hidden, a missing one to see whether it is visible), so the exact PVS size comes
// with it; no second per-triangle loop. Answers follow docs/theory.md §5.1 (positive measure of free lines);
// hidden is proved, visible carries an exactly re-checked witness.
#include "region/cell_pvs.hpp"

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
  CellPvsStats stats;                           // of the exact PVS computation
};

// Input: the context (scene, index, ray caster), the cell (lo < hi in every coordinate), the triangles the
// other tool lists (indices into Scene::triangles, any order, repeats allowed) and the exact method's
// options (threads, progress). Output: see PvsCheck; independent of the thread count. Throws
// std::invalid_argument for an index out of range or an invalid cell. Cost: exact_cell_pvs.
PvsCheck check_reported_pvs(const PvsContext& context, const RationalBox3& cell,
                            const std::vector<std::int64_t>& reported, const PvsOptions& options = {});

}  // namespace exactvis::region
