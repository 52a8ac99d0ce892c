#include "region/view_cell_grid.hpp"

#include "region/cell_pvs.hpp"

#include <stdexcept>

namespace exactvis::region {

std::vector<RationalBox3> grid_cells(const RationalBox3& box, const std::array<long, 3>& n) {
  check_view_cell(box);
  for (int k = 0; k < 3; ++k)
    if (n[k] < 1) throw std::invalid_argument("grid counts must be at least 1");
  // Exact planes of each axis: lo + i (hi - lo) / n, the last one exactly hi.
  std::array<std::vector<Exact>, 3> planes;
  for (int k = 0; k < 3; ++k)
    for (long i = 0; i <= n[k]; ++i)
      planes[k].push_back(i == n[k] ? box.hi[k] : box.lo[k] + (box.hi[k] - box.lo[k]) * Exact(i) / Exact(n[k]));
  std::vector<RationalBox3> out;
  out.reserve(static_cast<std::size_t>(n[0] * n[1] * n[2]));
  for (long k = 0; k < n[2]; ++k)
    for (long j = 0; j < n[1]; ++j)
      for (long i = 0; i < n[0]; ++i)
        out.push_back({{planes[0][i], planes[1][j], planes[2][k]}, {planes[0][i + 1], planes[1][j + 1], planes[2][k + 1]}});
  return out;
}

}  // namespace exactvis::region
