// push_sub_intervals against a brute-force oracle: on random integer cuts (repeats, cuts at the ends), popping
// the stack must give the integers' distinct values in [lo, hi] pairwise, left to right, covering [lo, hi]
// without gaps; what was on the stack before stays below.
#include "util/sub_intervals.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <utility>
#include <vector>

namespace {

TEST(SubIntervals, PoppingVisitsTheDistinctCutsLeftToRight) {
  std::mt19937 rng(11);
  for (int round = 0; round < 200; ++round) {
    const int lo = static_cast<int>(rng() % 20), hi = lo + 1 + static_cast<int>(rng() % 20);
    std::vector<int> cuts;
    const int k = static_cast<int>(rng() % 8);
    for (int i = 0; i < k; ++i) cuts.push_back(lo + static_cast<int>(rng() % (hi - lo + 1)));
    std::vector<std::pair<int, int>> todo{{-5, -4}};  // an earlier entry: must stay at the bottom
    exactvis::push_sub_intervals(cuts, lo, hi, todo);

    std::set<int> points(cuts.begin(), cuts.end());  // the oracle: sorted distinct points with both ends
    points.insert(lo);
    points.insert(hi);
    std::vector<std::pair<int, int>> expected;
    for (auto it = points.begin(); std::next(it) != points.end(); ++it) expected.emplace_back(*it, *std::next(it));

    std::vector<std::pair<int, int>> popped;
    while (todo.size() > 1) {
      popped.push_back(todo.back());
      todo.pop_back();
    }
    EXPECT_EQ(popped, expected) << "round " << round;
    ASSERT_EQ(todo.size(), 1u);
    EXPECT_EQ(todo.front(), std::make_pair(-5, -4));
  }
}

}  // namespace
