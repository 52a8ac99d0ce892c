// The one-wall occlusion proof (region/wall_umbra.hpp) on hand-computed cases: the horizontal condition
// (footprint inside the wall's 2D umbra, strict sides) and the vertical one (the crossing height bound,
// closed at exactly the wall's top), and the double proposal never accepting what the exact test refuses.
#include "region/wall_umbra.hpp"

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <array>
#include <cmath>
#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

// Cell [0,1] x [-1,1] x [0,1]; wall at x = 5, y in [-10, 10], z in [0, 10].
const RationalBox3 kCell = exact_box({{0, -1, 0}, {1, 1, 1}});
const Box3 kCellD{{0, -1, 0}, {1, 1, 1}};
const WallRectangle kWall{5, -10, 5, 10, 0, 10};

UmbraTarget square_at(double x, double y, double half, double z_lo, double z_hi) {
  return {{Point3{x - half, y - half, 0}, Point3{x + half, y - half, 0}, Point3{x - half, y + half, 0}, Point3{x + half, y + half, 0}},
          z_lo, z_hi};
}

bool both(const WallRectangle& w, const RationalBox3& cell, const Box3& cell_d, const UmbraTarget& t) {
  const bool exact = wall_hides_exactly(w, cell, t);
  const WallFromCell p = prepare_wall(w, cell_d);
  if (wall_may_hide(w, p, cell_d, t)) return exact;
  return exact;  // the proposal may reject a true case; the exact answer is what counts
}

}  // namespace

TEST(WallUmbra, HidesWhatIsBehindAndLowEnough) {
  EXPECT_TRUE(both(kWall, kCell, kCellD, square_at(9, 0, 1, 0, 1)));
  EXPECT_TRUE(wall_may_hide(kWall, prepare_wall(kWall, kCellD), kCellD, square_at(9, 0, 1, 0, 1)));
  // Beyond the wall's end in the top view: some line passes beside it (from (1, 1) to (6, 31): y = 25 at x = 5).
  EXPECT_FALSE(both(kWall, kCell, kCellD, square_at(7, 30, 1, 0, 1)));
  // Far in the wall's shadow though beyond its end's y: every line still crosses x = 5 below y = 10.
  EXPECT_TRUE(both(kWall, kCell, kCellD, square_at(12, 11, 1, 0, 1)));
  // In front of the wall (same side as the cell).
  EXPECT_FALSE(both(kWall, kCell, kCellD, square_at(3, 0, 1, 0, 1)));
  // Touching the wall's line: not strictly beyond.
  EXPECT_FALSE(both(kWall, kCell, kCellD, square_at(6, 0, 1, 0, 1)));
}

TEST(WallUmbra, VerticalBoundIsClosedAtTheWallTop) {
  // Target at x in [9, 11] (B in [4, 6] times 20), cell A in [4, 5] times 20: lambda_max = 5 / (5 + 4) = 5/9.
  // Height bound (1 - 5/9) * 1 + 5/9 * h <= 10  <=>  h <= 86/5 = 17.2. Exactly at the bound: hidden (closed).
  EXPECT_TRUE(wall_hides_exactly(kWall, kCell, square_at(10, 0, 1, 0, 17.2 - 1e-12)));
  WallRectangle w = kWall;
  // Target top 17: the bound is (4/9) + (5/9) * 17 = 89/9 (not a double): wall tops just above and below it.
  w.z_hi = 89.0 / 9.0 + 1e-9;
  EXPECT_TRUE(wall_hides_exactly(w, kCell, square_at(10, 0, 1, 0, 17)));
  w.z_hi = 89.0 / 9.0 - 1e-9;
  EXPECT_FALSE(wall_hides_exactly(w, kCell, square_at(10, 0, 1, 0, 17)));
  // A cell reaching above the wall still cannot see a low target far behind it (every segment crosses
  // x = 5 below z = 10: from (1, 11) to (8, 1) at z = 11 - 10 * 4/7), but one reaching much higher can.
  EXPECT_TRUE(wall_hides_exactly(kWall, exact_box({{0, -1, 0}, {1, 1, 11}}), square_at(9, 0, 1, 0, 1)));
  EXPECT_FALSE(wall_hides_exactly(kWall, exact_box({{0, -1, 0}, {1, 1, 30}}), square_at(9, 0, 1, 0, 1)));
  // A wall lifted off the ground: a target below its bottom is seen under it.
  WallRectangle lifted = kWall;
  lifted.z_lo = 0.5;
  const RationalBox3 high_cell = exact_box({{0, -1, 0.6}, {1, 1, 1}});
  EXPECT_TRUE(wall_hides_exactly(lifted, high_cell, square_at(9, 0, 1, 0.6, 1)));
  EXPECT_FALSE(wall_hides_exactly(lifted, high_cell, square_at(9, 0, 1, 0, 1)));
}

