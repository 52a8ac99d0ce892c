// Segment-to-segment visibility: witnesses re-checked by the oracle; "not visible" answers attacked by
// random sampling of connecting segments; hand-made narrow gaps and walls.
#include "tests/planar/scene2d_test_util.hpp"
#include "skeleton/segment_visibility_2d.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::test2d;

namespace {
oracle2d::Ring box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }
}  // namespace

TEST(SegmentVisibility2D, WallBlocksAndGapLetsThrough) {
  // a wall x in [4,5], y in [-10, 10]; S left of it, T right of it
  const std::vector<oracle2d::Polygon> wall{{{box(4, -10, 5, 10)}}};
  const Scene2D s = make_scene2d(to_input(wall));
  EXPECT_FALSE(segment_visibility(s, Point2(0.0, -1.0), Point2(0.0, 1.0), Point2(9.0, -1.0), Point2(9.0, 1.0)).visible);
  // around the wall's end: T reaches beyond y = 10
  const auto r = segment_visibility(s, Point2(0.0, 9.0), Point2(0.0, 11.0), Point2(9.0, 9.0), Point2(9.0, 11.0));
  ASSERT_TRUE(r.visible);
  EXPECT_TRUE(oracle2d::open_segment_free(wall, to_pt(r.witness_s), to_pt(r.witness_t)));
  // a wall with a narrow slit (width 2^-20): still visible, with an exact witness through the slit
  const double h = std::ldexp(1.0, -20);
  const std::vector<oracle2d::Polygon> slit{{{box(4, -10, 5, 0)}}, {{box(4, h, 5, 10)}}};
  const Scene2D s2 = make_scene2d(to_input(slit));
  const auto r2 = segment_visibility(s2, Point2(0.0, -1.0), Point2(0.0, 1.0), Point2(9.0, -1.0), Point2(9.0, 1.0));
  ASSERT_TRUE(r2.visible);
  EXPECT_TRUE(oracle2d::open_segment_free(slit, to_pt(r2.witness_s), to_pt(r2.witness_t)));
}

TEST(SegmentVisibility2D, RandomScenesWitnessesAndRefutations) {
  std::mt19937_64 rng(11);
  int visible = 0, hidden = 0, scenes = 0;
  for (std::uint64_t seed = 3000; scenes < 6 && seed < 3300; ++seed) {
    const auto polys = oracle2d::random_grid_scene(seed, 2);
    const auto s = try_scene(polys);
    if (!s) continue;
    ++scenes;
    std::uniform_real_distribution<double> u(-2, 22);
    int pairs = 0;
    while (pairs < 25) {
      const Point2 a(u(rng), u(rng)), b(u(rng), u(rng)), c(u(rng), u(rng)), d(u(rng), u(rng));
      if (!open_segment_free(*s, a, b) || !open_segment_free(*s, c, d) || inside_obstacle(*s, a) || inside_obstacle(*s, c))
        continue;
      ++pairs;
      const auto r = segment_visibility(*s, a, b, c, d);
      if (r.visible) {
        ++visible;
        EXPECT_TRUE(oracle2d::open_segment_free(polys, to_pt(r.witness_s), to_pt(r.witness_t)));
      } else {
        ++hidden;
        // try to refute: 400 random connecting segments must all be blocked
        std::uniform_real_distribution<double> w(0, 1);
        for (int k = 0; k < 400; ++k) {
          const mpq_class x(w(rng)), y(w(rng));
          const oracle2d::Pt p{to_pt(a).x + x * (to_pt(b).x - to_pt(a).x), to_pt(a).y + x * (to_pt(b).y - to_pt(a).y)};
          const oracle2d::Pt q{to_pt(c).x + y * (to_pt(d).x - to_pt(c).x), to_pt(c).y + y * (to_pt(d).y - to_pt(c).y)};
          ASSERT_FALSE(oracle2d::open_segment_free(polys, p, q)) << "missed witness, seed " << seed;
        }
      }
    }
  }
  EXPECT_GE(visible, 20);
  EXPECT_GE(hidden, 5);
}

TEST(SegmentVisibility2D, RejectsBadSegments) {
  const Scene2D s = make_scene2d(to_input({{{box(0, 0, 1, 1)}}}));
  EXPECT_THROW(segment_visibility(s, Point2(-1.0, 0.5), Point2(2.0, 0.5), Point2(5.0, 0.0), Point2(5.0, 1.0)),
               std::invalid_argument);  // S crosses the object
  EXPECT_THROW(segment_visibility(s, Point2(0.2, 0.5), Point2(0.8, 0.5), Point2(5.0, 0.0), Point2(5.0, 1.0)),
               std::invalid_argument);  // S inside the object
  EXPECT_THROW(segment_visibility(s, Point2(3.0, 3.0), Point2(3.0, 3.0), Point2(5.0, 0.0), Point2(5.0, 1.0)),
               std::invalid_argument);  // zero length
}
