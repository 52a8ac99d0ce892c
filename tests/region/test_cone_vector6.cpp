// The layered 6-vectors of region/cone_vector6 (filter -> fixed int64/__int128 -> gmp) against a GMP-only
// oracle written here (mpz/mpq sums, mpz_gcd, rational Plücker coordinates; no code of the library): the signs
// dot / side / q, the double-description combination eliminate() and the side functionals of lines through
// double points, on random vectors of 1 to 200 bits, on the int64 boundary (2^63 - 1, 2^63), on near-cancelling
// sums (Fibonacci pairs), and on adversarial combinations whose products overflow __int128 before the gcd
// reduction and whose result does or does not fit int64 after it. The layer counts show which layer decided.
#include "region/cone_vector6.hpp"

#include "kernel/filtered_predicate.hpp"
#include "kernel/plucker_line.hpp"
#include "kernel/predicates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

using Z6 = std::array<mpz_class, 6>;

// ---- oracle (GMP only) ----
int oracle_sum_sign(const Z6& x, const Z6& y, int n) {
  mpz_class s = 0;
  for (int i = 0; i < n; ++i) s += x[static_cast<std::size_t>(i)] * y[static_cast<std::size_t>(i)];
  return sgn(s);
}
int oracle_dot(const Z6& a, const Z6& b) { return oracle_sum_sign(a, b, 6); }
int oracle_side(const Z6& a, const Z6& b) {
  return oracle_sum_sign({a[0], a[1], a[2], b[0], b[1], b[2]}, {b[3], b[4], b[5], a[3], a[4], a[5]}, 6);
}
int oracle_form(const Z6& a) { return oracle_sum_sign({a[0], a[1], a[2], 0, 0, 0}, {a[3], a[4], a[5], 0, 0, 0}, 3); }

Z6 oracle_primitive(Z6 v) {
  mpz_class g = 0;
  for (const auto& c : v) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
  if (g != 0)
    for (auto& c : v) c /= g;
  return v;
}

Z6 oracle_eliminate(const Z6& w, const Z6& p, const Z6& q) {
  mpz_class wp = 0, wq = 0;
  for (std::size_t k = 0; k < 6; ++k) {
    wp += w[k] * p[k];
    wq += w[k] * q[k];
  }
  Z6 v;
  for (std::size_t k = 0; k < 6; ++k) v[k] = wp * q[k] - wq * p[k];
  return oracle_primitive(v);
}

// (m, d) of the line through a then b from exact rationals, scaled to primitive integers (positive factor).
Z6 oracle_side_functional(const Point3& a, const Point3& b) {
  const mpq_class ax(a.x), ay(a.y), az(a.z), bx(b.x), by(b.y), bz(b.z);
  const std::array<mpq_class, 6> f{ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx, bx - ax, by - ay, bz - az};
  mpz_class l = 1;
  for (const auto& c : f) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  Z6 v;
  for (std::size_t k = 0; k < 6; ++k) {
    const mpq_class s = f[k] * l;
    v[k] = s.get_num();
  }
  return oracle_primitive(v);
}

// ---- inputs ----
mpz_class random_int(std::mt19937_64& rng, int bits) {
  mpz_class c = 0;
  for (int b = 0; b < bits; b += 32) c = (c << 32) + static_cast<unsigned long>(rng() & 0xffffffffu);
  c >>= (bits + 31) / 32 * 32 - bits;
  if (rng() % 2) c = -c;
  if (rng() % 6 == 0) c = 0;
  return c;
}
Z6 random_vec(std::mt19937_64& rng, int bits) {
  Z6 v;
  for (auto& c : v) c = random_int(rng, bits);
  return v;
}

ConeLayerCounts counts() { return cone_layer_counts(); }

class FilterSwitch {
 public:
  explicit FilterSwitch(bool on) { set_filter_enabled(on); }
  ~FilterSwitch() { set_filter_enabled(true); }
};

}  // namespace

TEST(ConeVector6, StorageLayerAndRoundTrip) {
  const mpz_class max64(std::numeric_limits<long>::max());
  for (const mpz_class& c : {mpz_class(0), mpz_class(1), max64, mpz_class(-max64), mpz_class(max64 + 1),
                             mpz_class(-max64 - 1), mpz_class(max64 * 1000)}) {
    const Z6 v{c, 0, 1, -1, c, 7};
    const ConeVector6 x(v);
    EXPECT_EQ(x.is_fixed(), abs(c) <= max64) << c.get_str();
    EXPECT_EQ(x.to_gmp(), v);
    Z6 neg = v;
    for (auto& e : neg) e = -e;
    EXPECT_EQ(x.negated().to_gmp(), neg);
    EXPECT_EQ(x.negated().is_fixed(), x.is_fixed());
    EXPECT_EQ(x.negated().negated(), x);
    for (std::size_t k = 0; k < 6; ++k) {
      const double exact = v[k].get_d();
      EXPECT_LE(std::fabs(x.approx()[k] - exact), std::ldexp(std::fabs(exact), -52));
    }
  }
  EXPECT_TRUE(ConeVector6().is_zero());
  EXPECT_FALSE(ConeVector6(Fixed6{0, 0, 0, 0, 0, 1}).is_zero());
}

