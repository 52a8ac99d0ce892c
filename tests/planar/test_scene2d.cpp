// Validation of 2D scenes: every invalid input is rejected with a clear error.
#include "tests/planar/scene2d_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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

// The viewpoint frame has double corners (docs/theory.md, section 7, "Coordinate range"): refused when a
// corner would lie beyond the largest double or the margin is not a finite number >= 0, never an infinite
// corner (which crashed the exact constructions: SIGFPE).
TEST(Scene2D, FrameBeyondTheDoubleRangeIsRefused) {
  const Scene2D s = make_scene2d({{{{Point2(0.0, 0.0), Point2(1.7e308, 0.0), Point2(0.0, 1.0)}}}});
  EXPECT_FALSE(frame_box(s, 0.25).representable);
  EXPECT_THROW(with_frame(s, 0.25), Scene2DError);
  // margin 0: the frame is the box widened by 1 (at least one double) and fits
  ASSERT_TRUE(frame_box(s, 0.0).representable);
  const Scene2D f = with_frame(s, 0.0);
  for (int v = 0; v < s.num_vertices(); ++v) EXPECT_TRUE(frame_contains(f, s.points[v]));
  const Scene2D unit = make_scene2d({{{{Point2(0.0, 0.0), Point2(1.0, 0.0), Point2(0.0, 1.0)}}}});
  for (double m : {std::numeric_limits<double>::infinity(), std::nan(""), -1.0}) {
    EXPECT_FALSE(frame_box(unit, m).representable) << m;
    EXPECT_THROW(with_frame(unit, m), Scene2DError) << m;
  }
  EXPECT_TRUE(frame_box(unit, 1e300).representable);
  // A scene spanning more than the largest double: the frame is computed from half sides, and refused
  // only when the margin really pushes a corner out.
  const Scene2D wide = make_scene2d({{{{Point2(-1.5e308, 0.0), Point2(1.5e308, 0.0), Point2(0.0, 1.0)}}}});
  EXPECT_TRUE(frame_box(wide, 0.01).representable);
  EXPECT_FALSE(frame_box(wide, 0.25).representable);
}

// Huge coordinates with a small extent: lo - 1 rounds back to lo, so the corner moves to the next double
// (the frame must contain every vertex strictly).
TEST(Scene2D, FrameContainsHugeNarrowScenesStrictly) {
  const double b = 1e20;
  const Scene2D s = make_scene2d({{{{Point2(b, b), Point2(b + 16384, b), Point2(b, b + 16384)}}}});
  const Scene2D f = with_frame(s, 0.25);
  for (int v = 0; v < s.num_vertices(); ++v) EXPECT_TRUE(frame_contains(f, s.points[v])) << v;
}

// with_frame_around widens the margin until the points are inside, without a fixed number of steps; a point
// beyond every representable frame gives a frame that does not contain it (the caller reports it).
TEST(Scene2D, FrameWidensForFarPoints) {
  const Scene2D s = make_scene2d({{{{Point2(0.0, 0.0), Point2(1.0, 0.0), Point2(0.0, 1.0)}}}});
  for (double x : {1e30, 1e300, -1.7e308}) {
    const Point2 p(x, 3.0);
    EXPECT_TRUE(frame_contains(with_frame_around(s, {p}, 0.5), p)) << x;
  }
  const Point2 beyond(Exact(1e308) * Exact(10), Exact(3));
  EXPECT_FALSE(frame_contains(with_frame_around(s, {beyond}, 0.5), beyond));
}
