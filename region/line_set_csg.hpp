#pragma once
// The line-set CSG of one stabbing pair (docs/theory.md §5.3, §5.4): the stabbing lines of (S', T') form an
// open cone of Plücker space (with the quadric); each occluder's line set is subtracted by splitting the cone
// along the occluder's edge hyperplanes, and a piece survives only while it still contains real lines. A
// piece that no occluder touches proves visibility and yields a witness. Random sample segments come first
// (a sample found free and re-checked exactly is a witness too) and order the occluders by how much they
// block.
#include "kernel/scene.hpp"
#include "region/hierarchy_candidates.hpp"
#include "region/stabbing_pair.hpp"
#include "region/visibility_options.hpp"
#include "region/witness.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace exactvis::region {

struct PairVisibility {
  std::optional<Witness> witness;  // a free segment from relint S' to relint T', exactly re-checked; none:
                                   // the pair carries no set of free segments of positive measure
  VisibilityStats stats;           // this pair's counters (exact_evaluations not counted here)
  bool gave_up = false;            // options.split_budget was reached first: neither a witness nor a proof
                                   // (witness is then empty and means nothing)
};

// Input: the scene, the candidate occluders of the whole query (indices into Scene::triangles), the target
// triangle's index, one of its stabbing pairs, and the options (samples, seed). Exact; deterministic for a
// given seed. Cost: the samples, then the CSG (exponential in the number of effective occluders in the worst
// case, docs/performance.md), at most about options.split_budget splits when that is set.
PairVisibility pair_visibility(const Scene& scene, const std::vector<std::int64_t>& candidates, std::int64_t target,
                               const StabbingPair& pair, const VisibilityOptions& options);

// The same answer, stats and witness as pair_visibility(scene, finder(box), target, pair, options) (`box`:
// the box of the whole query), without listing finder(box): the shaft occluders are gathered through
// finder.pruned, skipping hierarchy boxes outside a shaft plane (region/occluder_shaft.hpp), and each exact
// re-check of a witness segment through the boxes that meet the segment's. Cost: follows the triangles near
// the shaft, not those of `box` (with a finder that has a hierarchy).
PairVisibility pair_visibility(const Scene& scene, const HierarchyCandidates& finder, const Box3& box, std::int64_t target,
                               const StabbingPair& pair, const VisibilityOptions& options);

// The same for occluders given as exact triangles (any rational corners, e.g. the exact boundaries of a
// Quake 3 map's solids; every one of them is an occluder, none is skipped). `stream` varies the random
// sequence (e.g. per target). Exact; deterministic for a given seed and stream.
PairVisibility pair_visibility(const std::vector<std::array<RationalPoint3, 3>>& occluders, std::uint64_t stream,
                               const StabbingPair& pair, const VisibilityOptions& options);

}  // namespace exactvis::region
