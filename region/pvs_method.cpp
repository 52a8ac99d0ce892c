#include "region/pvs_method.hpp"

#include "region/conservative_pvs.hpp"
#include "region/exact_pvs.hpp"
#include "region/sampled_pvs.hpp"

#include <stdexcept>

namespace exactvis::region {

const std::vector<std::string>& pvs_method_names() {
  static const std::vector<std::string> names{"exact", "sampled", "conservative"};
  return names;
}

PvsMethod parse_pvs_method(const std::string& name) {
  if (name == "exact") return PvsMethod::exact;
  if (name == "sampled") return PvsMethod::sampled;
  if (name == "conservative") return PvsMethod::conservative;
  std::string known;
  for (const auto& n : pvs_method_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown PVS method '" + name + "' (known: " + known + ")");
}

std::string pvs_method_name(PvsMethod method) {
  switch (method) {
    case PvsMethod::exact: return "exact";
    case PvsMethod::sampled: return "sampled";
    case PvsMethod::conservative: return "conservative";
  }
  return "?";
}

CellPvs compute_cell_pvs(PvsMethod method, const PvsContext& context, const RationalBox3& cell,
                         const PvsOptions& options) {
  switch (method) {
    case PvsMethod::exact: return exact_cell_pvs(context, cell, options);
    case PvsMethod::sampled: return sampled_cell_pvs(context, cell, options);
    case PvsMethod::conservative: return conservative_cell_pvs(context, cell, options);
  }
  throw std::logic_error("compute_cell_pvs: unhandled method");
}

}  // namespace exactvis::region
