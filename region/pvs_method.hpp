#pragma once
// The PVS methods of `exactvis pvs --method`: each is one function from (context, cell, options) to the same
// per-cell result (region/cell_pvs.hpp). Adding a method: a value here, its name, and one case below.
#include "region/cell_pvs.hpp"

#include <string>
#include <vector>

namespace exactvis::region {

enum class PvsMethod {
  exact,    // region/exact_pvs.hpp: every triangle decided exactly, witnesses checked exactly
  sampled,  // region/sampled_pvs.hpp: random rays per cell, each hit confirmed exactly (aggressive)
  conservative,  // region/conservative_pvs.hpp: only triangles proved hidden are left out (overestimates)
};

// The method names --method accepts, in order ("exact", "sampled", "conservative").
const std::vector<std::string>& pvs_method_names();
// The method called `name`; throws std::invalid_argument ("unknown PVS method 'NAME' (known: ...)").
PvsMethod parse_pvs_method(const std::string& name);
std::string pvs_method_name(PvsMethod method);

// The PVS of `cell` by `method`.
CellPvs compute_cell_pvs(PvsMethod method, const PvsContext& context, const RationalBox3& cell,
                         const PvsOptions& options);

}  // namespace exactvis::region
