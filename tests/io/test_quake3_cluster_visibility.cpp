// Exact cluster-to-cluster visibility of Quake 3 maps (io/quake3_cluster_visibility.hpp) on maps written by
// the tests with known answers (tests/io/bsp_test_writer.hpp): the tunnels map (hidden pairs that only the
// exact portal-to-portal queries can prove) and the doorway map (a slanted plane, a vis blocker); with
// occluders `brushes`, doorway maps with detail brushes filling the doorway, straddling its portal and
// overlapping each other, and non-solid brushes that must be ignored; every
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

// The doorway map's clusters as inequalities (closed regions).
bool doorway_in_cluster(int c, const Q3& p) {
  const mpq_class a(double(0.6f)), bb(double(0.8f)), d(double(170.3f));
  if (!in_box(p, q(0, 0, 0), q(256, 128, 128))) return false;
  switch (c) {
    case 0: return p[0] <= 120;
    case 2: return in_box(p, q(120, 48, 0), q(136, 80, 96));
    case 1: return p[0] >= 136 && a * p[0] + bb * p[1] >= d;
    case 3: return p[0] >= 136 && a * p[0] + bb * p[1] <= d;
  }
  return false;
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
  oracle.in_cluster = doorway_in_cluster;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y) {
      if (x == y) continue;
      const ClusterVisibility v = checker.check(x, y);
      EXPECT_TRUE(v.visible) << x << " -> " << y;
      if (v.witness) oracle.check(x, y, *v.witness);
    }
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

// ---- Occluders `brushes` (docs/theory.md §8.2): the world model's solid brushes, detail brushes included. ----
namespace {

// The doorway map's solid world brushes as boxes: the two wall parts and the detail pillar in room A (the
// lintel is `nodrawnonsolid`, contents 0; brush 4 belongs to model 1, a door).
std::vector<std::pair<Q3, Q3>> doorway_solid_brushes() {
  return {{q(120, 0, 0), q(136, 48, 128)}, {q(120, 80, 0), q(136, 128, 128)}, {q(32, 32, 0), q(48, 48, 64)}};
}

// The doorway map with the lintel's brush made solid (a shader with the solid bit).
bsptest::Bsp doorway_with_solid_lintel() {
  bsptest::Bsp b = bsptest::doorway_map().bsp;
  b.shaders.push_back({"textures/base/lintel", 0, 1});
  b.brushes[2].shader = static_cast<int>(b.shaders.size()) - 1;
  return b;
}

struct BrushCase {
  bsptest::Bsp bsp;
  std::vector<std::pair<Q3, Q3>> solids;  // every solid world brush, for the oracle
};

// Adds solid world box brushes (shader 2, the pillar's: contents solid, no detail bit, as in real maps).
BrushCase with_brushes(bsptest::Bsp b, std::vector<std::pair<Q3, Q3>> solids,
                       const std::vector<std::pair<std::array<float, 3>, std::array<float, 3>>>& boxes) {
  for (const auto& [lo, hi] : boxes) {
    bsptest::add_world_box_brush(b, lo, hi, 2);
    solids.push_back({q(lo[0], lo[1], lo[2]), q(hi[0], hi[1], hi[2])});
  }
  return {std::move(b), std::move(solids)};
}

// Checks every ordered pair against expected(a, b), witnesses by the oracle (closed segment misses every
// solid brush box, ends in their closed cluster regions).
template <class F>
void check_doorway_pairs(const BrushCase& c, F expected, const std::string& what) {
  iotest::TempDir dir;
  const BspMap map = read_written(dir, c.bsp);
  const ClusterVisibilityChecker checker(map, Occluders::Brushes);
  Oracle oracle;
  oracle.solids = c.solids;
  oracle.in_cluster = doorway_in_cluster;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y) {
      if (x == y) continue;
      const ClusterVisibility v = checker.check(x, y);
      EXPECT_EQ(v.visible, expected(x, y)) << what << ": " << x << " -> " << y;
      EXPECT_EQ(v.witness.has_value(), v.visible) << what;
      if (v.witness) oracle.check(x, y, *v.witness);
    }
}

}  // namespace

