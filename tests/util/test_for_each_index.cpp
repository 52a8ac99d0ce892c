// for_each_index visits every index exactly once, in order when not parallel.
#include "util/for_each_index.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace {

TEST(ForEachIndex, VisitsEveryIndexOnce) {
  for (const bool parallel : {false, true})
    for (const std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(7), std::size_t(1000)}) {
      std::vector<std::atomic<int>> seen(n);
      std::vector<std::size_t> order;
      exactvis::for_each_index(n, parallel, 3, [&](std::size_t i) {
        seen[i].fetch_add(1);
        if (!parallel) order.push_back(i);
      });
      for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(seen[i].load(), 1) << "n " << n << " index " << i;
      if (!parallel) {
        for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], i);
      }
    }
}

}  // namespace
