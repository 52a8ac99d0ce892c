// Virtual occluders of the exact PVS (region/virtual_occluders.hpp) against the independent oracle
// (tests/oracles): the exact segment/box test equals "an endpoint in the closed box or the segment meets one
// of its 12 closed face triangles" on random and degenerate (touching, grazing, flat) configurations; a
// "blocked" answer survives random exact segments from the cell to the target, and a "not blocked" answer has
// a corner segment that the oracle sees missing the box; the list keeps at most its cap, best first.
#include "oracles/rational_geometry.hpp"
#include "region/virtual_occluders.hpp"
#include "tests/region/oracle_input.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

using region_test::qv;

// The oracle: the closed segment meets the closed box iff an endpoint is in it or the segment meets its
// boundary, the union of 12 closed triangles (two per face; degenerate for flat boxes, which the oracle
// treats as segments or points).
bool oracle_meets_box(const oracle::QVec& a, const oracle::QVec& b, const oracle::QVec& lo, const oracle::QVec& hi) {
  if (oracle::oracle_point_in_closed_box(a, lo, hi) || oracle::oracle_point_in_closed_box(b, lo, hi)) return true;
  auto corner = [&](int k) {
    return oracle::QVec{(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z};
  };
  // Faces as corner quadruples (bits of the corner index), each cut along a diagonal.
  static const int faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (const auto& f : faces)
    if (oracle::oracle_closed_segment_meets_closed_triangle(a, b, corner(f[0]), corner(f[1]), corner(f[2])) ||
        oracle::oracle_closed_segment_meets_closed_triangle(a, b, corner(f[0]), corner(f[2]), corner(f[3])))
      return true;
  return false;
}

// Coordinates on a coarse grid (many touching and parallel cases), some of them exact thirds.
Exact coarse(std::mt19937_64& rng, bool thirds) {
  const int k = static_cast<int>(rng() % 13) - 6;
  return thirds && rng() % 3 == 0 ? Exact(k, 3) : Exact(k);
}
double coarse_double(std::mt19937_64& rng) { return static_cast<double>(static_cast<long>(rng() % 13) - 6) / 2; }

Box3 random_box(std::mt19937_64& rng, bool allow_flat) {
  Box3 b;
  for (int k = 0; k < 3; ++k) {
    double x = coarse_double(rng), y = coarse_double(rng);
    if (!allow_flat && x == y) y = x + 0.5;
    b.lo[k] = std::min(x, y);
    b.hi[k] = std::max(x, y);
  }
  return b;
}

TEST(VirtualOccluders, SegmentMeetsBoxAgreesWithTheOracle) {
  std::mt19937_64 rng(1234);
  int meets = 0, misses = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const RationalPoint3 a{coarse(rng, true), coarse(rng, true), coarse(rng, true)};
    const Point3 b{coarse_double(rng), coarse_double(rng), coarse_double(rng)};
    const Box3 v = random_box(rng, trial % 4 == 0);
    const bool expected = oracle_meets_box(qv(a), qv(b), qv(v.lo), qv(v.hi));
    ASSERT_EQ(segment_meets_box(a, b, v), expected)
        << "trial " << trial << " a " << a.x << "," << a.y << "," << a.z << " b " << b.x << "," << b.y << "," << b.z;
    (expected ? meets : misses)++;
  }
  EXPECT_GT(meets, 400);
  EXPECT_GT(misses, 400);
  // Hand-picked: touching a corner, grazing a face, a degenerate segment, through a flat box.
  const Box3 unit{{0, 0, 0}, {1, 1, 1}};
  EXPECT_TRUE(segment_meets_box({Exact(2), Exact(2), Exact(2)}, {1, 1, 1}, unit));
  EXPECT_TRUE(segment_meets_box({Exact(-1), Exact(1), Exact(0.5)}, {2, 1, 0.5}, unit));  // along a face
  EXPECT_FALSE(segment_meets_box({Exact(-1), Exact(1) + Exact(1, 1000000), Exact(0.5)}, {2, 1, 0.5}, unit));
  EXPECT_TRUE(segment_meets_box({Exact(1, 2), Exact(1, 2), Exact(1, 2)}, {0.5, 0.5, 0.5}, unit));
  EXPECT_FALSE(segment_meets_box({Exact(3, 2), Exact(1, 2), Exact(1, 2)}, {1.5, 0.5, 0.5}, unit));
  const Box3 flat{{0, 0, 0}, {1, 1, 0}};
  EXPECT_TRUE(segment_meets_box({Exact(1, 3), Exact(2, 3), Exact(-1)}, {0.5, 0.5, 1}, flat));
  EXPECT_FALSE(segment_meets_box({Exact(4, 3), Exact(2, 3), Exact(-1)}, {1.25, 0.5, 1}, flat));
}

