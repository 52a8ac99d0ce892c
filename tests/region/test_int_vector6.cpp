// The filtered signs of region/int_vector6 (dot_sign, side_sign, plucker_form_sign) against the sign of the
// same sum computed here term by term with GMP rationals (the oracle shares no code with the filter), on
// random vectors of 1 to 1100 bits and on near-cancelling ones (consecutive Fibonacci numbers, whose
// determinant is +-1, far below what doubles resolve), with the filter on and off. The counters show that
// the double layer decides the well-conditioned cases and defers the cancelling ones.
#include "region/int_vector6.hpp"

#include "kernel/filtered_predicate.hpp"
#include "kernel/predicate_counters.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

using namespace exactvis;
using namespace exactvis::region;

namespace {

// sign(sum x[i] * y[i]) in rationals, term by term.
int oracle_sign(const std::array<mpz_class, 6>& x, const std::array<mpz_class, 6>& y, int n) {
  mpq_class s = 0;
  for (int i = 0; i < n; ++i) s += mpq_class(x[i]) * mpq_class(y[i]);
  return sgn(s);
}

int oracle_dot(const IntVec6& a, const IntVec6& b) { return oracle_sign(a, b, 6); }
int oracle_side(const IntVec6& a, const IntVec6& b) {
  return oracle_sign({a[0], a[1], a[2], b[0], b[1], b[2]}, {b[3], b[4], b[5], a[3], a[4], a[5]}, 6);
}
int oracle_form(const IntVec6& a) { return oracle_sign({a[0], a[1], a[2]}, {a[3], a[4], a[5]}, 3); }

IntVec6 random_vec(std::mt19937_64& rng, int bits) {
  IntVec6 v;
  for (auto& c : v) {
    c = 0;
    for (int b = 0; b < bits; b += 32) c = (c << 32) + static_cast<unsigned long>(rng() & 0xffffffffu);
    c >>= (bits + 31) / 32 * 32 - bits;
    if (rng() % 2) c = -c;
    if (rng() % 5 == 0) c = 0;
  }
  return v;
}

std::uint64_t layer_count(const char* name, bool semi_static) {
  for (const auto& c : predicate_counters())
    if (c.name == name) return semi_static ? c.semi_static : c.exact;
  return 0;
}

struct Case {
  IntVec6 a, b;
};

std::vector<Case> cases() {
  std::mt19937_64 rng(20261202);
  std::vector<Case> out;
  for (int bits : {1, 8, 40, 60, 200, 1100})
    for (int i = 0; i < 300; ++i) out.push_back({random_vec(rng, bits), random_vec(rng, bits)});
  // Near cancellation: F(n+1) F(n-1) - F(n)^2 = (-1)^n with F(n) ~ 2^(0.69 n).
  std::vector<mpz_class> fib{0, 1};
  while (fib.size() < 400) fib.push_back(fib[fib.size() - 1] + fib[fib.size() - 2]);
  for (std::size_t n = 80; n + 1 < fib.size(); n += 7) {
    const mpz_class z = 0;
    // dot: F(n+1) F(n-1) + F(n) (-F(n)); side and the Plücker form see the same products.
    out.push_back({{fib[n + 1], fib[n], z, z, z, z}, {fib[n - 1], -fib[n], z, z, z, z}});
    out.push_back({{fib[n + 1], fib[n], z, fib[n - 1], -fib[n], z}, {z, z, z, z, z, z}});
    out.push_back({{fib[n + 1], fib[n], z, fib[n + 1], fib[n], z}, {fib[n - 1], -fib[n], z, fib[n - 1], -fib[n], z}});
    // Exactly zero with huge terms.
    out.push_back({{fib[n], fib[n], z, z, z, z}, {fib[n + 1], -fib[n + 1], z, z, z, z}});
  }
  return out;
}

void check_all(const std::vector<Case>& cs) {
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const auto& [a, b] = cs[i];
    const Approx6 aa = approximate(a), ba = approximate(b);
    ASSERT_EQ(dot_sign(a, aa, b, ba), oracle_dot(a, b)) << "case " << i;
    ASSERT_EQ(side_sign(a, aa, b, ba), oracle_side(a, b)) << "case " << i;
    ASSERT_EQ(plucker_form_sign(a, aa), oracle_form(a)) << "case " << i;
  }
}

}  // namespace

TEST(IntVector6, FilteredSignsEqualTheExactSigns) {
  const std::vector<Case> cs = cases();
  reset_predicate_counters();
  check_all(cs);
  // The double layer decides most random cases; the cancelling and the 1100-bit ones go to GMP.
  EXPECT_GT(layer_count("cone_dot", true), cs.size() / 2);
  EXPECT_GT(layer_count("cone_dot", false), 20u);
  EXPECT_GT(layer_count("cone_side", false), 20u);
  EXPECT_GT(layer_count("cone_plucker_form", false), 20u);
  set_filter_enabled(false);
  reset_predicate_counters();
  check_all(cs);
  EXPECT_EQ(layer_count("cone_dot", true), 0u);
  set_filter_enabled(true);
}

TEST(IntVector6, ApproximationTruncatesAndMarksHugeComponents) {
  IntVec6 v{mpz_class(3), mpz_class(-7), mpz_class(0), (mpz_class(1) << 60) + 1, mpz_class(1) << 1001, mpz_class(-5)};
  const Approx6 a = approximate(v);
  EXPECT_EQ(a[0], 3.0);
  EXPECT_EQ(a[1], -7.0);
  EXPECT_EQ(a[2], 0.0);
  EXPECT_EQ(a[3], 0x1p60);  // truncated toward zero
  EXPECT_TRUE(std::isinf(a[4]));
  EXPECT_EQ(a[5], -5.0);
}
