// rational_strictly_between: the result lies strictly between its arguments (exact comparisons), also for
// nearly equal irrational numbers and numbers with different roots; bad input throws.
#include "kernel/rational_between.hpp"

#include <gtest/gtest.h>

namespace exactvis {
namespace {

TEST(RationalBetween, StrictlyBetween) {
  const RootNumber a(Exact(0), Exact(1), Exact(2));  // sqrt 2
  const RootNumber b(Exact(1, 1000000000), Exact(1), Exact(2));
  const Exact q = rational_strictly_between(a, b);
  EXPECT_TRUE(a < RootNumber(q) && RootNumber(q) < b);
  const Exact r = rational_strictly_between(RootNumber(Exact(1)), a);
  EXPECT_TRUE(RootNumber(1) < RootNumber(r) && RootNumber(r) < a);
  EXPECT_THROW(rational_strictly_between(b, a), std::invalid_argument);
}

TEST(RationalBetween, DifferentRootsAndRationals) {
  const RootNumber a(Exact(0), Exact(1), Exact(3));  // sqrt 3
  const RootNumber b(Exact(2), Exact(-1, 10), Exact(2));  // 2 - sqrt(2)/10 = 1.858... > sqrt 3
  const Exact q = rational_strictly_between(a, b);
  EXPECT_TRUE(a < RootNumber(q) && RootNumber(q) < b);
  EXPECT_TRUE(rational_strictly_between(RootNumber(Exact(1, 3)), RootNumber(Exact(1, 2))) == Exact(5, 12));
  Exact r;
  EXPECT_TRUE(root_number_rational(RootNumber(Exact(7)), &r) && r == Exact(7));
  EXPECT_FALSE(root_number_rational(a, &r));
}

}  // namespace
}  // namespace exactvis
