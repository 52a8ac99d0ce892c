#include "region/hierarchy_candidates.hpp"

#include "region/convex_polygon_3.hpp"
#include "region/witness.hpp"

#include <algorithm>

namespace exactvis::region {
using hierarchy_detail::overlap;

std::vector<std::int64_t> HierarchyCandidates::operator()(const Box3& box) const {
  std::vector<std::int64_t> out = index.candidates_in_box(box);
  if (excluded) out.erase(std::remove_if(out.begin(), out.end(), [&](std::int64_t t) { return excluded(t); }), out.end());
  return out;
}

bool segment_is_free(const Scene& scene, const HierarchyCandidates& finder, const Box3& box, const RationalPoint3& p,
                     const RationalPoint3& q, std::int64_t skip) {
  const Box3 around = enclosing_box({p, q});
  return segment_is_free(scene, finder.pruned_with(box, [&around](const Box3& b) { return !overlap(b, around); }), p, q,
                         skip);
}

CandidateFinder hierarchy_candidates(const TriangleIndex& index, const Scene& scene, const TriangleBvh& bvh) {
  return HierarchyCandidates{index, &scene, &bvh, {}};
}

}  // namespace exactvis::region
