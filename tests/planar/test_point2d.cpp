// The planar predicates and the line intersection of planar/point2d against GMP rationals computed here:
// on double coordinates (the kernel's semi-static filters decide most calls) and on rational ones (the
// BoundedDouble layer on enclosures), at many scales, with equal coordinates, collinear and nearly
// collinear points. Also: a Point2's enclosures are CGAL::to_interval's.
#include "planar/point2d.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace exactvis;

namespace {

mpq_class qx(const Point2& p) { return mpq_class(p.x.mpq()); }
mpq_class qy(const Point2& p) { return mpq_class(p.y.mpq()); }

int cross_oracle(const Point2& u0, const Point2& u1, const Point2& v0, const Point2& v1) {
  return sgn((qx(u1) - qx(u0)) * (qy(v1) - qy(v0)) - (qy(u1) - qy(u0)) * (qx(v1) - qx(v0)));
}
int dot_oracle(const Point2& u0, const Point2& u1, const Point2& v0, const Point2& v1) {
  return sgn((qx(u1) - qx(u0)) * (qx(v1) - qx(v0)) + (qy(u1) - qy(u0)) * (qy(v1) - qy(v0)));
}

struct Gen {
  std::mt19937_64 rng;
  explicit Gen(std::uint64_t s) : rng(s) {}
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  double uniform() { return std::uniform_real_distribution<double>(-1, 1)(rng); }
  // Four points of one case: doubles at one scale, small integers, thirds (no doubles), with shared
  // coordinates and (nearly) collinear triples.
  std::array<Point2, 4> points() {
    const int kind = integer(0, 3);
    const double s = std::ldexp(1.0, integer(-600, 600));
    auto fresh = [&]() -> Point2 {
      switch (kind) {
        case 0: return Point2(uniform() * s, uniform() * s);
        case 1: return Point2(double(integer(-4, 4)), double(integer(-4, 4)));
        case 2: return Point2(Exact(integer(-30, 30), 3), Exact(integer(-30, 30), 7));
        default: return Point2(uniform(), uniform());
      }
    };
    std::array<Point2, 4> p{fresh(), fresh(), fresh(), fresh()};
    switch (integer(0, 3)) {
      case 0: p[2] = Point2(p[0].x, p[1].y); break;  // shared coordinates
      case 1:                                         // on the line through p0, p1 (exact), or rounded
        p[2] = kind == 2 ? Point2(p[0].x + (p[1].x - p[0].x) * 2, p[0].y + (p[1].y - p[0].y) * 2)
                         : Point2(p[0].ax + 0.5 * (p[1].ax - p[0].ax), p[0].ay + 0.5 * (p[1].ay - p[0].ay));
        break;
      case 2: p[3] = p[1]; break;  // repeated point
      default: break;
    }
    return p;
  }
};

TEST(Point2D, PredicatesMatchRationals) {
  Gen g(71);
  int zeros = 0;
  for (int i = 0; i < 20000; ++i) {
    const auto p = g.points();
    const int c = cross_oracle(p[0], p[1], p[2], p[3]);
    zeros += c == 0;
    ASSERT_EQ(to_int(cross_sign(p[0], p[1], p[2], p[3])), c) << "case " << i;
    ASSERT_EQ(to_int(orientation2(p[0], p[1], p[2])), cross_oracle(p[0], p[1], p[0], p[2])) << "case " << i;
    ASSERT_EQ(to_int(dot_sign(p[0], p[1], p[2], p[3])), dot_oracle(p[0], p[1], p[2], p[3])) << "case " << i;
    ASSERT_EQ(to_int(dx_sign(p[0], p[2])), sgn(qx(p[2]) - qx(p[0]))) << "case " << i;
    ASSERT_EQ(to_int(dy_sign(p[1], p[2])), sgn(qy(p[2]) - qy(p[1]))) << "case " << i;
  }
  EXPECT_GT(zeros, 200);  // degenerate cases occur
}

TEST(Point2D, LineIntersectionIsExact) {
  // The intersection point lies on both lines (exact rational check), for double and rational inputs.
  Gen g(72);
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    const auto p = g.points();
    const Point2 c = g.points()[0];
    if (cross_oracle(p[0], p[1], p[2], p[3]) == 0) continue;  // parallel: no intersection
    const Point2 x = line_intersection(c, p[0], p[1], p[2], p[3]);
    // x - c parallel to p1 - p0, and x on the line through p2, p3
    ASSERT_EQ(sgn((qx(x) - qx(c)) * (qy(p[1]) - qy(p[0])) - (qy(x) - qy(c)) * (qx(p[1]) - qx(p[0]))), 0) << i;
    ASSERT_EQ(sgn((qx(p[3]) - qx(p[2])) * (qy(x) - qy(p[2])) - (qy(p[3]) - qy(p[2])) * (qx(x) - qx(p[2]))), 0) << i;
    ++checked;
  }
  EXPECT_GT(checked, 1500);
}

TEST(Point2D, EnclosuresAreTheTightestIntervals) {
  Gen g(73);
  for (int i = 0; i < 2000; ++i) {
    const auto p = g.points();
    for (const Point2& q : p) {
      const auto ix = CGAL::to_interval(q.x), iy = CGAL::to_interval(q.y);
      ASSERT_EQ(q.ix.inf(), ix.first);
      ASSERT_EQ(q.ix.sup(), ix.second);
      ASSERT_EQ(q.iy.inf(), iy.first);
      ASSERT_EQ(q.iy.sup(), iy.second);
    }
  }
}

}  // namespace
