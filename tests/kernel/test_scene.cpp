// kernel/scene: lookup by stable id (ids with gaps where degenerate triangles were dropped) and bounding
// boxes, against brute force.
#include "kernel/scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace exactvis {
namespace {

Scene random_scene(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> u(-100, 100);
  std::bernoulli_distribution dropped(0.3);
  Scene s;
  std::int64_t id = 0;
  for (int i = 0; i < n; ++i) {
    while (dropped(rng)) ++id;  // ids of dropped triangles are absent
    const int base = static_cast<int>(s.vertices.size());
    for (int k = 0; k < 3; ++k) s.vertices.push_back({u(rng), u(rng), u(rng)});
    s.triangles.push_back({id++, {base, base + 1, base + 2}, 0});
  }
  s.objects.push_back({"all"});
  return s;
}

TEST(Scene, IndexOfIdMatchesLinearSearch) {
  std::mt19937_64 rng(61);
  for (int rep = 0; rep < 20; ++rep) {
    const Scene s = random_scene(rng, 1 + rep * 7);
    const std::int64_t max_id = s.triangles.back().id + 3;
    for (std::int64_t id = -2; id <= max_id; ++id) {
      std::int64_t expected = -1;
      for (size_t i = 0; i < s.triangles.size(); ++i)
        if (s.triangles[i].id == id) expected = static_cast<std::int64_t>(i);
      ASSERT_EQ(s.index_of_id(id), expected) << "id " << id;
    }
  }
}

TEST(Scene, BoundingBoxContainsExactlyTheUsedCorners) {
  std::mt19937_64 rng(62);
  Scene s = random_scene(rng, 50);
  s.vertices.push_back({1e6, -1e6, 0});  // a vertex no triangle uses does not count
  const Box3 b = bounding_box(s);
  ASSERT_FALSE(b.empty());
  for (int k = 0; k < 3; ++k) {
    double lo = 1e300, hi = -1e300;
    for (const auto& t : s.triangles)
      for (int c = 0; c < 3; ++c) {
        lo = std::min(lo, s.corner(t, c)[k]);
        hi = std::max(hi, s.corner(t, c)[k]);
      }
    EXPECT_EQ(b.lo[k], lo);
    EXPECT_EQ(b.hi[k], hi);
  }
  EXPECT_TRUE(bounding_box(Scene{}).empty());
}

}  // namespace
}  // namespace exactvis