TEST(Quake3ClusterVisibility, BrushesDoorwayMapEveryPairVisible) {
  // The pillar stands in room A and the lintel is not solid: every pair is visible, past the pillar.
  check_doorway_pairs({bsptest::doorway_map().bsp, doorway_solid_brushes()}, [](int, int) { return true; }, "doorway");
}

TEST(Quake3ClusterVisibility, BrushesDetailBrushBlocksTheDoorway) {
  // A detail brush fills the doorway leaf (cluster 2, whose region then lies inside it: no viewpoint); the
  // lintel solid: room A is sealed; the rooms B front and back still see each other. Leaves and the
  // visdata (everything visible except the planted bits) do not see the brush.
  const BrushCase c = with_brushes(doorway_with_solid_lintel(), doorway_solid_brushes(), {{{120, 48, 0}, {136, 80, 96}}});
  check_doorway_pairs(c, [](int a, int b) { return (a == 1 && b == 3) || (a == 3 && b == 1); }, "detail doorway");
  iotest::TempDir dir;
  const BspMap map = read_written(dir, c.bsp);
  const ClusterVisibilityChecker leaves(map, Occluders::Leaves);
  EXPECT_TRUE(leaves.check(0, 1).visible);
  EXPECT_TRUE(leaves.check(2, 3).visible);
}

TEST(Quake3ClusterVisibility, BrushesIgnoreNonSolidBrushes) {
  // The same detail brush, the lintel `nodrawnonsolid` (contents 0): brushes mode sees over the detail
  // brush through the lintel's leaf (which leaves mode treats as solid).
  const BrushCase c = with_brushes(bsptest::doorway_map().bsp, doorway_solid_brushes(), {{{120, 48, 0}, {136, 80, 96}}});
  check_doorway_pairs(c, [](int a, int b) { return a != 2 && b != 2; }, "nodrawnonsolid lintel");
}

TEST(Quake3ClusterVisibility, BrushesStraddlingThePortal) {
  const bsptest::Bsp lintel = doorway_with_solid_lintel();
  // A brush across the portal x = 120 (half in room A, half in the doorway, into the wall) up to z = 64:
  // the doorway's upper part stays open, every pair visible past the brush.
  check_doorway_pairs(with_brushes(lintel, doorway_solid_brushes(), {{{110, 40, 0}, {130, 90, 64}}}),
                      [](int, int) { return true; }, "low straddling brush");
  // Up to z = 96 it closes room A; the doorway's free part x > 130 still sees both rooms B.
  check_doorway_pairs(with_brushes(lintel, doorway_solid_brushes(), {{{110, 40, 0}, {130, 90, 96}}}),
                      [](int a, int b) { return a != 0 && b != 0; }, "closing straddling brush");
}

TEST(Quake3ClusterVisibility, BrushesOverlapping) {
  const bsptest::Bsp lintel = doorway_with_solid_lintel();
  // Two overlapping brushes (y 40..70 and 60..90) close room A together, neither alone.
  check_doorway_pairs(with_brushes(lintel, doorway_solid_brushes(), {{{110, 40, 0}, {130, 70, 128}}, {{115, 60, 0}, {125, 90, 128}}}),
                      [](int a, int b) { return a != 0 && b != 0; }, "overlapping closed");
  // The second one ends at y = 78: a slit 78 < y < 80 of the doorway's full height stays open.
  check_doorway_pairs(with_brushes(lintel, doorway_solid_brushes(), {{{110, 40, 0}, {130, 70, 128}}, {{115, 60, 0}, {125, 78, 128}}}),
                      [](int, int) { return true; }, "overlapping with a slit");
}
