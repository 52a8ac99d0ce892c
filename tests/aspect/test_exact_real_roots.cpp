// aspect/exact_real_roots against polynomials with known roots: (t - 1)(t - 2)(t^2 - 2)(t + 1/3) has the roots
// -sqrt 2, -1/3, 1, sqrt 2, 2 (two irrational, three rational), each isolated once and in order; the sign of
// t^2 - 2 is 0 exactly at +-sqrt 2 (gcd test), the sign of t - 1.41421356 at sqrt 2 is +1 and of t - 1.41421357
// is -1 (refinement past 10^-8); multiple roots vanish from the square-free part.
#include "aspect/exact_real_roots.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace exactvis;

ExactPolynomial lin(const Exact& r) { return poly_from({-r, Exact(1)}); }

TEST(ExactRealRoots, IsolatesRationalAndIrrationalRootsInOrder) {
  const ExactPolynomial two = poly_from({Exact(-2), Exact(0), Exact(1)});
  const ExactPolynomial p = lin(Exact(1)) * lin(Exact(2)) * two * lin(Exact(-1, 3));
  EXPECT_EQ(p.degree(), 5);
  auto roots = isolate_roots(p, Exact(-10), Exact(10));
  ASSERT_EQ(roots.size(), 5u);
  const double want[5] = {-std::sqrt(2.0), -1.0 / 3, 1, std::sqrt(2.0), 2};
  for (int i = 0; i < 5; ++i) {
    for (int k = 0; k < 60; ++k) refine_root(p, roots[i]);
    EXPECT_NEAR(CGAL::to_double(roots[i].lo), want[i], 1e-12);
    EXPECT_FALSE(roots[i].hi < roots[i].lo);
    if (i > 0) {
      EXPECT_TRUE(roots[i - 1].hi < roots[i].lo || roots[i - 1].hi == roots[i].lo);
    }
  }
  EXPECT_EQ(poly_root_count(p, Exact(0), Exact(3, 2)), 2);  // 1 and sqrt 2
  EXPECT_EQ(isolate_roots(p, Exact(1), Exact(2)).size(), 3u);  // both ends are roots
}

TEST(ExactRealRoots, SignAtAnIrrationalRoot) {
  const ExactPolynomial two = poly_from({Exact(-2), Exact(0), Exact(1)});
  const ExactPolynomial p = two * lin(Exact(3));
  auto roots = isolate_roots(p, Exact(0), Exact(2));
  ASSERT_EQ(roots.size(), 1u);
  IsolatedRoot r = roots[0];
  EXPECT_EQ(sign_at_root(p, r, two), 0);
  EXPECT_EQ(sign_at_root(p, r, two * lin(Exact(5))), 0);
  EXPECT_EQ(sign_at_root(p, r, lin(Exact(141421356, 100000000))), 1);
  EXPECT_EQ(sign_at_root(p, r, lin(Exact(141421357, 100000000))), -1);
  EXPECT_EQ(sign_at_root(p, r, poly_from({Exact(-1)})), -1);
  EXPECT_TRUE(Exact(141421356, 100000000) < r.hi);
}

TEST(ExactRealRoots, SquareFreePartKeepsTheDistinctRoots) {
  const ExactPolynomial p = lin(Exact(1)) * lin(Exact(1)) * lin(Exact(1)) * lin(Exact(-2));
  const ExactPolynomial q = poly_square_free(p);
  EXPECT_EQ(q.degree(), 2);
  EXPECT_EQ(CGAL::sign(q(Exact(1))), 0);
  EXPECT_EQ(CGAL::sign(q(Exact(-2))), 0);
  EXPECT_EQ(poly_gcd(p, poly_derivative(p)).degree(), 2);
  EXPECT_EQ(isolate_roots(q, Exact(-5), Exact(5)).size(), 2u);
}

}  // namespace
