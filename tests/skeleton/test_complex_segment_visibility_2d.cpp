// Segment-to-segment visibility answered from the complex, against the O(n^4) cell sampling of
// segment_visibility (a different algorithm: it cuts S at every line through two vertices and tests segments
// exactly, without the complex) and the independent GMP oracle for every witness. Adversarial family: two
// walls with small offset gaps ("double keyholes"), where S sees T only through a thin bundle of lines
// bounded by lines through two corners of different walls (strict pairs of the visibility graph): a breakpoint
// set without those lines finds no witness there.
#include "tests/planar/scene2d_test_util.hpp"
#include "skeleton/complex_segment_visibility_2d.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::test2d;

namespace {

oracle2d::Ring box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// Oracle check of a witness: its ends on S and T, its open segment free.
void expect_witness(const std::vector<oracle2d::Polygon>& polys, const SegmentVisibility2D& r, const Point2& s0,
                    const Point2& s1, const Point2& t0, const Point2& t1) {
  auto on = [](const oracle2d::Pt& a, const oracle2d::Pt& b, const oracle2d::Pt& p) {
    const mpq_class cr = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    const mpq_class dt = (p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y);
    const mpq_class l2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
    return cr == 0 && dt >= 0 && dt <= l2;
  };
  const auto ws = to_pt(r.witness_s), wt = to_pt(r.witness_t);
  EXPECT_TRUE(on(to_pt(s0), to_pt(s1), ws));
  EXPECT_TRUE(on(to_pt(t0), to_pt(t1), wt));
  EXPECT_TRUE(oracle2d::open_segment_free(polys, ws, wt));
}

// Compares with segment_visibility and checks witnesses; returns the number of visible answers.
int compare(const std::vector<oracle2d::Polygon>& polys, const Scene2D& s, const ComplexWalkIndex2D& ix,
            const Point2& a, const Point2& b, const Point2& c, const Point2& d, const std::string& where) {
  const SegmentVisibility2D ref = segment_visibility(s, a, b, c, d);
  const SegmentVisibility2D got = segment_visibility_in_complex(ix, a, b, c, d);
  EXPECT_EQ(ref.visible, got.visible) << where;
  if (got.visible) expect_witness(polys, got, a, b, c, d);
  return got.visible ? 1 : 0;
}

}  // namespace

TEST(ComplexSegmentVisibility2D, DoubleKeyholeNeedsStrictPairLines) {
  // walls x in [0,1] and [10,11] with gaps y in (0,1) and (5,6); S at x = -10, T at x = 21
  const std::vector<oracle2d::Polygon> polys{{{box(0, -100, 1, 0)}}, {{box(0, 1, 1, 100)}},
                                             {{box(10, -100, 11, 5)}}, {{box(10, 6, 11, 100)}}};
  const Scene2D s = make_scene2d(to_input(polys));
  const VisibilityComplex2D cx = visibility_complex(s);
  const ComplexWalkIndex2D ix = complex_walk_index(s, cx);
  const Point2 s0(-10.0, -20.0), s1(-10.0, 20.0), t0(21.0, -20.0), t1(21.0, 30.0);
  ComplexSegmentStats2D st;
  const auto r = segment_visibility_in_complex(ix, s0, s1, t0, t1, &st);
  ASSERT_TRUE(r.visible);
  expect_witness(polys, r, s0, s1, t0, t1);
  EXPECT_GE(st.walks, 1u);
  // the witness passes both gaps
  EXPECT_TRUE(segment_visibility(s, s0, s1, t0, t1).visible);
  // S moved above the bundle: hidden (both algorithms)
  EXPECT_FALSE(segment_visibility_in_complex(ix, Point2(-10.0, 10.0), Point2(-10.0, 20.0), t0, t1).visible);
  EXPECT_FALSE(segment_visibility(s, Point2(-10.0, 10.0), Point2(-10.0, 20.0), t0, t1).visible);
}

