// Exact cluster-to-cluster visibility of Quake 3 maps (io/quake3_cluster_visibility.hpp) on maps written by
// the tests with known answers (tests/io/bsp_test_writer.hpp): the tunnels map (hidden pairs that only the
// exact portal-to-portal queries can prove) and the doorway map (a slanted plane, a vis blocker); every
// witness re-checked by an independent GMP oracle (segment against the maps' solid boxes, ends in the
// clusters' regions written as inequalities).
#include "io/quake3_cluster_visibility.hpp"

#include "bsp_test_writer.hpp"
#include "io_test_util.hpp"

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <functional>

using namespace exactvis;
using namespace exactvis::quake3;

namespace {

using Q3 = std::array<mpq_class, 3>;

Q3 q3(const RationalPoint3& p) { return {mpq_class(p.x.mpq()), mpq_class(p.y.mpq()), mpq_class(p.z.mpq())}; }

// Does the closed segment [p, q] meet the closed box [lo, hi]? (Liang-Barsky with rationals.)
bool segment_meets_box(const Q3& p, const Q3& q, const Q3& lo, const Q3& hi) {
  mpq_class t0 = 0, t1 = 1;
  for (int k = 0; k < 3; ++k) {
    const mpq_class d = q[k] - p[k];
    if (d == 0) {
      if (p[k] < lo[k] || p[k] > hi[k]) return false;
      continue;
    }
    mpq_class a = (lo[k] - p[k]) / d, b = (hi[k] - p[k]) / d;
    if (a > b) std::swap(a, b);
    if (a > t0) t0 = a;
    if (b < t1) t1 = b;
    if (t0 > t1) return false;
  }
  return true;
}

Q3 q(double x, double y, double z) { return {mpq_class(x), mpq_class(y), mpq_class(z)}; }

struct Oracle {
  std::vector<std::pair<Q3, Q3>> solids;
  std::function<bool(int, const Q3&)> in_cluster;  // closed region
  void check(int a, int b, const region::Witness& w) const {
    const Q3 p = q3(w.p), qq = q3(w.q);
    EXPECT_TRUE(in_cluster(a, p)) << a << " -> " << b << ": p not in cluster " << a;
    EXPECT_TRUE(in_cluster(b, qq)) << a << " -> " << b << ": q not in cluster " << b;
    for (const auto& [lo, hi] : solids) EXPECT_FALSE(segment_meets_box(p, qq, lo, hi)) << a << " -> " << b;
  }
};

bool in_box(const Q3& p, const Q3& lo, const Q3& hi) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < lo[k] || p[k] > hi[k]) return false;
  return true;
}

BspMap read_written(const iotest::TempDir& dir, const bsptest::Bsp& b) {
  return read_bsp(iotest::write_file(dir.file("map.bsp"), b.bytes()));
}

}  // namespace

TEST(Quake3ClusterVisibility, TunnelsMapKnownAnswers) {
  iotest::TempDir dir;
  const BspMap map = read_written(dir, bsptest::tunnels_map().bsp);
  const ClusterVisibilityChecker checker(map, Occluders::Leaves);
  ASSERT_EQ(checker.cluster_count(), 5);
  // Portals: A-D1, D1-B, B-D2, D2-C, each seen from both sides.
  const std::vector<std::size_t> expected_portals{1, 2, 2, 2, 1};
  for (int c = 0; c < 5; ++c) EXPECT_EQ(checker.portals()[static_cast<std::size_t>(c)].size(), expected_portals[static_cast<std::size_t>(c)]) << c;
  Oracle oracle;
  oracle.solids = {{q(100, 16, 0), q(200, 128, 128)}, {q(220, 0, 0), q(320, 112, 128)}};
  const Q3 boxes[5][2] = {{q(0, 0, 0), q(100, 128, 128)}, {q(100, 0, 0), q(200, 16, 128)},
                          {q(200, 0, 0), q(220, 128, 128)}, {q(220, 112, 0), q(320, 128, 128)},
                          {q(320, 0, 0), q(384, 128, 128)}};
  oracle.in_cluster = [&](int c, const Q3& p) { return in_box(p, boxes[c][0], boxes[c][1]); };
  for (int a = 0; a < 5; ++a)
    for (int b = 0; b < 5; ++b) {
      if (a == b) continue;
      const ClusterVisibility v = checker.check(a, b);
      EXPECT_EQ(v.visible, bsptest::TunnelsMap::exact(a, b)) << a << " -> " << b;
      EXPECT_EQ(v.witness.has_value(), v.visible);
      if (v.witness) oracle.check(a, b, *v.witness);
    }
  EXPECT_THROW(checker.check(0, 0), std::invalid_argument);
  EXPECT_THROW(checker.check(0, 5), std::out_of_range);
}

TEST(Quake3ClusterVisibility, DoorwayMapEveryPairVisible) {
  iotest::TempDir dir;
  const BspMap map = read_written(dir, bsptest::doorway_map().bsp);
  const ClusterVisibilityChecker checker(map, Occluders::Leaves);
  Oracle oracle;
  // Solid leaves: the wall below and above the doorway and the lintel (a vis blocker).
  oracle.solids = {{q(120, 0, 0), q(136, 48, 128)}, {q(120, 80, 0), q(136, 128, 128)}, {q(120, 48, 96), q(136, 80, 128)}};
  const mpq_class a(double(0.6f)), bb(double(0.8f)), d(double(170.3f));
  oracle.in_cluster = [&](int c, const Q3& p) {
    if (!in_box(p, q(0, 0, 0), q(256, 128, 128))) return false;
    switch (c) {
      case 0: return p[0] <= 120;
      case 2: return in_box(p, q(120, 48, 0), q(136, 80, 96));
      case 1: return p[0] >= 136 && a * p[0] + bb * p[1] >= d;
      case 3: return p[0] >= 136 && a * p[0] + bb * p[1] <= d;
    }
    return false;
  };
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y) {
      if (x == y) continue;
      const ClusterVisibility v = checker.check(x, y);
      EXPECT_TRUE(v.visible) << x << " -> " << y;
      if (v.witness) oracle.check(x, y, *v.witness);
    }
  EXPECT_THROW(ClusterVisibilityChecker(map, Occluders::Brushes), std::invalid_argument);
}

TEST(Quake3ClusterVisibility, SealedDoorwayHidesTheRooms) {
  // The doorway leaf made solid: room A is sealed; cluster 2 has no leaf left (empty region: hidden).
  bsptest::Bsp b = bsptest::doorway_map().bsp;
  b.leaves[5].cluster = -1;
  iotest::TempDir dir;
  const BspMap map = read_written(dir, b);
  const ClusterVisibilityChecker checker(map, Occluders::Leaves);
  EXPECT_TRUE(checker.region_empty(2));
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y) {
      if (x == y) continue;
      const bool expected = (x == 1 && y == 3) || (x == 3 && y == 1);
      EXPECT_EQ(checker.check(x, y).visible, expected) << x << " -> " << y;
    }
}
