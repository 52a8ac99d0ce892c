#include "events/eee_line_miss_filter.hpp"

#include "kernel/filtered_predicate.hpp"
#include "kernel/predicate_counters.hpp"

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

namespace exactvis {
namespace {

using I = Interval;  // CGAL::Interval_nt<false>: only under the Protect_FPU_rounding of misses()
using IVec = std::array<I, 3>;

constexpr int kPieces = 8;  // pieces of the range: a quadratic's interval enclosure tightens with the width

IVec enclose(const Point3& p) { return {I(p.x), I(p.y), I(p.z)}; }

}  // namespace

EeeLineMissFilter::EeeLineMissFilter(const std::array<std::array<Exact, 3>, 3>& d,
                                     const std::array<std::array<Exact, 3>, 3>& m) {
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      const auto a = CGAL::to_interval(d[k][j]), b = CGAL::to_interval(m[k][j]);
      d_[k][j] = {a.first, a.second};
      m_[k][j] = {b.first, b.second};
    }
}

bool EeeLineMissFilter::misses(const Point3& a, const Point3& b, const Point3& c, double t_lo, double t_hi) const {
  static PredicateCounter counter("eee_line_misses");
  std::atomic<std::uint64_t>* counts = counter.thread_counts();
  detail::bump(counts[0]);
  auto not_proved = [&] {
    detail::bump(counts[1 + static_cast<int>(FilterLayer::Exact)]);
    return false;
  };
  if (!filter_enabled() || !(t_lo <= t_hi)) return not_proved();
  if (!proved(a, b, c, t_lo, t_hi)) return not_proved();
  detail::bump(counts[1 + static_cast<int>(FilterLayer::Interval)]);
  return true;
}

bool EeeLineMissFilter::proved(const Point3& a, const Point3& b, const Point3& c, double t_lo, double t_hi) const {
  // One rounding-mode switch for the whole test (the per-operation protection of Interval_nt<true> cost
  // more than the arithmetic).
  CGAL::Protect_FPU_rounding<true> guard;
  // q_k(t) = side(L(t), e_k) = d(t) . m_k + m(t) . d_k with e_k = (c_k+1 - c_k, c_k x c_k+1): coefficients.
  const IVec v[3] = {enclose(a), enclose(b), enclose(c)};
  std::array<std::array<I, 3>, 3> q;  // [edge][degree]
  for (int e = 0; e < 3; ++e) {
    const IVec& p = v[e];
    const IVec& r = v[(e + 1) % 3];
    const IVec ed{r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const IVec em{p[1] * r[2] - p[2] * r[1], p[2] * r[0] - p[0] * r[2], p[0] * r[1] - p[1] * r[0]};
    for (int j = 0; j < 3; ++j) {
      I s(0);
      for (int k = 0; k < 3; ++k) s += I(d_[k][j][0], d_[k][j][1]) * em[k] + I(m_[k][j][0], m_[k][j][1]) * ed[k];
      q[e][j] = s;
    }
  }
  // Every piece [u_i, u_i+1] of the range needs a certainly positive and a certainly negative q_k over it.
  const I lo(t_lo), width = I(t_hi) - lo;
  I prev = lo;
  for (int i = 1; i <= kPieces; ++i) {
    const I next = i == kPieces ? I(t_hi) : lo + width * I(double(i) / kPieces);  // i / 8 exact in binary
    const I t(prev.inf(), next.sup());
    bool pos = false, neg = false;
    for (int e = 0; e < 3; ++e) {
      const I val = q[e][0] + t * (q[e][1] + t * q[e][2]);
      pos = pos || val.inf() > 0;
      neg = neg || val.sup() < 0;
    }
    if (!(pos && neg)) return false;
    prev = next;
  }
  return true;
}

}  // namespace exactvis
