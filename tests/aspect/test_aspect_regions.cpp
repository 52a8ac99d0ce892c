// Regions of equal aspect from a cell complex: hand-made complexes whose regions and adjacencies are known.
#include "aspect/aspect_regions.hpp"

#include <gtest/gtest.h>

namespace {

using namespace exactvis;

// A segment split at a midpoint: v0 (A) - e0 (A) - m (B) - e1 (C) - v1 (C). Regions {v0, e0}, {m}, {e1, v1};
// the middle point touches both others; the two ends do not touch each other.
TEST(AspectRegions, SplitSegment) {
  std::vector<AspectCell> c(5);
  c[0] = {0, 0, {}};      // v0, aspect A
  c[1] = {0, 1, {}};      // m, aspect B
  c[2] = {0, 2, {}};      // v1, aspect C
  c[3] = {1, 0, {0, 1}};  // e0, aspect A
  c[4] = {1, 2, {1, 2}};  // e1, aspect C
  const AspectRegions r = aspect_regions(c, std::vector<bool>(5, true));
  ASSERT_EQ(r.members.size(), 3u);
  EXPECT_EQ(r.region_of[0], r.region_of[3]);
  EXPECT_EQ(r.region_of[2], r.region_of[4]);
  EXPECT_EQ(r.dimension[r.region_of[1]], 0);
  EXPECT_EQ(r.dimension[r.region_of[3]], 1);
  ASSERT_EQ(r.adjacency.size(), 2u);
  for (const auto& a : r.adjacency) {
    EXPECT_LT(a.a, a.b);
    EXPECT_TRUE(a.a == r.region_of[1] || a.b == r.region_of[1]);
  }
  // Regions are numbered by decreasing dimension.
  EXPECT_EQ(r.dimension.front(), 1);
}

// A face F (aspect A) whose edge e has another aspect (B) and whose vertex v (in e's closure) has aspect A:
// v lies in F's closure, so F and v form one region, and the region touches e's region; cells not kept
// (here a second vertex w) are skipped with their own facets.
TEST(AspectRegions, ClosureIsTransitive) {
  std::vector<AspectCell> c(4);
  c[0] = {0, 0, {}};      // v, aspect A
  c[1] = {0, 0, {}};      // w, aspect A, not a viewpoint
  c[2] = {1, 1, {0, 1}};  // e, aspect B
  c[3] = {2, 0, {2}};     // F, aspect A
  const AspectRegions r = aspect_regions(c, {true, false, true, true});
  ASSERT_EQ(r.members.size(), 2u);
  EXPECT_EQ(r.region_of[0], r.region_of[3]);
  EXPECT_EQ(r.region_of[1], -1);
  ASSERT_EQ(r.adjacency.size(), 1u);
  EXPECT_EQ(r.members[r.region_of[3]], (std::vector<int>{0, 3}));
}

}  // namespace
