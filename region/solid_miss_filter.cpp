#include "region/solid_miss_filter.hpp"

#include "kernel/number_types.hpp"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cstdint>

namespace exactvis::region {

SolidMissFilter::SolidMissFilter(const std::vector<ConvexSolid>& solids, const std::vector<std::size_t>& listed,
                                 const RationalBox3& cell)
    : facets_(solids.size()) {
  for (const std::size_t k : listed)
    for (const Plane3& f : solids[k].facets) {
      const auto [nxl, nxh] = enclosing_interval(f.normal.x);
      const auto [nyl, nyh] = enclosing_interval(f.normal.y);
      const auto [nzl, nzh] = enclosing_interval(f.normal.z);
      const auto [dl, dh] = enclosing_interval(f.offset);
      facets_[k].push_back({nxl, nxh, nyl, nyh, nzl, nzh, dl, dh});
    }
  for (int c = 0; c < 8; ++c) {
    const Exact& x = (c & 1) ? cell.hi.x : cell.lo.x;
    const Exact& y = (c & 2) ? cell.hi.y : cell.lo.y;
    const Exact& z = (c & 4) ? cell.hi.z : cell.lo.z;
    const auto [xl, xh] = enclosing_interval(x);
    const auto [yl, yh] = enclosing_interval(y);
    const auto [zl, zh] = enclosing_interval(z);
    cell_corners_[c] = {xl, xh, yl, yh, zl, zh};
  }
}

bool SolidMissFilter::proves_miss(std::size_t k, const Box3& box) const {
  using I = CGAL::Interval_nt<false>;
  CGAL::Protect_FPU_rounding<true> protect;  // Interval_nt<false> needs rounding towards +infinity
  if (k >= facets_.size() || facets_[k].empty()) return false;
  const std::vector<Facet>& facets = facets_[k];
  // Facet values, certified lower bounds: value > 0 means strictly outside that facet's half-space.
  std::vector<I> nx, ny, nz, d;
  for (const Facet& f : facets) {
    nx.push_back(I(f.nx_lo, f.nx_hi)), ny.push_back(I(f.ny_lo, f.ny_hi)), nz.push_back(I(f.nz_lo, f.nz_hi));
    d.push_back(I(f.d_lo, f.d_hi));
  }
  const std::size_t n = facets.size();
  // Facet values at the 8 cell corners and the 8 box corners (the box's corners are exact doubles).
  std::vector<I> vc(8 * n), vb(8 * n);
  for (int c = 0; c < 8; ++c) {
    const auto& p = cell_corners_[c];
    const I x(p[0], p[1]), y(p[2], p[3]), z(p[4], p[5]);
    const I bx((c & 1) ? box.hi.x : box.lo.x), by((c & 2) ? box.hi.y : box.lo.y), bz((c & 4) ? box.hi.z : box.lo.z);
    for (std::size_t f = 0; f < n; ++f) {
      vc[c * n + f] = nx[f] * x + ny[f] * y + nz[f] * z - d[f];
      vb[c * n + f] = nx[f] * bx + ny[f] * by + nz[f] * bz - d[f];
    }
  }
  // For each segment a -> b, the clipping of segment_meets_solid with the facets whose signs the intervals
  // decide (dropping a facet only enlarges the set of parameters left, so an empty set is still a proof):
  // v(t) = va + t (vb - va) <= 0 for t >= va / (va - vb) when va > 0 > vb, t <= va / (va - vb) when
  // va < 0 < vb; both ends outside one facet: missed.
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      double lower = 0, upper = 1;  // certified: the parameters left lie in [>= lower, <= upper]
      bool missed = false;
      for (std::size_t f = 0; f < n && !missed; ++f) {
        const I& va = vc[a * n + f];
        const I& wb = vb[b * n + f];
        if (va.inf() > 0 && wb.inf() > 0) missed = true;
        else if (va.inf() > 0 && wb.sup() < 0) lower = std::max(lower, (va / (va - wb)).inf());
        else if (va.sup() < 0 && wb.inf() > 0) upper = std::min(upper, (va / (va - wb)).sup());
        if (lower > upper) missed = true;
      }
      if (missed) return true;
    }
  return false;
}

}  // namespace exactvis::region
