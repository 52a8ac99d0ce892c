// The 2.5D rule and wall rectangles (region/extruded_scene.hpp): generated towns are 2.5D, forests and
// sloped or half-covered walls are not; the rectangles are exactly the closed unions of paired triangles,
// merged along lines and stacked into maximal runs (checked against hand-computed answers).
#include "region/extruded_scene.hpp"

#include "kernel/scene_generators.hpp"
#include "tests/region/pvs_test_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace exactvis;
using namespace exactvis::region;

namespace {

bool has_wall(const ExtrudedScene& e, WallRectangle w) {
  return std::any_of(e.walls.begin(), e.walls.end(), [&](const WallRectangle& r) {
    return r.ax == w.ax && r.ay == w.ay && r.bx == w.bx && r.by == w.by && r.z_lo == w.z_lo && r.z_hi == w.z_hi;
  });
}

}  // namespace

TEST(ExtrudedScene, GeneratedTownsAre25dForestsAreNot) {
  for (std::uint64_t seed : {1, 2, 3}) {
    const Scene town = generate_scene("town", 400, seed);
    const ExtrudedScene e = detect_extruded_scene(town);
    EXPECT_TRUE(e.is_25d) << e.reason;
    EXPECT_EQ(e.horizontal + e.wall_triangles, static_cast<std::int64_t>(town.triangles.size()));
    EXPECT_FALSE(e.walls.empty());
  }
  const ExtrudedScene f = detect_extruded_scene(generate_scene("forest", 400, 1));
  EXPECT_FALSE(f.is_25d);
  EXPECT_NE(f.reason.find("sloped"), std::string::npos) << f.reason;
  EXPECT_FALSE(f.walls.empty());  // the trunks' sides are wall rectangles even so
}

TEST(ExtrudedScene, PairsMergesAndStacks) {
  pvs_test::SceneBuilder b;
  // A wall on y = 0 made of a 3 x 2 grid of unit rectangles with the middle top one missing (a window):
  // x in [0,3], z in [0,2].
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j)
      if (!(i == 1 && j == 1)) b.rect(1, 0, static_cast<double>(j), j + 1.0, static_cast<double>(i), i + 1.0);
  b.rect(2, 0, -5, 5, -5, 5);  // ground (horizontal)
  const ExtrudedScene e = detect_extruded_scene(b.scene);
  EXPECT_TRUE(e.is_25d) << e.reason;
  EXPECT_EQ(e.wall_triangles, 10);
  EXPECT_TRUE(has_wall(e, {0, 0, 3, 0, 0, 1}));  // the bottom row, merged along the line
  EXPECT_TRUE(has_wall(e, {0, 0, 1, 0, 0, 2}));  // the left column, stacked
  EXPECT_TRUE(has_wall(e, {2, 0, 3, 0, 0, 2}));  // the right column
  EXPECT_FALSE(has_wall(e, {0, 0, 3, 0, 0, 2})); // never across the window
  EXPECT_FALSE(has_wall(e, {0, 0, 1, 0, 0, 1})); // absorbed by its runs
  for (const auto& w : e.walls) EXPECT_FALSE(w.ax == 1 && w.bx == 2 && w.z_hi == 2) << "a wall over the window";
}

TEST(ExtrudedScene, HalfCoveredAndSlopedWallsBreakTheRule) {
  {  // two triangles of one rectangle missing adjacent corners: they overlap and leave a hole
    pvs_test::SceneBuilder b;
    b.triangle({0, 0, 0}, {1, 0, 0}, {1, 0, 1});  // misses (0, 1)
    b.triangle({0, 0, 0}, {1, 0, 0}, {0, 0, 1});  // misses (1, 1)
    const ExtrudedScene e = detect_extruded_scene(b.scene);
    EXPECT_FALSE(e.is_25d);
    EXPECT_TRUE(e.walls.empty());
  }
  {  // a vertical triangle that is not half of a rectangle (a gable)
    pvs_test::SceneBuilder b;
    b.triangle({0, 0, 0}, {2, 0, 0}, {1, 0, 1});
    EXPECT_FALSE(detect_extruded_scene(b.scene).is_25d);
  }
  {  // a wall tilted by one ulp in x is sloped
    pvs_test::SceneBuilder b;
    b.quad({0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {std::nextafter(0.0, 1.0), 0, 1});
    const ExtrudedScene e = detect_extruded_scene(b.scene);
    EXPECT_FALSE(e.is_25d);
  }
  {  // one quad, either diagonal: one wall
    pvs_test::SceneBuilder b;
    b.quad({0, 0, 0}, {1, 1, 0}, {1, 1, 2}, {0, 0, 2});
    b.quad({3, 3, 0}, {3, 3, 2}, {2, 2, 2}, {2, 2, 0});
    const ExtrudedScene e = detect_extruded_scene(b.scene);
    EXPECT_TRUE(e.is_25d) << e.reason;
    EXPECT_TRUE(has_wall(e, {0, 0, 1, 1, 0, 2}));
    EXPECT_TRUE(has_wall(e, {2, 2, 3, 3, 0, 2}));
    EXPECT_FALSE(has_wall(e, {0, 0, 3, 3, 0, 2}));  // a gap between them: no merge
  }
}
