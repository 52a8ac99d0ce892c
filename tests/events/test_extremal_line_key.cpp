// Extremal line keys: canonical forms (generator order does not matter), a total order consistent with ==
// and the hash, and the EEEE branch: the two transversals of four edges' lines get branches 0 and 1 whatever
// the edge order and however the line is represented (its orientation, a positive or negative scale).
#include "events/extremal_line_key.hpp"
#include "kernel/lines_through_four_lines.hpp"
#include "kernel/predicates.hpp"
#include "tests/events/event_test_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <unordered_set>

namespace exactvis {
namespace {

TEST(ExtremalLineKey, CanonicalForms) {
  EXPECT_EQ(vv_key(7, 3), vv_key(3, 7));
  EXPECT_EQ(vee_key(4, {9, 2}, {1, 5}), vee_key(4, {1, 5}, {2, 9}));
  EXPECT_NE(vee_key(4, {1, 5}, {2, 9}), vee_key(5, {1, 5}, {2, 9}));
  EXPECT_EQ(fee_key(11, {8, 3}, {1, 2}), fee_key(11, {1, 2}, {3, 8}));
  EXPECT_NE(fee_key(11, {1, 2}, {3, 8}), fee_key(12, {1, 2}, {3, 8}));
  EXPECT_EQ(veff_key(0, {6, 5}, 9, 4), veff_key(0, {5, 6}, 4, 9));
  // EEEF and EEP: the third edge has its own role.
  EXPECT_EQ(eeef_key({3, 1}, {0, 2}, {7, 6}, 5), eeef_key({0, 2}, {1, 3}, {6, 7}, 5));
  EXPECT_NE(eeef_key({0, 2}, {1, 3}, {6, 7}, 5), eeef_key({0, 2}, {6, 7}, {1, 3}, 5));
  EXPECT_NE(eep_key({0, 2}, {1, 3}, {6, 7}), eeef_key({0, 2}, {1, 3}, {6, 7}, -1));
  // Kinds differ even with the same generator slots.
  EXPECT_NE(fve_key(3, 1, {4, 5}), vef_key(1, {4, 5}, 3));
  EXPECT_EQ(to_string(vee_key(4, {9, 2}, {1, 5})), "VEE(v 4; e [1,5] [2,9])");
  EXPECT_EQ(to_string(fve_key(12, 3, {6, 5})), "FVE(v 3; e [5,6]; f 12)");
  EXPECT_EQ(vv_key(1, 2).vertex_count(), 2);
  EXPECT_EQ(eeef_key({0, 2}, {1, 3}, {6, 7}, 5).edge_count(), 3);
  EXPECT_EQ(veff_key(0, {5, 6}, 4, 9).face_count(), 2);
}

TEST(ExtremalLineKey, OrderAndHashAgreeWithEquality) {
  std::mt19937 rng(3);
  std::vector<ExtremalLineKey> keys;
  auto e = [&] { return edge_ids(static_cast<int>(rng() % 6), 6 + static_cast<int>(rng() % 4)); };
  for (int i = 0; i < 400; ++i) {
    const int v = static_cast<int>(rng() % 5);
    switch (rng() % 5) {
      case 0: keys.push_back(vv_key(v, static_cast<int>(rng() % 5))); break;
      case 1: keys.push_back(vee_key(v, e(), e())); break;
      case 2: keys.push_back(fve_key(static_cast<std::int64_t>(rng() % 3), v, e())); break;
      case 3: keys.push_back(fee_key(static_cast<std::int64_t>(rng() % 3), e(), e())); break;
      default: keys.push_back(eep_key(e(), e(), e())); break;
    }
  }
  const std::set<ExtremalLineKey> ordered(keys.begin(), keys.end());
  const std::unordered_set<ExtremalLineKey> hashed(keys.begin(), keys.end());
  EXPECT_EQ(ordered.size(), hashed.size());
  EXPECT_LT(ordered.size(), keys.size());  // the draws repeat keys: equality is exercised
  for (const auto& a : keys)
    for (const auto& b : keys) {
      ASSERT_EQ(a == b, !(a < b) && !(b < a));
      if (a == b) {
        ASSERT_EQ(std::hash<ExtremalLineKey>{}(a), std::hash<ExtremalLineKey>{}(b));
      }
    }
}

// Four random edges with two real transversals: eeee_key ranks them 0 and 1 independently of the edge order
// and of the scale (sign included) of the line's coordinates.
TEST(ExtremalLineKey, EeeeBranchIsIntrinsic) {
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> c(-50, 50);
  int tested = 0;
  for (int round = 0; round < 400 && tested < 40; ++round) {
    std::vector<Point3> v;
    for (int i = 0; i < 8; ++i) v.push_back({double(c(rng)), double(c(rng)), double(c(rng))});
    const Scene s = event_test::make_scene(v, {{0, 1, 2}, {3, 4, 5}, {6, 7, 0}});  // only vertices are used
    std::array<EdgeIds, 4> edges{EdgeIds{0, 1}, EdgeIds{2, 3}, EdgeIds{4, 5}, EdgeIds{6, 7}};
    std::array<PluckerLine<Exact>, 4> lines;
    for (int i = 0; i < 4; ++i)
      lines[i] = line_through(to_rational(v[edges[i][0]]), to_rational(v[edges[i][1]]));
    const LinesThroughFourLines t = lines_through_four_lines(lines);
    if (t.kind != TransversalKind::Finite || t.lines.size() != 2) continue;
    ++tested;
    std::set<int> branches;
    for (const auto& line : t.lines) {
      const ExtremalLineKey k = eeee_key(s, edges, line);
      branches.insert(k.branch);
      // Other edge order (and reversed vertex order within an edge), and the reversed, scaled line.
      std::array<EdgeIds, 4> shuffled{EdgeIds{7, 6}, edges[2], EdgeIds{1, 0}, edges[1]};
      PluckerLine<RootNumber> scaled = line;
      for (int i = 0; i < 3; ++i) scaled.d[i] = scaled.d[i] * RootNumber(-3), scaled.m[i] = scaled.m[i] * RootNumber(-3);
      EXPECT_EQ(eeee_key(s, shuffled, scaled), k);
      EXPECT_EQ(k.edges[0], (EdgeIds{0, 1}));
      EXPECT_EQ(k.edges[3], (EdgeIds{6, 7}));
    }
    EXPECT_EQ(branches, (std::set<int>{0, 1}));
  }
  EXPECT_GE(tested, 20);
}

}  // namespace
}  // namespace exactvis
