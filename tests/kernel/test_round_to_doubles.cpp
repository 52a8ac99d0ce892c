// round_to_doubles against an independent rule (GMP's mpq_class): each coordinate becomes a double, less than one
// ulp from the exact value (strictly between its two neighbouring doubles); beyond the double range it stays exact.
#include "kernel/round_to_doubles.hpp"

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <cmath>
#include <random>
#include <sstream>

namespace exactvis {
namespace {

mpq_class as_mpq(const Exact& e) {
  std::ostringstream os;
  os << e;
  return mpq_class(os.str());
}

TEST(RoundToDoubles, EachCoordinateIsADoubleWithinOneUlp) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 2000; ++trial) {
    RationalPoint3 p;
    for (int k = 0; k < 3; ++k) {
      const long num = static_cast<long>(rng() % 2000001) - 1000000;
      const long den = static_cast<long>(rng() % 999983) + 1;
      p[k] = Exact(static_cast<double>(num)) / Exact(static_cast<double>(den));
    }
    const RationalPoint3 r = round_to_doubles(p);
    for (int k = 0; k < 3; ++k) {
      const double d = CGAL::to_double(r[k]);
      ASSERT_EQ(as_mpq(r[k]), mpq_class(d)) << "not a double";
      const mpq_class exact = as_mpq(p[k]);
      EXPECT_LT(mpq_class(std::nextafter(d, -INFINITY)), exact);
      EXPECT_GT(mpq_class(std::nextafter(d, INFINITY)), exact);
    }
  }
}

TEST(RoundToDoubles, DoublesStayAndHugeValuesStayExact) {
  const RationalPoint3 p{Exact(0.1), Exact(-3.0), Exact(1e-310)};
  const RationalPoint3 r = round_to_doubles(p);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(r[k], p[k]);
  Exact huge(1e308);
  huge = huge * huge;  // 1e616: beyond the double range
  const RationalPoint3 h = round_to_doubles(RationalPoint3{huge, Exact(1), Exact(2)});
  EXPECT_EQ(h[0], huge);
  EXPECT_EQ(h[1], Exact(1));
}

}  // namespace
}  // namespace exactvis
