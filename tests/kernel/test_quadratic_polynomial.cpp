// Exact real roots of quadratics: every root substituted exactly in Q(sqrt D) gives 0, the number of distinct
// roots matches the sign of the discriminant (computed here with plain GMP rationals), roots are rational
// exactly when the discriminant is a rational square, and the arithmetic obeys its degree bound.
#include "kernel/quadratic_polynomial.hpp"
#include "kernel/rational_between.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>

namespace exactvis {
namespace {

RootNumber evaluate(const QuadraticPolynomial& p, const RootNumber& t) {
  return (RootNumber(p.c[2]) * t + RootNumber(p.c[1])) * t + RootNumber(p.c[0]);
}

mpq_class to_mpq(const Exact& q) {
  mpq_class r;
  mpq_set(r.get_mpq_t(), q.mpq());
  return r;
}

TEST(QuadraticPolynomial, RootsAreExactAndComplete) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> coef(-6, 6), den(1, 5);
  int irrational = 0, rational = 0;
  for (int n = 0; n < 3000; ++n) {
    QuadraticPolynomial p;
    for (int k = 0; k < 3; ++k) p.c[k] = Exact(coef(rng)) / Exact(den(rng));
    if (n % 7 == 0) p.c[2] = Exact(0);  // linear and constant cases
    const auto roots = real_roots(p);
    for (const auto& r : roots) {
      EXPECT_TRUE(CGAL::is_zero(evaluate(p, r.t)));
      Exact q;
      EXPECT_EQ(r.rational, root_number_rational(r.t, &q));
      if (r.rational) EXPECT_TRUE(q == r.q);
      (r.rational ? rational : irrational)++;
    }
    for (std::size_t i = 0; i < roots.size(); ++i)
      for (std::size_t j = i + 1; j < roots.size(); ++j) EXPECT_FALSE(roots[i].t == roots[j].t);
    // Expected count from the oracle's own discriminant.
    const mpq_class a = to_mpq(p.c[2]), b = to_mpq(p.c[1]), c = to_mpq(p.c[0]);
    std::size_t expected = 0;
    if (a != 0) {
      const mpq_class disc = b * b - 4 * a * c;
      expected = disc > 0 ? 2 : (disc == 0 ? 1 : 0);
      if (disc > 0) {
        const bool square = mpz_perfect_square_p(disc.get_num_mpz_t()) && mpz_perfect_square_p(disc.get_den_mpz_t());
        for (const auto& r : roots) EXPECT_EQ(r.rational, square);
      }
    } else if (b != 0) {
      expected = 1;
    }
    EXPECT_EQ(roots.size(), expected);
  }
  EXPECT_GT(irrational, 100);
  EXPECT_GT(rational, 100);
}

TEST(QuadraticPolynomial, Arithmetic) {
  const auto x = QuadraticPolynomial::linear(Exact(1), Exact(2));  // 1 + 2t
  const auto y = QuadraticPolynomial::linear(Exact(-3), Exact(1));  // -3 + t
  const auto p = x * y;                                             // -3 - 5t + 2t^2
  EXPECT_EQ(p.degree(), 2);
  EXPECT_TRUE(p.c[0] == Exact(-3) && p.c[1] == Exact(-5) && p.c[2] == Exact(2));
  EXPECT_TRUE(p(Exact(3)) == Exact(0));
  EXPECT_TRUE((x - x).degree() == -1);
  EXPECT_TRUE(scaled(p, Exact(1, 2))(Exact(1)) == Exact(-3));
  EXPECT_THROW(p * x, std::logic_error);
  EXPECT_TRUE(real_roots(QuadraticPolynomial(0)).empty());
  EXPECT_TRUE(real_roots(QuadraticPolynomial(4)).empty());
}

}  // namespace
}  // namespace exactvis
