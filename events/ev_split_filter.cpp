#include "events/ev_split_filter.hpp"

#include <CGAL/FPU.h>

#include <algorithm>

namespace exactvis {

using I = CGAL::Interval_nt<>;
// Unprotected intervals under one rounding-mode switch per call (same enclosures, fewer switches).
using IU = CGAL::Interval_nt<false>;
namespace {
IU u(const I& x) { return IU(x.inf(), x.sup()); }
}  // namespace

FilterAnswer segment_t_range_meets(const std::array<I, 4>& eb, const std::pair<double, double>& it0,
                                   const std::pair<double, double>& it1) {
  CGAL::Protect_FPU_rounding<true> guard;
  const IU sp = u(eb[0]) + u(eb[1]), sq = u(eb[2]) + u(eb[3]);
  const int gp = sp.inf() > 0 ? 1 : sp.sup() < 0 ? -1 : 0, gq = sq.inf() > 0 ? 1 : sq.sup() < 0 ? -1 : 0;
  if (gp == 0 || gq == 0) return FilterAnswer::Unknown;
  if (gp != gq) return FilterAnswer::Yes;  // the exact test keeps segments whose sigma changes sign
  const IU tp = u(eb[1]) / sp, tq = u(eb[3]) / sq;
  if (std::max(tp.sup(), tq.sup()) < it0.first || std::min(tp.inf(), tq.inf()) > it1.second) return FilterAnswer::No;
  const bool max_ge_t0 = tp.inf() >= it0.second || tq.inf() >= it0.second;
  const bool min_le_t1 = tp.sup() <= it1.first || tq.sup() <= it1.first;
  return max_ge_t0 && min_le_t1 ? FilterAnswer::Yes : FilterAnswer::Unknown;
}

bool endpoint_certainly_dropped(const I& ia, const I& ib, double nn_lo, const std::pair<double, double>& it0,
                                const std::pair<double, double>& it1) {
  CGAL::Protect_FPU_rounding<true> guard;
  const IU sigma = u(ia) + u(ib);
  if (sigma.inf() >= 0 && sigma.sup() < nn_lo) return true;
  if (!(sigma.inf() > 0 || sigma.sup() < 0)) return false;
  const IU t = u(ib) / sigma;
  return t.sup() <= it0.first || t.inf() >= it1.second;
}

}  // namespace exactvis
