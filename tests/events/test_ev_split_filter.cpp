// The interval layers of the EV end-object split's segment and endpoint tests (events/ev_split_filter) against
// the exact tests computed here on mpq_class (no exactvis arithmetic): every decided answer must be the exact
// one, and enough cases must be decided that the layers are not vacuous. Inputs are random rationals with
// denominators 1..12 (most not exact in binary, so the enclosures are true intervals), near-degenerate cases
// included (t at t0 or t1 exactly, sigma = 0, sigma = |n|^2).
#include "events/ev_split_filter.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace exactvis {
namespace {

using Q = mpq_class;
using I = CGAL::Interval_nt<>;

// An enclosure of q: get_d truncates, so one ulp each way contains it.
std::pair<double, double> around(const Q& q) {
  const double d = q.get_d();
  return {std::nextafter(d, -HUGE_VAL), std::nextafter(d, HUGE_VAL)};
}
I enclose(const Q& q) {
  const auto e = around(q);
  return I(e.first, e.second);
}

// Far below the enclosures' width at these magnitudes (not a power of two: never exact in binary).
const Q tiny(1, 3 * (1L << 60));

struct Gen {
  std::mt19937_64 rng;
  explicit Gen(std::uint64_t seed) : rng(seed) {}
  Q rational(int range) {
    Q q(static_cast<long>(rng() % (2 * range * 12 + 1)) - range * 12, 1 + static_cast<long>(rng() % 12));
    q.canonicalize();
    return q;
  }
  int pick(int n) { return static_cast<int>(rng() % n); }
};

// The exact segment test of the split: kept unless sigma has one nonzero sign at both ends and both t are
// below t0 or both above t1.
bool exact_keeps_segment(const Q& ap, const Q& bp, const Q& aq, const Q& bq, const Q& t0, const Q& t1) {
  const Q sp = ap + bp, sq = aq + bq;
  const int gp = sgn(sp), gq = sgn(sq);
  if (gp == 0 || gp != gq) return true;
  const Q tp = bp / sp, tq = bq / sq;
  return !(std::max(tp, tq) < t0 || std::min(tp, tq) > t1);
}

// The exact endpoint test: kept iff (sigma >= nn or sigma < 0) and t0 < t < t1.
bool exact_keeps_endpoint(const Q& a, const Q& b, const Q& nn, const Q& t0, const Q& t1) {
  const Q sigma = a + b;
  if (!(sigma >= nn || sgn(sigma) < 0)) return false;
  const Q t = b / sigma;
  return t > t0 && t < t1;
}

TEST(EvSplitFilter, SegmentAnswersAreExact) {
  Gen g(20261203);
  int decided_no = 0, decided_yes = 0, unknown = 0;
  for (int it = 0; it < 20000; ++it) {
    Q t0 = g.rational(1), t1 = g.rational(1);
    if (t1 < t0) std::swap(t0, t1);
    if (t0 == t1) t1 += Q(1, 7);
    Q ap = g.rational(4), bp = g.rational(4), aq = g.rational(4), bq = g.rational(4);
    // set(a, b, t): keep sigma = a + b, move the point to parameter t.
    auto set = [](Q& a, Q& b, const Q& t) {
      const Q sigma = a + b;
      b = t * sigma;
      a = sigma - b;
    };
    switch (it % 6) {
      case 0: set(ap, bp, t0); break;  // t_p = t0 exactly (when sigma_p != 0)
      case 1: set(aq, bq, t1); break;  // t_q = t1 exactly
      case 2: bp = -ap; break;         // sigma_p = 0
      case 3: set(ap, bp, t0 - tiny), set(aq, bq, t0 - 2 * tiny); break;  // both just below t0
      case 4: set(ap, bp, t1 + tiny), set(aq, bq, t0 + tiny); break;      // one just inside
      default: break;
    }
    const FilterAnswer a = segment_t_range_meets({enclose(ap), enclose(bp), enclose(aq), enclose(bq)}, around(t0),
                                                 around(t1));
    const bool keeps = exact_keeps_segment(ap, bp, aq, bq, t0, t1);
    if (a == FilterAnswer::No) {
      ++decided_no;
      EXPECT_FALSE(keeps) << "case " << it;
    } else if (a == FilterAnswer::Yes) {
      ++decided_yes;
      EXPECT_TRUE(keeps) << "case " << it;
    } else {
      ++unknown;
    }
  }
  EXPECT_GT(decided_no, 400);
  EXPECT_GT(decided_yes, 3000);
  std::printf("segment answers: no %d, yes %d, unknown %d\n", decided_no, decided_yes, unknown);
  EXPECT_GT(unknown, 100);  // the exact cases (t at t0 or t1, sigma = 0) reach the exact test
}

TEST(EvSplitFilter, EndpointDropsAreExact) {
  Gen g(7);
  int dropped = 0, kept_by_exact = 0;
  for (int it = 0; it < 20000; ++it) {
    Q t0 = g.rational(1), t1 = g.rational(1);
    if (t1 < t0) std::swap(t0, t1);
    if (t0 == t1) t1 += Q(1, 5);
    const Q nn = abs(g.rational(3)) + Q(1, 3);
    Q a = g.rational(4), b = g.rational(4);
    auto set = [&](const Q& t) {  // keep sigma = a + b, move the point to parameter t
      const Q sigma = a + b;
      b = t * sigma;
      a = sigma - b;
    };
    switch (it % 6) {
      case 0: b = nn - a; break;  // sigma = |n|^2 exactly
      case 1: b = -a; break;      // sigma = 0
      case 2: set(t0); break;     // t = t0 exactly
      case 3: set(t1); break;     // t = t1 exactly
      case 4: set(it % 4 ? Q(t0 + tiny) : Q(t1 - tiny)); break;  // just inside (t0, t1)
      default: break;
    }
    const bool keeps = exact_keeps_endpoint(a, b, nn, t0, t1);
    kept_by_exact += keeps;
    if (endpoint_certainly_dropped(enclose(a), enclose(b), around(nn).first, around(t0), around(t1))) {
      ++dropped;
      EXPECT_FALSE(keeps) << "case " << it;
    }
  }
  std::printf("endpoints: dropped %d, kept by the exact test %d\n", dropped, kept_by_exact);
  EXPECT_GT(dropped, 5000);
  EXPECT_GT(kept_by_exact, 500);
}

}  // namespace
}  // namespace exactvis
