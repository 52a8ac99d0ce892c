// kernel/line_intersection_2d against GMP rationals computed here (c + t d with t as a rational quotient):
// random doubles at one scale, with the exponents of the ten coordinates spread over the whole range
// (subnormal to near overflow), zeros and small integers, nearly parallel lines; parallel lines rejected.
#include "kernel/line_intersection_2d.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace exactvis {
namespace {

mpq_class to_mpq(const Exact& x) { return mpq_class(x.mpq()); }

std::array<mpq_class, 2> oracle(const Double2& c, const Double2& d0, const Double2& d1, const Double2& a,
                                const Double2& b) {
  const mpq_class dx = mpq_class(d1[0]) - d0[0], dy = mpq_class(d1[1]) - d0[1];
  const mpq_class ex = mpq_class(b[0]) - a[0], ey = mpq_class(b[1]) - a[1];
  const mpq_class t = ((mpq_class(a[0]) - c[0]) * ey - (mpq_class(a[1]) - c[1]) * ex) / (dx * ey - dy * ex);
  return {c[0] + t * dx, c[1] + t * dy};
}

TEST(LineIntersection2D, MatchesRationalsAtAllScales) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> e(-1070, 1000), kind(0, 4), small(-5, 5);
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    const int k = kind(rng);
    const double scale = std::ldexp(1.0, e(rng));
    auto coord = [&]() -> double {
      switch (k) {
        case 0: return u(rng);
        case 1: return u(rng) * scale;                          // one scale
        case 2: return std::ldexp(u(rng), e(rng) / 2);          // exponents spread per coordinate
        case 3: return small(rng);                              // small integers, zeros
        default: return std::ldexp(double(small(rng)), -1074);  // subnormals
      }
    };
    Double2 p[5];
    for (auto& q : p)
      for (double& x : q) x = coord();
    if (i % 5 == 0) p[4] = {p[3][0] + (p[2][0] - p[1][0]), p[3][1] + (p[2][1] - p[1][1]) * (1 + 0x1p-50)};  // nearly parallel
    const mpq_class dx = mpq_class(p[2][0]) - p[1][0], dy = mpq_class(p[2][1]) - p[1][1];
    const mpq_class ex = mpq_class(p[4][0]) - p[3][0], ey = mpq_class(p[4][1]) - p[3][1];
    if (dx * ey - dy * ex == 0) {
      EXPECT_THROW(line_intersection_2d(p[0], p[1], p[2], p[3], p[4]), std::invalid_argument);
      continue;
    }
    const auto got = line_intersection_2d(p[0], p[1], p[2], p[3], p[4]);
    const auto want = oracle(p[0], p[1], p[2], p[3], p[4]);
    ASSERT_EQ(to_mpq(got[0]), want[0]) << "case " << i;
    ASSERT_EQ(to_mpq(got[1]), want[1]) << "case " << i;
    ++checked;
  }
  EXPECT_GT(checked, 15000);
}

TEST(LineIntersection2D, RejectsParallelLinesAndNonFiniteInput) {
  EXPECT_THROW(line_intersection_2d({0, 0}, {0, 0}, {1, 1}, {0, 1}, {2, 3}), std::invalid_argument);
  EXPECT_THROW(line_intersection_2d({0, 0}, {0, 0}, {1, 0}, {0, INFINITY}, {1, 1}), std::invalid_argument);
  const auto x = line_intersection_2d({0, 0}, {0, 0}, {1, 1}, {0, 1}, {1, 0});  // the diagonals of the unit square
  EXPECT_EQ(x[0], Exact(1, 2));
  EXPECT_EQ(x[1], Exact(1, 2));
}

}  // namespace
}  // namespace exactvis
