// kernel/line_plane_intersection: the exact point is checked on the plane (oracle 4x4 determinant) and on
// the line (oracle cross product), the kinds against oracle incidence tests.
#include "kernel/line_plane_intersection.hpp"
#include "kernel/segment_triangle_intersection.hpp"
#include "kernel_test_inputs.hpp"

#include <gtest/gtest.h>

namespace exactvis {
namespace {

using test::PointGenerator;
using test::to_oracle;

TEST(LinePlaneIntersection, HandPickedCases) {
  const Point3 t0{0, 0, 0}, t1{1, 0, 0}, t2{0, 1, 0};
  auto r = line_plane_intersection(Point3{0.25, 0.5, -1}, Point3{0.25, 0.5, 3}, t0, t1, t2);
  ASSERT_EQ(r.kind, LinePlaneKind::Point);
  EXPECT_EQ(r.t, Exact(1) / Exact(4));
  EXPECT_EQ(r.point, (RationalPoint3{Exact(0.25), Exact(0.5), Exact(0)}));
  EXPECT_EQ(line_plane_intersection(Point3{0, 0, 1}, Point3{1, 0, 1}, t0, t1, t2).kind, LinePlaneKind::Parallel);
  EXPECT_EQ(line_plane_intersection(Point3{0, 0, 0}, Point3{1, 1, 0}, t0, t1, t2).kind, LinePlaneKind::Contained);
  EXPECT_EQ(line_plane_intersection(Point3{0, 0, 0}, Point3{0, 0, 0}, t0, t1, t2).kind,
            LinePlaneKind::DegenerateInput);
  EXPECT_EQ(line_plane_intersection(Point3{0, 0, 0}, Point3{0, 0, 1}, t0, t1, Point3{2, 0, 0}).kind,
            LinePlaneKind::DegenerateInput);
  // The intersection of a line with 1/3 slopes is not a double: exactness matters.
  r = line_plane_intersection(Point3{0, 0, -1}, Point3{1, 1, 2}, t0, t1, t2);
  ASSERT_EQ(r.kind, LinePlaneKind::Point);
  EXPECT_EQ(r.point.x, Exact(1) / Exact(3));
}

TEST(LinePlaneIntersection, MatchesOracle) {
  PointGenerator gen(31);
  int kinds[4] = {0, 0, 0, 0};
  for (int i = 0; i < 20000; ++i) {
    gen.start_case();
    const Point3 t0 = gen.next(), t1 = gen.next(), t2 = gen.next(), p = gen.next(), q = gen.next();
    const std::string where = std::string(test::family_name(gen.family)) + " case " + std::to_string(i);
    const auto o0 = to_oracle(t0), o1 = to_oracle(t1), o2 = to_oracle(t2), op = to_oracle(p), oq = to_oracle(q);
    const auto r = line_plane_intersection(p, q, t0, t1, t2);
    kinds[static_cast<int>(r.kind)]++;
    const bool degenerate_plane = oracle::is_zero(oracle::cross(o1 - o0, o2 - o0));
    if (degenerate_plane || op == oq) {
      ASSERT_EQ(r.kind, LinePlaneKind::DegenerateInput) << where;
      continue;
    }
    const int sp = oracle::orient3d(o0, o1, o2, op), sq = oracle::orient3d(o0, o1, o2, oq);
    if (sp == 0 && sq == 0) {
      ASSERT_EQ(r.kind, LinePlaneKind::Contained) << where;
    } else if (sp == sq) {
      // Both strictly on one side: parallel iff equal heights, which the oracle checks by a translated point.
      const bool parallel = oracle::orient3d(o0, o1, o2, o0 + (oq - op)) == 0;
      ASSERT_EQ(r.kind, parallel ? LinePlaneKind::Parallel : LinePlaneKind::Point) << where;
    } else {
      ASSERT_EQ(r.kind, LinePlaneKind::Point) << where;
    }
    if (r.kind != LinePlaneKind::Point) continue;
    const oracle::QVec x = test::to_oracle(r.point);
    ASSERT_EQ(oracle::orient3d(o0, o1, o2, x), 0) << where;                          // on the plane
    ASSERT_TRUE(oracle::is_zero(oracle::cross(oq - op, x - op))) << where;          // on the line
    ASSERT_TRUE(x == op + test::to_mpq(r.t) * (oq - op)) << where;                 // its parameter
    // On [p,q] and in the closed triangle iff the segment meets the triangle (non-coplanar case).
    const bool in_seg = r.t >= 0 && r.t <= 1;
    ASSERT_EQ(in_seg && oracle::oracle_point_in_closed_triangle(x, o0, o1, o2),
              segment_meets_closed_triangle(p, q, t0, t1, t2))
        << where;
    // The Plücker form gives the same point.
    const auto rl = line_plane_intersection(line_through(to_rational(p), to_rational(q)), to_rational(t0),
                                            to_rational(t1), to_rational(t2));
    ASSERT_EQ(rl.kind, LinePlaneKind::Point);
    ASSERT_EQ(rl.point, r.point) << where;
  }
  EXPECT_GT(kinds[static_cast<int>(LinePlaneKind::Point)], 5000);
  EXPECT_GT(kinds[static_cast<int>(LinePlaneKind::Parallel)], 30);
  EXPECT_GT(kinds[static_cast<int>(LinePlaneKind::Contained)], 200);
  EXPECT_GT(kinds[static_cast<int>(LinePlaneKind::DegenerateInput)], 200);
}

TEST(LinePlaneIntersection, PluckerKinds) {
  const RationalPoint3 t0{0, 0, 0}, t1{1, 0, 0}, t2{0, 1, 0};
  const auto line = [](double a, double b, double c, double d, double e, double f) {
    return line_through(to_rational(Point3{a, b, c}), to_rational(Point3{d, e, f}));
  };
  EXPECT_EQ(line_plane_intersection(line(0, 0, 1, 1, 0, 1), t0, t1, t2).kind, LinePlaneKind::Parallel);
  EXPECT_EQ(line_plane_intersection(line(0, 0, 0, 1, 1, 0), t0, t1, t2).kind, LinePlaneKind::Contained);
  PluckerLine<Exact> not_real = line(0, 0, 1, 1, 0, 1);
  not_real.m.x += 1;  // breaks d.m = 0
  EXPECT_EQ(line_plane_intersection(not_real, t0, t1, t2).kind, LinePlaneKind::DegenerateInput);
}

}  // namespace
}  // namespace exactvis
