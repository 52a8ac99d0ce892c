// Validation of 2D scenes: every invalid input is rejected with a clear error.
#include "tests/planar/scene2d_test_util.hpp"

#include <gtest/gtest.h>

using namespace exactvis;
using namespace exactvis::test2d;

namespace {
oracle2d::Ring box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

std::string error_of(const std::vector<oracle2d::Polygon>& polys) {
  try {
    make_scene2d(to_input(polys));
  } catch (const Scene2DError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Scene2D, RingsAreOrientedWithTheObjectOnTheLeft) {
  // clockwise outer input, counterclockwise hole input
  const std::vector<oracle2d::Polygon> polys{{{{{0, 0}, {0, 10}, {10, 10}, {10, 0}}, box(2, 2, 8, 8)}}};
  const Scene2D s = make_scene2d(to_input(polys));
  for (int v = 0; v < s.num_vertices(); ++v) {
    // the centre of the hole lies left of the (counterclockwise) outer ring, right of the (clockwise) hole
    const Sign o = orientation2(s.points[v], s.points[s.next[v]], Point2(5.0, 5.0));
    EXPECT_EQ(o, s.rings[s.ring_of[v]].hole ? Sign::Negative : Sign::Positive) << "vertex " << v;
  }
  EXPECT_TRUE(inside_obstacle(s, Point2(1.0, 1.0)));
  EXPECT_FALSE(inside_obstacle(s, Point2(5.0, 5.0)));
  EXPECT_FALSE(inside_obstacle(s, Point2(11.0, 5.0)));
}

TEST(Scene2D, RejectsInvalidScenes) {
  EXPECT_NE(error_of({{{box(0, 0, 2, 2)}}, {{box(1, 1, 3, 3)}}}), "");                  // overlapping
  EXPECT_NE(error_of({{{box(0, 0, 4, 4)}}, {{box(1, 1, 2, 2)}}}), "");                  // nested, not a hole
  EXPECT_NE(error_of({{{box(0, 0, 1, 1)}}, {{box(1, 0, 2, 1)}}}), "");                  // shared edge
  EXPECT_NE(error_of({{{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}}}), "");                      // bow tie
  EXPECT_NE(error_of({{{{{0, 0}, {1, 0}, {1, 0}, {0, 1}}}}}), "");                      // duplicate vertex
  EXPECT_NE(error_of({{{{{0, 0}, {1, 0}, {2, 0}}}}}), "");                              // zero area
  EXPECT_NE(error_of({{{{{0, 0}, {1, 0}}}}}), "");                                      // too few
  EXPECT_NE(error_of({{{box(0, 0, 4, 4), box(5, 5, 6, 6)}}}), "");                      // hole outside
  EXPECT_NE(error_of({{{box(0, 0, 9, 9), box(1, 1, 8, 8), box(2, 2, 3, 3)}}}), "");     // nested holes
  EXPECT_NE(error_of({{{{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}}}}), "");              // touches itself
  EXPECT_NE(error_of({{{{{0, 0}, {4, 0}, {2, 0}, {2, 3}}}}}), "");                      // folds back
  EXPECT_EQ(error_of({{{box(0, 0, 9, 9), box(1, 1, 8, 8)}}, {{box(2, 2, 3, 3)}}}), ""); // island in a hole
  EXPECT_EQ(error_of({{{{{0, 0}, {1, 0}, {2, 0}, {2, 2}}}}}), "");                      // flat vertex is fine
}
