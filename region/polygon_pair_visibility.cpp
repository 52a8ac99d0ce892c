#include "region/polygon_pair_visibility.hpp"

#include "region/line_set_csg.hpp"
#include "region/stabbing_pair.hpp"

namespace exactvis::region {

PolygonPairVisibility visible_between_polygons(const Polygon3& source, const Polygon3& target,
                                               const std::vector<std::array<RationalPoint3, 3>>& occluders,
                                               const VisibilityOptions& options) {
  PolygonPairVisibility out;
  for (std::size_t k = 1; k + 1 < target.size(); ++k) {
    const std::array<RationalPoint3, 3> tri{target[0], target[k], target[k + 1]};
    if (collinear(tri[0], tri[1], tri[2])) continue;
    for (const StabbingPair& pair : stabbing_pairs(source, tri)) {
      ++out.stats.stabbing_pairs;
      const PairVisibility pv = pair_visibility(occluders, k, pair, options);
      accumulate(out.stats, pv.stats);
      if (pv.witness) {
        out.visible = true;
        out.witness = pv.witness;
        return out;
      }
    }
  }
  return out;
}

}  // namespace exactvis::region
