// BoundedDouble (kernel/bounded_double): on random expression trees of sums, differences and products over
// doubles of every magnitude (subnormal to near overflow) and enclosures of rationals, the invariant
// |v| <= m and |v - x| <= ((1 - u)^-k - 1) m holds against the exact value x (GMP rationals, computed here),
// and a certified sign is always the exact sign. Cancelling trees put the value at the rounding level, and
// products in the subnormal range (where the relative error model fails) must never certify a wrong sign.
#include "kernel/bounded_double.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace exactvis {
namespace {

struct Node {
  BoundedDouble b;
  mpq_class x;  // exact value of the same expression
};

Node operator+(const Node& p, const Node& q) { return {p.b + q.b, p.x + q.x}; }
Node operator-(const Node& p, const Node& q) { return {p.b - q.b, p.x - q.x}; }
Node operator*(const Node& p, const Node& q) { return {p.b * q.b, p.x * q.x}; }

int exact_sign(const mpq_class& x) { return sgn(x); }

// (1 - u)^-k - 1, exactly (memoized).
const mpq_class& g(int k) {
  static std::vector<mpq_class> table;
  static const mpq_class one_minus_u = mpq_class(1) - mpq_class(1, mpz_class(1) << 53);
  while (static_cast<int>(table.size()) <= k)
    table.push_back(table.empty() ? mpq_class(0) : (table.back() + 1) / one_minus_u - 1);
  return table[k];
}

// The invariant of every BoundedDouble against its exact value; false if it is violated.
::testing::AssertionResult invariant_holds(const Node& n) {
  const double m = n.b.magnitude();
  if (!std::isfinite(m)) return ::testing::AssertionSuccess();  // certifies nothing
  const mpq_class v(n.b.value()), mm(m);
  if (abs(v) > mm) return ::testing::AssertionFailure() << "|v| > m: v=" << n.b.value() << " m=" << m;
  if (abs(v - n.x) > g(n.b.index()) * mm)
    return ::testing::AssertionFailure() << "error above g(k) m: v=" << n.b.value() << " m=" << m
                                         << " k=" << n.b.index() << " x=" << n.x.get_d();
  return ::testing::AssertionSuccess();
}

struct Gen {
  std::mt19937_64 rng;
  int scale_lo = -1074, scale_hi = 1000;
  explicit Gen(std::uint64_t s) : rng(s) {}
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  double uniform() { return std::uniform_real_distribution<double>(-1, 1)(rng); }

