#include "region/pvs_check.hpp"

#include <stdexcept>
#include <string>

namespace exactvis::region {

PvsCheck check_reported_pvs(const Scene& scene, const TriangleIndex& index, const RationalBox3& cell,
                            const std::vector<std::int64_t>& reported, const CellVisibilityOptions& options) {
  const auto n = static_cast<std::int64_t>(scene.triangles.size());
  PvsCheck out;
  out.reported_visible.assign(static_cast<std::size_t>(n), false);
  for (const std::int64_t t : reported) {
    if (t < 0 || t >= n)
      throw std::invalid_argument("reported triangle index " + std::to_string(t) + " is out of range");
    if (!out.reported_visible[static_cast<std::size_t>(t)]) ++out.reported;
    out.reported_visible[static_cast<std::size_t>(t)] = true;
  }
  std::vector<std::int64_t> all(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) all[static_cast<std::size_t>(i)] = i;
  const CellVisibility cv = visibility_from_source(scene, index, {cell, {}}, all, options);
  out.stats = cv.stats;
  out.exact = cv.visible;
  out.exactly_visible.assign(static_cast<std::size_t>(n), false);
  for (const VisibilityResult& r : cv.results) {
    const auto i = static_cast<std::size_t>(r.triangle_index);
    out.exactly_visible[i] = r.visible;
    if (r.visible && !out.reported_visible[i]) {
      out.false_invisible.push_back(r.triangle_index);
      out.false_invisible_witness.push_back(*r.witness);
    } else if (!r.visible && out.reported_visible[i]) {
      out.false_visible.push_back(r.triangle_index);
    }
  }
  return out;
}

}  // namespace exactvis::region