TEST(ConeVector6, SignsAgreeWithGmpOracleInEveryLayer) {
  std::mt19937_64 rng(20261202);
  for (bool filter : {true, false}) {
    FilterSwitch fs(filter);
    for (int bits : {1, 8, 31, 40, 62, 63, 64, 100, 200})
      for (int i = 0; i < 400; ++i) {
        // Mixed widths: one operand may be fixed and the other gmp.
        const Z6 a = random_vec(rng, bits), b = random_vec(rng, (i % 3 == 0) ? 20 : bits);
        const ConeVector6 ca(a), cb(b);
        ASSERT_EQ(dot_sign(ca, cb), oracle_dot(a, b)) << bits;
        ASSERT_EQ(side_sign(ca, cb), oracle_side(a, b)) << bits;
        ASSERT_EQ(plucker_form_sign(ca), oracle_form(a)) << bits;
        mpz_class exact_dot = 0;
        for (std::size_t k = 0; k < 6; ++k) exact_dot += a[k] * b[k];
        ASSERT_EQ(dot(ca, b), exact_dot);
      }
  }
}

TEST(ConeVector6, CancellingSumsGoPastTheFilterAndStayExact) {
  // F(n+1)^2 - F(n) F(n+2) = +-1: far below what doubles resolve for n ~ 80 (F ~ 2^55).
  std::vector<mpz_class> fib{0, 1};
  while (fib.size() < 95) fib.push_back(fib[fib.size() - 1] + fib[fib.size() - 2]);
  const ConeLayerCounts before = counts();
  int cases = 0;
  for (std::size_t n = 40; n + 2 < fib.size(); ++n) {
    const Z6 a{fib[n + 1], fib[n], 0, 0, 0, 0}, b{fib[n + 1], -fib[n + 2], 0, 0, 0, 0};
    const ConeVector6 ca(a), cb(b);
    EXPECT_EQ(dot_sign(ca, cb), oracle_dot(a, b)) << n;
    EXPECT_NE(oracle_dot(a, b), 0);
    const Z6 c{fib[n + 1], fib[n], 0, fib[n + 1], -fib[n + 2], 0};  // q = F(n+1)^2 - F(n) F(n+2)
    EXPECT_EQ(plucker_form_sign(ConeVector6(c)), oracle_form(c)) << n;
    cases += 2;
  }
  const ConeLayerCounts after = counts();
  const auto fixed = after.signs[1] - before.signs[1], gmp = after.signs[2] - before.signs[2];
  EXPECT_GT(fixed, 0u);   // int64 Fibonacci numbers: the fixed layer decides what the filter cannot
  EXPECT_GT(gmp, 0u);     // beyond 2^63 (n >= 92): gmp
  EXPECT_LE(fixed + gmp, static_cast<std::uint64_t>(cases));
}

TEST(ConeVector6, FixedLayerDecidesSmallInputsWithTheFilterOff) {
  FilterSwitch fs(false);
  std::mt19937_64 rng(5);
  const ConeLayerCounts before = counts();
  for (int i = 0; i < 1000; ++i) {
    const ConeVector6 a(random_vec(rng, 60)), b(random_vec(rng, 60));
    dot_sign(a, b);
    side_sign(a, b);
  }
  const ConeLayerCounts after = counts();
  EXPECT_EQ(after.signs[1] - before.signs[1], 2000u);  // |products| < 2^120: never an overflow
  EXPECT_EQ(after.signs[2] - before.signs[2], 0u);
}

TEST(ConeVector6, EliminateAgreesWithGmpOracle) {
  std::mt19937_64 rng(99);
  std::uint64_t fixed_results = 0;
  for (int bits : {2, 10, 30, 45, 62, 63, 80, 150})
    for (int i = 0; i < 300; ++i) {
      const Z6 w = random_vec(rng, bits), p = random_vec(rng, bits), q = random_vec(rng, bits);
      const ConeVector6 v = eliminate(ConeVector6(w), ConeVector6(p), ConeVector6(q));
      const Z6 expect = oracle_eliminate(w, p, q);
      ASSERT_EQ(v.to_gmp(), expect) << "bits " << bits << " case " << i;
      // The layer follows the value: fixed iff every component fits.
      bool fits = true;
      for (const auto& c : expect) fits = fits && abs(c) <= mpz_class(std::numeric_limits<long>::max());
      ASSERT_EQ(v.is_fixed(), fits);
      fixed_results += v.is_fixed() ? 1 : 0;
    }
  EXPECT_GE(fixed_results, 600u);  // the 2- and 10-bit inputs stay fixed; beyond 30 bits the results do not fit
}

