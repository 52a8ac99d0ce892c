// The one-wall occlusion proof (region/wall_umbra.hpp) on hand-computed cases: the horizontal condition
// (footprint inside the wall's 2D umbra, strict sides) and the vertical one (the crossing height bound,
// closed at exactly the wall's top), and the double proposal never accepting what the exact test refuses.
#include "region/wall_umbra.hpp"

#include <gtest/gtest.h>

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