  Node leaf() {
    switch (integer(0, 4)) {
      case 0: {  // an exact double at a random scale
        const double x = std::ldexp(uniform(), integer(scale_lo, scale_hi));
        return {BoundedDouble(x), mpq_class(x)};
      }
      case 1: {  // a small integer (exact sums and products)
        const double x = integer(-9, 9);
        return {BoundedDouble(x), mpq_class(x)};
      }
      case 2: {  // an enclosure of a rational that is no double
        const mpq_class q(integer(-1000000, 1000000), integer(1, 999) * 2 + 1);
        const Exact e(q.get_mpq_t());
        return {BoundedDouble(enclosing_interval(e)), q};
      }
      case 3: {  // an Interval enclosure of a scaled rational
        mpq_class q(integer(1, 1 << 30), 3);
        if (integer(0, 1)) q = -q;
        const int e = integer(-900, 900);
        if (e >= 0) q *= mpq_class(mpz_class(1) << e); else q /= mpq_class(mpz_class(1) << -e);
        return {BoundedDouble(CGAL::to_interval(Exact(q.get_mpq_t()))), q};
      }
      default: {  // a subnormal
        const double x = std::ldexp(double(integer(-5000, 5000)), -1074);
        return {BoundedDouble(x), mpq_class(x)};
      }
    }
  }
  Node tree(int depth) {
    if (depth == 0 || integer(0, 3) == 0) return leaf();
    const Node a = tree(depth - 1), b = tree(depth - 1);
    switch (integer(0, 2)) {
      case 0: return a + b;
      case 1: return a - b;
      default: return a * b;
    }
  }
};

TEST(BoundedDouble, InvariantAndSignsOnRandomTrees) {
  Gen gen(7);
  int decided = 0, total = 0;
  for (int scales = 0; scales < 3; ++scales) {
    // whole range; moderate magnitudes (most decisions); tiny and huge only
    gen.scale_lo = scales == 1 ? -20 : (scales == 2 ? 900 : -1074);
    gen.scale_hi = scales == 1 ? 20 : (scales == 2 ? 1010 : 1000);
    for (int i = 0; i < 20000; ++i) {
      const Node n = gen.tree(gen.integer(1, 4));
      ASSERT_TRUE(invariant_holds(n)) << "tree " << i;
      ++total;
      if (const auto s = n.b.certified_sign()) {
        ++decided;
        ASSERT_EQ(to_int(*s), exact_sign(n.x)) << "tree " << i;
      }
    }
  }
  EXPECT_GT(decided, total / 2);  // the layer is not vacuous
}

TEST(BoundedDouble, CancellingTreesAtTheRoundingLevel) {
  // Two evaluation orders of one exact value: their difference is a few rounding errors, or exactly 0.
  Gen gen(8);
  gen.scale_lo = -300, gen.scale_hi = 300;
  int decided = 0;
  for (int i = 0; i < 20000; ++i) {
    const Node a = gen.tree(2), b = gen.tree(2), c = gen.tree(2);
    Node d;
    switch (i % 4) {
      case 0: d = (a * b) * c - a * (b * c); break;
      case 1: d = (a + b) + c - (a + (b + c)); break;
      case 2: d = a * (b + c) - (a * b + a * c); break;
      default: d = (a - b) * (a + b) - (a * a - b * b); break;
    }
    ASSERT_TRUE(invariant_holds(d)) << "case " << i;
    if (const auto s = d.b.certified_sign()) {
      ++decided;
      ASSERT_EQ(to_int(*s), exact_sign(d.x)) << "case " << i;
    }
  }
  EXPECT_GT(decided, 20);
}

TEST(BoundedDouble, SubnormalProductsNeverCertifyAWrongSign) {
  // Eight products of exact value 0.6 * 2^-1074 each round up to 2^-1074; minus one of exactly 5 * 2^-1074.
  // Computed: 8 - 5 = 3 (x 2^-1074) > 0; exact: 4.8 - 5 < 0. The relative model does not hold there.
  const double a = 0.6 * std::ldexp(1.0, -537), b = std::ldexp(1.0, -537);
  Node sum{BoundedDouble(0.0), 0};
  for (int i = 0; i < 8; ++i) sum = sum + Node{a, mpq_class(a)} * Node{b, mpq_class(b)};
  const double e = 5 * std::ldexp(1.0, -537);
  const Node d = sum - Node{e, mpq_class(e)} * Node{b, mpq_class(b)};
  ASSERT_LT(exact_sign(d.x), 0);
  ASSERT_GT(d.b.value(), 0);  // the floating-point value has the wrong sign
  const auto s = d.b.certified_sign();
  EXPECT_TRUE(!s || *s == Sign::Negative);
  EXPECT_TRUE(invariant_holds(d));
}

TEST(BoundedDouble, ExactZerosAndEnclosures) {
  // m == 0: an exact zero, whatever the operations.
  const BoundedDouble z = (BoundedDouble(0.0) - 0.0) * 1e300 + BoundedDouble(5.0) * 0.0;
  EXPECT_EQ(z.certified_sign(), Sign::Zero);
  // Exact operands that cancel exactly give an exact zero; a zero of rounded values is not certified
  // (0.1 + 0.2 rounds to the double next to 0.3, but the exact sum is not that double).
  EXPECT_EQ(((BoundedDouble(3.0) - 3.0) * 1e300 + (BoundedDouble(-2.5) + 2.5)).certified_sign(), Sign::Zero);
  EXPECT_EQ((BoundedDouble(0.1) + 0.2).value(), 0.30000000000000004);
  EXPECT_FALSE(((BoundedDouble(0.1) + 0.2) - 0.30000000000000004).certified_sign().has_value());
  // A point interval is an exact double; a wide or zero-crossing enclosure certifies only what its width
  // allows (its magnitude covers 2^50 times the width).
  EXPECT_EQ((BoundedDouble(Interval(2)) - 1.0).certified_sign(), Sign::Positive);
  EXPECT_FALSE((BoundedDouble(Interval(1, 2)) - 0.5).certified_sign().has_value());
  EXPECT_EQ((BoundedDouble(Interval(1, 2)) - 1e16).certified_sign(), Sign::Negative);
  EXPECT_FALSE(BoundedDouble(Interval(-1e-300, 1e-300)).certified_sign().has_value());
  EXPECT_EQ((BoundedDouble(Interval(-1e-300, 1e-300)) + 1.0).certified_sign(), Sign::Positive);
  // A narrow enclosure of 1/3 certifies 1/3 - 0.3 > 0, but not the sign of 1/3 - fl(1/3) (below its width).
  const Exact third(1, 3);
  EXPECT_EQ((BoundedDouble(enclosing_interval(third)) - 0.3).certified_sign(), Sign::Positive);
  EXPECT_FALSE((BoundedDouble(enclosing_interval(third)) - 1.0 / 3).certified_sign().has_value());
  // Overflow certifies nothing.
  EXPECT_FALSE((BoundedDouble(1e300) * 1e300 - 1.0).certified_sign().has_value());
}

}  // namespace
}  // namespace exactvis
