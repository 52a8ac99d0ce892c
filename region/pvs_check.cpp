#include "region/pvs_check.hpp"

#include "region/exact_pvs.hpp"

#include <stdexcept>
#include <string>

namespace exactvis::region {

PvsCheck check_reported_pvs(const PvsContext& context, const RationalBox3& cell,
                            const std::vector<std::int64_t>& reported, const PvsOptions& options) {
  const auto n = static_cast<std::int64_t>(context.scene().triangles.size());
  PvsCheck out;
  out.reported_visible.assign(static_cast<std::size_t>(n), false);
  for (const std::int64_t t : reported) {
    if (t < 0 || t >= n)
      throw std::invalid_argument("reported triangle index " + std::to_string(t) + " is out of range");
    if (!out.reported_visible[static_cast<std::size_t>(t)]) ++out.reported;
    out.reported_visible[static_cast<std::size_t>(t)] = true;
  }
  const CellPvs pvs = exact_cell_pvs(context, cell, options);
  out.stats = pvs.stats;
  out.exact = static_cast<std::int64_t>(pvs.visible.size());
  out.exactly_visible.assign(static_cast<std::size_t>(n), false);
  for (const VisibleTriangle& v : pvs.visible) {
    out.exactly_visible[static_cast<std::size_t>(v.index)] = true;
    if (!out.reported_visible[static_cast<std::size_t>(v.index)]) {
      out.false_invisible.push_back(v.index);
      out.false_invisible_witness.push_back(*v.witness);
    }
  }
  for (std::int64_t i = 0; i < n; ++i)
    if (out.reported_visible[static_cast<std::size_t>(i)] && !out.exactly_visible[static_cast<std::size_t>(i)])
      out.false_visible.push_back(i);
  return out;
}

}  // namespace exactvis::region