TEST(ConeVector6, EliminateAcrossTheOverflowBoundaries) {
  std::mt19937_64 rng(4242);
  const ConeLayerCounts before = counts();
  int reduced_to_fixed = 0, beyond_fixed = 0;
  for (int i = 0; i < 400; ++i) {
    // w . p = w . q = g ~ 2^124 (w orthogonal to p - q): (w.p) q alone overflows __int128, but the
    // coefficients reduce to (1, 1) and v = q - p fits int64.
    Z6 p, q, w;
    for (std::size_t k = 0; k < 6; ++k) {
      p[k] = abs(random_int(rng, 62));
      q[k] = abs(random_int(rng, 62));
    }
    const mpz_class d0 = p[0] - q[0], d1 = p[1] - q[1];
    w = {d1, -d0, 0, 0, 0, 0};
    const ConeVector6 v = eliminate(ConeVector6(w), ConeVector6(p), ConeVector6(q));
    const Z6 expect = oracle_eliminate(w, p, q);
    ASSERT_EQ(v.to_gmp(), expect) << i;
    if (v.is_fixed()) ++reduced_to_fixed;
    // Coprime 62-bit inputs: the result has ~186-bit components, beyond int64 after any gcd: gmp, exact.
    const Z6 w2 = random_vec(rng, 62), p2 = random_vec(rng, 62), q2 = random_vec(rng, 62);
    const ConeVector6 v2 = eliminate(ConeVector6(w2), ConeVector6(p2), ConeVector6(q2));
    ASSERT_EQ(v2.to_gmp(), oracle_eliminate(w2, p2, q2)) << i;
    if (!v2.is_fixed()) ++beyond_fixed;
    // Partial sums beyond 2^127 that cancel (three times +(2^63 - 1)^2, then three times minus, + m i): the
    // fixed layer declines (checked additions), gmp answers.
    const mpz_class m(std::numeric_limits<long>::max());
    const Z6 big{m, m, m, m, m, m}, unit{m, m, m, -m, -m, -m + i};
    EXPECT_EQ(dot_sign(ConeVector6(big), ConeVector6(unit)), oracle_dot(big, unit));
    ASSERT_EQ(eliminate(ConeVector6(big), ConeVector6(unit), ConeVector6(Z6{1, 0, 0, 0, 0, 0})).to_gmp(),
              oracle_eliminate(big, unit, Z6{1, 0, 0, 0, 0, 0}));
  }
  const ConeLayerCounts after = counts();
  EXPECT_GT(reduced_to_fixed, 350);
  EXPECT_GT(beyond_fixed, 350);
  EXPECT_GT(after.constructions[1] - before.constructions[1], 350u);
  EXPECT_GT(after.constructions[2] - before.constructions[2], 350u);
}

TEST(ConeVector6, SideFunctionalOfDoublesAgreesWithRationalPlucker) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> grid(-4096, 4096);
  std::uniform_real_distribution<double> unit(-1, 1);
  int computed = 0, declined = 0;
  for (int i = 0; i < 3000; ++i) {
    Point3 a, b;
    switch (i % 4) {
      case 0:  // town-like: multiples of 1/64
        a = {grid(rng) / 64.0, grid(rng) / 64.0, grid(rng) / 64.0};
        b = {grid(rng) / 64.0, grid(rng) / 64.0, grid(rng) / 64.0};
        break;
      case 1:  // integers, and a shared coordinate (axis-aligned edges)
        a = {double(grid(rng)), double(grid(rng)), double(grid(rng))};
        b = {a.x, double(grid(rng)), a.z};
        break;
      case 2:  // arbitrary doubles: mostly beyond the fixed layer
        a = {unit(rng), unit(rng), unit(rng)};
        b = {unit(rng), unit(rng), unit(rng)};
        break;
      default:  // mixed exponents: 2^30 next to 2^-30
        a = {std::ldexp(grid(rng), 30), std::ldexp(grid(rng), -30), 1.5};
        b = {std::ldexp(grid(rng), -20), 3.0, std::ldexp(grid(rng), 10)};
    }
    ConeVector6 v;
    if (side_functional_of_doubles(a, b, v)) {
      ++computed;
      ASSERT_EQ(v.to_gmp(), oracle_side_functional(a, b)) << i;
      ASSERT_TRUE(v.is_fixed());
      // The library's rational path gives the same vector.
      ASSERT_EQ(v.to_gmp(), side_functional(line_through(to_rational(a), to_rational(b))));
    } else {
      ++declined;
      ASSERT_TRUE(i % 4 >= 2 || (a.x == b.x && a.y == b.y && a.z == b.z)) << "town-like input declined, case " << i;
    }
  }
  EXPECT_EQ(computed, 1500);  // every town-like and integer case (half the inputs); none of the others here
  ConeVector6 v;
  EXPECT_FALSE(side_functional_of_doubles({1, 2, 3}, {1, 2, 3}, v));
  EXPECT_FALSE(side_functional_of_doubles({NAN, 2, 3}, {1, 2, 3}, v));
}