TEST(ComplexSegmentVisibility2D, RandomDoubleKeyholes) {
  std::mt19937_64 rng(5);
  int visible = 0, total = 0;
  for (int k = 0; k < 40; ++k) {
    std::uniform_int_distribution<int> g(-6, 6);
    const int y1 = g(rng), y2 = g(rng) + (k % 3 == 0 ? 0 : 3);
    const double w = k % 2 ? 1.0 : 0.25;  // gap width
    const std::vector<oracle2d::Polygon> polys{{{box(0, -30, 1, y1)}}, {{box(0, y1 + w, 1, 30)}},
                                               {{box(10, -30, 11, y2)}}, {{box(10, y2 + w, 11, 30)}}};
    const Scene2D s = make_scene2d(to_input(polys));
    const VisibilityComplex2D cx = visibility_complex(s);
    const ComplexWalkIndex2D ix = complex_walk_index(s, cx);
    std::uniform_real_distribution<double> u(-25, 25);
    for (int j = 0; j < 6; ++j) {
      const double a = u(rng), b = u(rng), c = u(rng), d = u(rng);
      const double xs = -3 - 10 * (j % 2), xt = 14 + 10 * (j % 3 == 0);
      visible += compare(polys, s, ix, Point2(xs, std::min(a, b) - 0.5), Point2(xs, std::max(a, b) + 0.5),
                         Point2(xt, std::min(c, d) - 0.5), Point2(xt + (j % 2), std::max(c, d) + 0.5),
                         "keyhole " + std::to_string(k) + "/" + std::to_string(j));
      ++total;
    }
  }
  EXPECT_GT(visible, 0);
  EXPECT_LT(visible, total);
}

TEST(ComplexSegmentVisibility2D, RandomGridScenesAgreeWithCellSampling) {
  int visible = 0, total = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto polys = oracle2d::random_grid_scene(seed, 2 + seed % 3, seed % 2);
    const auto s = try_scene(polys);
    if (!s) continue;
    const VisibilityComplex2D cx = visibility_complex(*s);
    const ComplexWalkIndex2D ix = complex_walk_index(*s, cx);
    std::mt19937_64 rng(seed);
    const double hi = 10.0 * (2 + seed % 3);
    auto rnd = [&] {
      const double x = std::uniform_real_distribution<double>(-2, hi + 2)(rng);
      return seed % 3 == 0 ? std::round(2 * x) / 2 : x;  // half-integers: collinear with many vertices
    };
    for (int k = 0; k < 20; ++k) {
      const double ax = rnd(), ay = rnd(), cx2 = rnd(), cy2 = rnd();
      const Point2 a(ax, ay), b(ax + 1.5, ay + 0.5), c(cx2, cy2), d(cx2 + 0.5, cy2 - 1.5);
      if (!open_segment_free(*s, a, b) || !open_segment_free(*s, c, d) || inside_obstacle(*s, a) ||
          inside_obstacle(*s, c))
        continue;
      visible += compare(polys, *s, ix, a, b, c, d, "seed " + std::to_string(seed) + " k " + std::to_string(k));
      ++total;
    }
  }
  EXPECT_GT(visible, 0);
  EXPECT_LT(visible, total);
}

TEST(ComplexSegmentVisibility2D, CrossingAndTouchingSegmentsAndBadInput) {
  const std::vector<oracle2d::Polygon> polys{{{box(4, -10, 5, 10)}}};
  const Scene2D s = make_scene2d(to_input(polys));
  const VisibilityComplex2D cx = visibility_complex(s);
  const ComplexWalkIndex2D ix = complex_walk_index(s, cx);
  // S and T cross: visible (a short segment near the crossing)
  compare(polys, s, ix, Point2(0.0, 0.0), Point2(2.0, 2.0), Point2(0.0, 2.0), Point2(2.0, 0.0), "crossing");
  // T through an endpoint of S, collinear overlap
  compare(polys, s, ix, Point2(0.0, 0.0), Point2(2.0, 0.0), Point2(1.0, 0.0), Point2(3.0, 0.0), "overlap");
  // far outside the scene's frame: the frame is widened
  compare(polys, s, ix, Point2(-100.0, 50.0), Point2(-90.0, 50.0), Point2(100.0, 50.0), Point2(90.0, 60.0), "far");
  EXPECT_THROW(segment_visibility_in_complex(ix, Point2(0.0, 0.0), Point2(0.0, 0.0), Point2(9.0, 0.0), Point2(9.0, 1.0)),
               std::invalid_argument);
  EXPECT_THROW(segment_visibility_in_complex(ix, Point2(0.0, 0.0), Point2(6.0, 0.0), Point2(9.0, 0.0), Point2(9.0, 1.0)),
               std::invalid_argument);
  EXPECT_THROW(segment_visibility_in_complex(ix, Point2(0.0, 0.0), Point2(1.0, 0.0), Point2(4.5, 0.0), Point2(4.6, 1.0)),
               std::invalid_argument);
}
