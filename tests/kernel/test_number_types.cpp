// kernel/number_types: doubles are read as the exact rationals they denote; rational text round-trips.
#include "kernel/number_types.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace exactvis {
namespace {

TEST(NumberTypes, DoublesAreExactRationals) {
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int> e(-1070, 1020);
  std::uniform_real_distribution<double> m(-1, 1);
  for (int i = 0; i < 5000; ++i) {
    const double x = std::ldexp(m(rng), e(rng));
    const Exact q = to_exact(x);
    ASSERT_EQ(mpq_class(q.mpq()), mpq_class(x));  // gmpxx conversion is exact too (independent path)
    double back = 0;
    ASSERT_TRUE(exact_double(q, &back));
    ASSERT_EQ(back, x);
    ASSERT_EQ(parse_rational(to_rational_string(q)), q);
  }
  EXPECT_EQ(to_rational_string(to_exact(0.1)), "3602879701896397/36028797018963968");
  EXPECT_EQ(to_rational_string(to_exact(-3)), "-3");
  EXPECT_TRUE(exact_double(to_exact(std::numeric_limits<double>::denorm_min()), nullptr));
}

TEST(NumberTypes, NonDoubleRationalsAreDetected) {
  EXPECT_FALSE(exact_double(Exact(1) / Exact(3), nullptr));
  EXPECT_FALSE(exact_double(to_exact(1.0) + to_exact(std::ldexp(1.0, -60)), nullptr));
  EXPECT_FALSE(exact_double(to_exact(1e308) * to_exact(10.0), nullptr));
}

TEST(NumberTypes, TightIntervalEqualsCgalToInterval) {
  // The smallest enclosing pair of doubles, as CGAL::to_interval (MPFR) computes it: doubles at every
  // scale (point intervals), rationals that are no doubles, dyadics with 54+ significant bits, sums of a
  // double and a tiny offset, subnormal and overflowing magnitudes, both signs.
  std::mt19937_64 rng(12);
  std::uniform_int_distribution<int> e(-1074, 1023);
  std::uniform_real_distribution<double> m(-1, 1);
  std::uniform_int_distribution<long> n(-1000000007, 1000000007);
  std::vector<Exact> xs{Exact(0), Exact(1), Exact(-1), Exact(1, 3), Exact(-2, 3), Exact(1e308) * 4, -Exact(1e308) * 4,
                        Exact(std::ldexp(1.0, -1074)), Exact(std::ldexp(1.0, -1074)) / 3, Exact(std::ldexp(1.0, -1022)) / 3};
  for (int i = 0; i < 3000; ++i) {
    const double d = std::ldexp(m(rng), e(rng));
    xs.push_back(Exact(d));
    xs.push_back(Exact(d) + Exact(std::ldexp(d, -60)));  // 54+ significant bits: not a double
    xs.push_back(Exact(n(rng), std::max<long>(1, std::abs(n(rng)))));
    xs.push_back(Exact(d) / 7);
  }
  for (const Exact& x : xs) {
    const auto got = tight_interval(x), want = CGAL::to_interval(x);
    ASSERT_EQ(got.first, want.first) << x;
    ASSERT_EQ(got.second, want.second) << x;
  }
}

TEST(NumberTypes, ParseRational) {
  EXPECT_EQ(parse_rational("1/3") * 3, Exact(1));
  EXPECT_EQ(parse_rational("-2/4"), Exact(-1) / Exact(2));
  EXPECT_EQ(parse_rational("0.1"), to_exact(0.1));  // the double 0.1, not 1/10
  // integers beyond 2^53 are exact (not rounded through a double)
  EXPECT_EQ(parse_rational("123456789012345678901234567890"),
            Exact(ExactInt("123456789012345678901234567890")));
  EXPECT_EQ(parse_rational("-9007199254740993"), Exact(ExactInt("-9007199254740993")));
  EXPECT_EQ(parse_rational("+7"), Exact(7));
  EXPECT_THROW(parse_rational("-"), std::invalid_argument);
  EXPECT_EQ(parse_rational("1e-300"), to_exact(1e-300));
  EXPECT_THROW(parse_rational(""), std::invalid_argument);
  EXPECT_THROW(parse_rational("1/0"), std::invalid_argument);
  EXPECT_THROW(parse_rational("abc"), std::invalid_argument);
  EXPECT_THROW(parse_rational("1.5x"), std::invalid_argument);
  EXPECT_THROW(parse_rational("inf"), std::invalid_argument);
  EXPECT_THROW(parse_rational("nan"), std::invalid_argument);
  EXPECT_THROW(parse_rational("1e999"), std::invalid_argument);
}

TEST(NumberTypes, SignHelpers) {
  EXPECT_EQ(exact_sign(Exact(-5)), Sign::Negative);
  EXPECT_EQ(exact_sign(Exact(0)), Sign::Zero);
  EXPECT_EQ(-Sign::Positive, Sign::Negative);
  EXPECT_EQ(Sign::Negative * Sign::Negative, Sign::Positive);
}

}  // namespace
}  // namespace exactvis
