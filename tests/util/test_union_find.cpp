// UnionFind against a brute-force oracle: sets kept as explicit label vectors, relabelled on every union.
#include "util/union_find.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

TEST(UnionFind, MatchesExplicitLabels) {
  std::mt19937 rng(7);
  for (int round = 0; round < 20; ++round) {
    const int n = 1 + static_cast<int>(rng() % 60);
    exactvis::UnionFind uf(static_cast<std::size_t>(n / 2));
    std::vector<int> label;
    for (int i = 0; i < n / 2; ++i) label.push_back(i);
    while (static_cast<int>(uf.size()) < n) {
      EXPECT_EQ(uf.add(), static_cast<int>(label.size()));
      label.push_back(static_cast<int>(label.size()));
    }
    ASSERT_EQ(uf.size(), static_cast<std::size_t>(n));
    for (int step = 0; step < 2 * n; ++step) {
      const int a = static_cast<int>(rng() % n), b = static_cast<int>(rng() % n);
      const int root_b = uf.find(b);
      uf.unite(a, b);
      EXPECT_EQ(uf.find(a), root_b) << "unite(a, b) keeps b's representative";
      const int la = label[a], lb = label[b];
      for (int& l : label)
        if (l == la) l = lb;
      for (int x = 0; x < n; ++x)
        for (int y = 0; y < n; ++y) ASSERT_EQ(uf.find(x) == uf.find(y), label[x] == label[y]) << x << " " << y;
    }
  }
}

}  // namespace
