// Grids of view cells (region/view_cell_grid.hpp): exact corners, x fastest, neighbours sharing faces
// exactly, the union equal to the box, and refused flat boxes and counts.
#include "region/view_cell_grid.hpp"

#include <gtest/gtest.h>

using namespace exactvis;
using namespace exactvis::region;

TEST(ViewCellGrid, ExactCellsInOrderCoveringTheBox) {
  const RationalBox3 box{{Exact(0), Exact(-1), Exact(1, 3)}, {Exact(1), Exact(2), Exact(5, 7)}};
  const std::vector<RationalBox3> cells = grid_cells(box, {3, 2, 5});
  ASSERT_EQ(cells.size(), 30u);
  EXPECT_TRUE(cells[0].lo == box.lo);
  EXPECT_TRUE(cells[29].hi == box.hi);
  EXPECT_TRUE(cells[1].lo.x == Exact(1, 3));    // x fastest
  EXPECT_TRUE(cells[3].lo.y == Exact(1, 2));    // then y
  EXPECT_TRUE(cells[6].lo.z == Exact(1, 3) + (Exact(5, 7) - Exact(1, 3)) / 5);
  Exact volume(0);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const auto& b = cells[c];
    volume += (b.hi.x - b.lo.x) * (b.hi.y - b.lo.y) * (b.hi.z - b.lo.z);
    if (c % 3 != 2) {
      EXPECT_TRUE(cells[c + 1].lo.x == b.hi.x);  // shared face, exactly
    }
  }
  EXPECT_TRUE(volume == (box.hi.x - box.lo.x) * (box.hi.y - box.lo.y) * (box.hi.z - box.lo.z));
}

TEST(ViewCellGrid, RefusesFlatBoxesAndBadCounts) {
  const RationalBox3 flat{{Exact(0), Exact(0), Exact(0)}, {Exact(1), Exact(1), Exact(0)}};
  EXPECT_THROW(grid_cells(flat, {1, 1, 1}), std::invalid_argument);
  const RationalBox3 ok{{Exact(0), Exact(0), Exact(0)}, {Exact(1), Exact(1), Exact(1)}};
  EXPECT_THROW(grid_cells(ok, {0, 1, 1}), std::invalid_argument);
  EXPECT_EQ(grid_cells(ok, {1, 1, 1}).size(), 1u);
}