TEST(WallUmbra, ExactBoundaryOfTheTopView) {
  // Wall y in [-1, 1] at x = 2 (as wide as the cell); a target point on the umbra's edge line: the segment
  // from corner (0, 1) through the wall end (2, 1) continues to (4, 1): exactly on the edge, still hidden
  // (the segment meets the wall's end); a hair outside is not.
  const WallRectangle w{2, -1, 2, 1, 0, 10};
  const UmbraTarget on{{Point3{4, 1, 0}, Point3{4, -1, 0}, Point3{5, 0, 0}}, 0, 1};
  EXPECT_TRUE(wall_hides_exactly(w, kCell, on));
  const UmbraTarget off{{Point3{4, std::nextafter(1.0, 2.0), 0}, Point3{4, -1, 0}, Point3{5, 0, 0}}, 0, 1};
  EXPECT_FALSE(wall_hides_exactly(w, kCell, off));
  // Diagonal wall: the answer does not depend on which end is a.
  const WallRectangle d{3, -10, 7, 10, 0, 10};
  EXPECT_TRUE(wall_hides_exactly(d, kCell, square_at(9, 0, 0.5, 0, 1)));
}

// ---- Umbra fusion of two adjacent walls (wall_pair_hides_exactly). ----
namespace {

// A building [5, 9] x [0, 4] seen from the cell [0, 1] x [-3, -2] across its corner (5, 0): its front wall
// x = 5 and its side wall y = 0, both z in [0, 10].
const RationalBox3 kCornerCell = exact_box({{0, -3, 0}, {1, -2, 1}});
const Box3 kCornerCellD{{0, -3, 0}, {1, -2, 1}};
const WallRectangle kFront{5, 0, 5, 4, 0, 10}, kSide{5, 0, 9, 0, 0, 10};

// Independent check with GMP rationals: does the segment p q cross the wall's vertical plane strictly
// between its ends at a point of the closed rectangle?
bool segment_meets_wall(const std::array<mpq_class, 3>& p, const std::array<mpq_class, 3>& q, const WallRectangle& w) {
  const mpq_class ax(w.ax), ay(w.ay), bx(w.bx), by(w.by);
  auto f = [&](const std::array<mpq_class, 3>& x) -> mpq_class { return (bx - ax) * (x[1] - ay) - (by - ay) * (x[0] - ax); };
  const mpq_class fp = f(p), fq = f(q);
  if (!((fp > 0 && fq < 0) || (fp < 0 && fq > 0))) return false;
  const mpq_class t = fp / (fp - fq);
  const mpq_class x = p[0] + t * (q[0] - p[0]), y = p[1] + t * (q[1] - p[1]), z = p[2] + t * (q[2] - p[2]);
  const mpq_class s = (x - ax) * (bx - ax) + (y - ay) * (by - ay), len = (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
  return s >= 0 && s <= len && z >= mpq_class(w.z_lo) && z <= mpq_class(w.z_hi);
}

}  // namespace

TEST(WallUmbra, TwoWallsAtACornerHideWhatNeitherHides) {
  // Target around (12, 6): some segments from the cell cross the front wall, others the side wall.
  const UmbraTarget t = square_at(12, 6, 0.5, 0, 1);
  EXPECT_FALSE(wall_hides_exactly(kFront, kCornerCell, t));
  EXPECT_FALSE(wall_hides_exactly(kSide, kCornerCell, t));
  EXPECT_TRUE(wall_pair_hides_exactly(kFront, kSide, kCornerCell, t));
  EXPECT_TRUE(wall_pair_hides_exactly(kSide, kFront, kCornerCell, t));
  EXPECT_TRUE(wall_pair_may_hide(kFront, prepare_wall(kFront, kCornerCellD), kSide, prepare_wall(kSide, kCornerCellD),
                                 kCornerCellD, t));
  // Walls that do not touch (a gap 5 < x < 5.5 on y = 0 where lines pass): no proof.
  const WallRectangle apart{5.5, 0, 9, 0, 0, 10};
  EXPECT_FALSE(wall_pair_hides_exactly(kFront, apart, kCornerCell, t));
  // A side wall too low for the segments that cross it: no proof.
  const WallRectangle low{5, 0, 9, 0, 0, 0.3};
  EXPECT_FALSE(wall_pair_hides_exactly(kFront, low, kCornerCell, t));
  // A target beside the building's far end (segments pass beyond x = 9 on y = 0): no proof.
  EXPECT_FALSE(wall_pair_hides_exactly(kFront, kSide, kCornerCell, square_at(14, 1, 0.5, 0, 1)));
}

TEST(WallUmbra, TwoWallProofsSurviveRandomSegments) {
  // Random corners (two walls sharing an endpoint), cells and targets; every proof is attacked with random
  // segments from the cell to the target region (exact rationals), each of which must meet one of the walls.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  int proofs = 0, single = 0;
  for (int trial = 0; trial < 4000 && proofs < 60; ++trial) {
    const double mx = 4 + 4 * u(rng), my = 4 * u(rng) - 2;
    const double a1 = 2 * M_PI * u(rng), a2 = 2 * M_PI * u(rng), l1 = 1 + 5 * u(rng), l2 = 1 + 5 * u(rng);
    const WallRectangle w1{mx, my, std::round(mx + l1 * std::cos(a1)), std::round(my + l1 * std::sin(a1)), 0, 1 + 3 * u(rng)};
    const WallRectangle w2{mx, my, std::round(mx + l2 * std::cos(a2)), std::round(my + l2 * std::sin(a2)), 0, 1 + 3 * u(rng)};
    const double cx = 2 * u(rng) - 1, cy = 2 * u(rng) - 1;
    const RationalBox3 cell = exact_box({{cx, cy, 0}, {cx + 1, cy + 1, 1 + u(rng)}});
    const UmbraTarget t = square_at(mx + 10 * u(rng) - 2, my + 10 * u(rng) - 5, 0.5 * u(rng), 0, 3 * u(rng));
    if (!wall_pair_hides_exactly(w1, w2, cell, t)) continue;
    ++proofs;
    single += wall_hides_exactly(w1, cell, t) || wall_hides_exactly(w2, cell, t);
    for (int s = 0; s < 200; ++s) {
      std::array<mpq_class, 3> p, q;
      for (int k = 0; k < 3; ++k) p[k] = mpq_class(cell.lo[k].mpq()) + mpq_class(u(rng)) * mpq_class((cell.hi[k] - cell.lo[k]).mpq());
      // A random convex combination of the target's points, a random height in its range.
      double w[4], total = 0;
      for (double& x : w) total += (x = u(rng));
      q = {0, 0, mpq_class(t.z_lo) + mpq_class(u(rng)) * (mpq_class(t.z_hi) - mpq_class(t.z_lo))};
      for (int j = 0; j < 4; ++j) {
        q[0] += mpq_class(w[j] / total) * mpq_class(t.points[j].x);
        q[1] += mpq_class(w[j] / total) * mpq_class(t.points[j].y);
      }
      // (w[j] / total rounded: the weights still sum to about 1; pull q into the hull by renormalising.)
      mpq_class sum = 0;
      for (int j = 0; j < 4; ++j) sum += mpq_class(w[j] / total);
      q[0] /= sum, q[1] /= sum;
      ASSERT_TRUE(segment_meets_wall(p, q, w1) || segment_meets_wall(p, q, w2)) << "trial " << trial;
    }
  }
  EXPECT_GE(proofs, 30);
  EXPECT_LT(single, proofs) << "every proof was a one-wall proof: fusion untested";
}
