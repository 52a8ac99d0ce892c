// kernel/segment_triangle_intersection against the oracle (explicit intersection points, barycentric
// coordinates and parameter clipping), over random and adversarial configurations.
#include "kernel/segment_triangle_intersection.hpp"
#include "kernel_test_inputs.hpp"

#include <gtest/gtest.h>

namespace exactvis {
namespace {

using test::PointGenerator;
using test::to_oracle;

TEST(SegmentTriangle, HandPickedCases) {
  const Point3 t0{0, 0, 0}, t1{4, 0, 0}, t2{0, 4, 0};
  // Transversal through the interior.
  EXPECT_TRUE(segment_meets_closed_triangle(Point3{1, 1, -1}, Point3{1, 1, 1}, t0, t1, t2));
  EXPECT_TRUE(open_segment_meets_closed_triangle(Point3{1, 1, -1}, Point3{1, 1, 1}, t0, t1, t2));
  EXPECT_TRUE(segment_crosses_triangle_interior(Point3{1, 1, -1}, Point3{1, 1, 1}, t0, t1, t2));
  // Through a vertex: meets, but does not cross the interior.
  EXPECT_TRUE(open_segment_meets_closed_triangle(Point3{0, 0, -1}, Point3{0, 0, 1}, t0, t1, t2));
  EXPECT_FALSE(segment_crosses_triangle_interior(Point3{0, 0, -1}, Point3{0, 0, 1}, t0, t1, t2));
  // Endpoint on the interior: the closed segment meets, the open one does not.
  EXPECT_TRUE(segment_meets_closed_triangle(Point3{1, 1, 0}, Point3{1, 1, 1}, t0, t1, t2));
  EXPECT_FALSE(open_segment_meets_closed_triangle(Point3{1, 1, 0}, Point3{1, 1, 1}, t0, t1, t2));
  EXPECT_FALSE(segment_crosses_triangle_interior(Point3{1, 1, 0}, Point3{1, 1, 1}, t0, t1, t2));
  // Coplanar overlap, coplanar touching at an endpoint, coplanar disjoint.
  EXPECT_TRUE(open_segment_meets_closed_triangle(Point3{-1, 1, 0}, Point3{5, 1, 0}, t0, t1, t2));
  EXPECT_FALSE(open_segment_meets_closed_triangle(Point3{-1, 0, 0}, Point3{0, 0, 0}, t0, t1, t2));
  EXPECT_TRUE(segment_meets_closed_triangle(Point3{-1, 0, 0}, Point3{0, 0, 0}, t0, t1, t2));
  EXPECT_FALSE(segment_meets_closed_triangle(Point3{3, 3, 0}, Point3{5, 1, 0}, t0, t1, t2));
  // Along an edge.
  EXPECT_TRUE(open_segment_meets_closed_triangle(Point3{1, 0, 0}, Point3{2, 0, 0}, t0, t1, t2));
  // Zero-length segment: the open segment is empty.
  EXPECT_FALSE(open_segment_meets_closed_triangle(Point3{1, 1, 0}, Point3{1, 1, 0}, t0, t1, t2));
  EXPECT_TRUE(segment_meets_closed_triangle(Point3{1, 1, 0}, Point3{1, 1, 0}, t0, t1, t2));
  // Zero-area triangle (a segment): crossing it.
  EXPECT_TRUE(open_segment_meets_closed_triangle(Point3{1, -1, 0}, Point3{1, 1, 0}, t0, t1, Point3{2, 0, 0}));
  EXPECT_FALSE(segment_crosses_triangle_interior(Point3{1, -1, 0}, Point3{1, 1, 0}, t0, t1, Point3{2, 0, 0}));
}

void check_case(const Point3& a, const Point3& b, const Point3& t0, const Point3& t1, const Point3& t2,
                const std::string& where, int* stats) {
  const auto oa = to_oracle(a), ob = to_oracle(b), o0 = to_oracle(t0), o1 = to_oracle(t1), o2 = to_oracle(t2);
  const bool closed = oracle::oracle_closed_segment_meets_closed_triangle(oa, ob, o0, o1, o2);
  const bool open = oracle::oracle_open_segment_meets_closed_triangle(oa, ob, o0, o1, o2);
  const bool crosses = oracle::oracle_segment_crosses_triangle_interior(oa, ob, o0, o1, o2);
  const bool a_in = oracle::oracle_point_in_closed_triangle(oa, o0, o1, o2);
  ASSERT_EQ(segment_meets_closed_triangle(a, b, t0, t1, t2), closed) << where;
  ASSERT_EQ(open_segment_meets_closed_triangle(a, b, t0, t1, t2), open) << where;
  ASSERT_EQ(segment_crosses_triangle_interior(a, b, t0, t1, t2), crosses) << where;
  ASSERT_EQ(point_in_closed_triangle(a, t0, t1, t2), a_in) << where;
  const auto ra = to_rational(a), rb = to_rational(b), r0 = to_rational(t0), r1 = to_rational(t1),
             r2 = to_rational(t2);
  ASSERT_EQ(segment_meets_closed_triangle(ra, rb, r0, r1, r2), closed) << where;
  ASSERT_EQ(open_segment_meets_closed_triangle(ra, rb, r0, r1, r2), open) << where;
  ASSERT_EQ(segment_crosses_triangle_interior(ra, rb, r0, r1, r2), crosses) << where;
  ASSERT_EQ(point_in_closed_triangle(ra, r0, r1, r2), a_in) << where;
  // Symmetries: reversing the segment, rotating the triangle's corners.
  ASSERT_EQ(open_segment_meets_closed_triangle(b, a, t1, t2, t0), open) << where;
  ASSERT_EQ(segment_meets_closed_triangle(b, a, t2, t1, t0), closed) << where;
  const bool coplanar = orient3d(t0, t1, t2, a) == Sign::Zero && orient3d(t0, t1, t2, b) == Sign::Zero;
  stats[0] += closed;
  stats[1] += open;
  stats[2] += crosses;
  stats[3] += closed && !open;
  stats[4] += coplanar && open;
  stats[5] += collinear(t0, t1, t2) && closed;
  stats[6] += coplanar && !open && closed;
}

TEST(SegmentTriangle, MatchesOracleOnAdversarialInputs) {
  PointGenerator gen(21);
  int stats[7] = {0, 0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 40000; ++i) {
    gen.start_case();
    const Point3 t0 = gen.next(), t1 = gen.next(), t2 = gen.next();
    const Point3 a = gen.next(), b = gen.next();
    check_case(a, b, t0, t1, t2, std::string(test::family_name(gen.family)) + " case " + std::to_string(i), stats);
    if (HasFatalFailure()) return;
  }
  // Coverage of the degenerate branches (the generator must really reach them).
  EXPECT_GT(stats[0], 4000);  // closed meets
  EXPECT_GT(stats[2], 500);   // transversal crossings
  EXPECT_GT(stats[3], 1000);  // touching only at an endpoint
  EXPECT_GT(stats[4], 300);   // coplanar overlaps
  EXPECT_GT(stats[5], 300);   // zero-area triangles met
  EXPECT_GT(stats[6], 100);   // coplanar, touching only at an endpoint
}

TEST(SegmentTriangle, MatchesOracleOnSmallIntegerGrid) {
  // Exhaustive-style: small integer coordinates give every incidence (vertex, edge, coplanar) often.
  PointGenerator gen(22);
  gen.degenerate_probability = 0.4;
  int stats[7] = {0, 0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 30000; ++i) {
    gen.start_case(test::Family::SmallInt);
    const Point3 t0 = gen.next(), t1 = gen.next(), t2 = gen.next();
    const Point3 a = gen.next(), b = gen.next();
    check_case(a, b, t0, t1, t2, "small-int case " + std::to_string(i), stats);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(stats[4], 500);
  EXPECT_GT(stats[6], 200);
}

}  // namespace
}  // namespace exactvis