// A random exact point of the closed box [lo, hi] (including its faces: coordinates k/8 of the way).
oracle::QVec random_in(std::mt19937_64& rng, const oracle::QVec& lo, const oracle::QVec& hi) {
  auto f = [&](const mpq_class& l, const mpq_class& h) -> mpq_class {
    mpq_class w(static_cast<long>(rng() % 9), 8);
    w.canonicalize();
    return l + (h - l) * w;
  };
  return {f(lo.x, hi.x), f(lo.y, hi.y), f(lo.z, hi.z)};
}

TEST(VirtualOccluders, BoxBlocksIsRightOnRandomCellsBoxesAndTargets) {
  // Cell on the left, a wall-like box V in the middle, targets on the right: many blocked, many not.
  std::mt19937_64 rng(99);
  int blocked = 0, not_blocked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    auto u = [&](double lo, double hi) { return lo + (hi - lo) * static_cast<double>(rng() % 1000) / 1000; };
    const double cy = u(-1, 1), cz = u(-1, 1);
    const RationalBox3 cell{{Exact(-5), Exact(cy) - Exact(1, 3), Exact(cz) - Exact(1, 3)},
                            {Exact(-4), Exact(cy) + Exact(1, 3), Exact(cz) + Exact(1, 3)}};
    const Box3 v{{u(-1, 0), u(-4, -1), u(-4, -1)}, {u(0, 1), u(1, 4), u(1, 4)}};
    const double ty = u(-3, 3), tz = u(-3, 3), s = u(0.1, 2);
    const Box3 target{{u(2, 4), ty, tz}, {u(4, 6), ty + s, tz + s}};
    const std::array<Point3, 8> corners = corners_of(target);
    const bool b = box_blocks(v, cell, corners);
    const oracle::QVec clo = qv(cell.lo), chi = qv(cell.hi), vlo = qv(v.lo), vhi = qv(v.hi);
    const oracle::QVec tlo = qv(target.lo), thi = qv(target.hi);
    if (b) {
      ++blocked;
      for (int k = 0; k < 40; ++k)
        ASSERT_TRUE(oracle_meets_box(random_in(rng, clo, chi), random_in(rng, tlo, thi), vlo, vhi)) << "trial " << trial;
    } else {
      ++not_blocked;
      bool some_miss = false;
      for (int i = 0; i < 8 && !some_miss; ++i) {
        const oracle::QVec a{(i & 1) ? chi.x : clo.x, (i & 2) ? chi.y : clo.y, (i & 4) ? chi.z : clo.z};
        for (const Point3& c : corners) some_miss |= !oracle_meets_box(a, qv(c), vlo, vhi);
      }
      EXPECT_TRUE(some_miss) << "trial " << trial << ": every corner segment meets V, yet not blocked";
    }
  }
  EXPECT_GT(blocked, 40);
  EXPECT_GT(not_blocked, 40);
}

TEST(VirtualOccluders, ListKeepsTheCapBestFirstAndBlocksOnlyWithADarkBox) {
  const RationalBox3 cell{{Exact(-5), Exact(-1, 2), Exact(-1, 2)}, {Exact(-4), Exact(1, 2), Exact(1, 2)}};
  const Box3 target{{3, -0.25, -0.25}, {4, 0.25, 0.25}};
  const std::array<Point3, 8> tc = corners_of(target);
  VirtualOccluders none(cell, 0);
  none.add({{0, -3, -3}, {1, 3, 3}});
  EXPECT_EQ(none.size(), 0u);
  EXPECT_FALSE(none.blocks(tc));
  VirtualOccluders two(cell, 2);
  two.add({{0, 5, 5}, {1, 6, 6}});      // off to the side: blocks nothing
  EXPECT_FALSE(two.blocks(tc));
  two.add({{0, -3, -3}, {1, 3, 3}});    // a large wall between cell and target
  two.add({{10, 20, 20}, {10.5, 20.5, 20.5}});  // small and far: dropped by the cap
  EXPECT_EQ(two.size(), 2u);
  EXPECT_EQ(two.added(), 3);
  EXPECT_TRUE(two.blocks(tc));
  EXPECT_TRUE(two.blocks(tc));  // the same box, tried first
  const Box3 beside{{3, 5, 5}, {4, 5.5, 5.5}};
  EXPECT_FALSE(two.blocks(corners_of(beside)));
}

}  // namespace
