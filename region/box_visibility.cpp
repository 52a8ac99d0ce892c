#include "region/box_visibility.hpp"

#include "region/line_set_csg.hpp"
#include "region/stabbing_pair.hpp"

namespace exactvis::region {

bool boxes_meet(const RationalBox3& cell, const Box3& box) {
  for (int k = 0; k < 3; ++k)
    if (Exact(box.hi[k]) < cell.lo[k] || cell.hi[k] < Exact(box.lo[k])) return false;
  return true;
}

namespace {

// The loop of box_may_be_visible; `pair_query` decides one stabbing pair against the occluders.
// options.split_budget (> 0) bounds the splits of the whole test: each pair gets what the earlier ones left.
template <class PairQuery>
BoxReach box_reached(const RationalBox3& cell, const Box3& box, const VisibilityOptions& options,
                     VisibilityStats& stats, const PairQuery& pair_query) {
  VisibilityOptions pair_options = options;
  const std::int64_t splits_before = stats.splits;
  const RationalBox3 b = exact_box(box);
  for (int axis = 0; axis < 3; ++axis)
    for (bool high : {false, true}) {
      // Segments reach B first through a face whose outer open half-space holds their start in the cell.
      const bool faces_cell = high ? cell.hi[axis] > b.hi[axis] : cell.lo[axis] < b.lo[axis];
      if (!faces_cell) continue;
      // A flat box (all its triangles in one plane) has a degenerate face: its area is the face itself.
      const Polygon3 face = box_face(b, axis, high);
      if (is_degenerate(face)) continue;  // zero-area face: reached only by a measure-zero set of lines
      // The face is one convex target (not two triangles): the same free lines (§5.8), half the pairs.
      for (int ca = 0; ca < 3; ++ca)
        for (bool chigh : {false, true}) {
          const Exact& plane = chigh ? cell.hi[ca] : cell.lo[ca];
          bool in_front = false;
          for (const auto& c : face) in_front |= chigh ? (c[ca] > plane) : (c[ca] < plane);
          if (!in_front) continue;
          for (const StabbingPair& pair : stabbing_pairs(box_face(cell, ca, chigh), face)) {
            ++stats.stabbing_pairs;
            if (options.split_budget > 0) {
              pair_options.split_budget = options.split_budget - (stats.splits - splits_before);
              if (pair_options.split_budget <= 0) return {true, true};  // spent by the earlier pairs
            }
            const PairVisibility pv = pair_query(pair, pair_options);
            accumulate(stats, pv.stats);
            if (pv.witness) return {true, false};
            if (pv.gave_up) return {true, true};  // no proof for this pair: the box may be visible (descending is sound)
          }
        }
    }
  return {false, false};
}

}  // namespace

BoxReach box_may_be_visible(const Scene& scene, const std::vector<std::int64_t>& occluders, const RationalBox3& cell,
                            const Box3& box, const VisibilityOptions& options, VisibilityStats& stats) {
  return box_reached(cell, box, options, stats, [&](const StabbingPair& pair, const VisibilityOptions& o) {
    return pair_visibility(scene, occluders, -1, pair, o);
  });
}

BoxReach box_may_be_visible(const Scene& scene, const HierarchyCandidates& occluders, const Box3& query_box,
                            const RationalBox3& cell, const Box3& box, const VisibilityOptions& options,
                            VisibilityStats& stats) {
  return box_reached(cell, box, options, stats, [&](const StabbingPair& pair, const VisibilityOptions& o) {
    return pair_visibility(scene, occluders, query_box, -1, pair, o);
  });
}

}  // namespace exactvis::region
