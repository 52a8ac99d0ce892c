// Property tests of kernel/predicates: every predicate against the independent rational oracle, over random
// and adversarial inputs with fixed seeds; the side-operator sign convention; the stabbing theorem.
#include "kernel/predicates.hpp"
#include "kernel_test_inputs.hpp"

#include <gtest/gtest.h>

namespace exactvis {
namespace {

using test::PointGenerator;
using test::to_oracle;

int as_int(Sign s) { return to_int(s); }

TEST(Predicates, SideSignConventionExample) {
  // a: the x-axis, directed +x. b: the line through (0,0,1) directed +y, passing above a.
  const Point3 pa{0, 0, 0}, qa{1, 0, 0}, pb{0, 0, 1}, qb{0, 1, 1};
  // side = (p_a - p_b) . (d_a x d_b) = (0,0,-1) . (0,0,1) = -1.
  EXPECT_EQ(side_of_lines(pa, qa, pb, qb), Sign::Negative);
  EXPECT_EQ(side_of_lines(pb, qb, pa, qa), Sign::Negative);  // symmetric
  EXPECT_EQ(side_of_lines(qa, pa, pb, qb), Sign::Positive);  // reversing one line flips the sign
  // Meeting and parallel lines give 0.
  EXPECT_EQ(side_of_lines(pa, qa, Point3{0, 0, 0}, Point3{0, 1, 0}), Sign::Zero);
  EXPECT_EQ(side_of_lines(pa, qa, Point3{0, 5, 3}, Point3{2, 5, 3}), Sign::Zero);
}

TEST(Predicates, SideEqualsOrient3dAndAngularMomentum) {
  // side(line(p1,q1), line(p2,q2)) = orient3d(p1,q1,p2,q2) as numbers, and
  // = d_b . (w x d_a) with w = p_a - p_b: positive iff a turns counterclockwise about b seen from the tip of d_b.
  PointGenerator gen(11);
  for (int i = 0; i < 20000; ++i) {
    gen.start_case();
    const Point3 p1 = gen.next(), q1 = gen.next(), p2 = gen.next(), q2 = gen.next();
    const auto a = oracle::line_through(to_oracle(p1), to_oracle(q1));
    const auto b = oracle::line_through(to_oracle(p2), to_oracle(q2));
    const auto w = to_oracle(p1) - to_oracle(p2);
    const int momentum = oracle::sign(oracle::dot(b.d, oracle::cross(w, a.d)));
    ASSERT_EQ(oracle::sign(oracle::side(a, b)), momentum);
    ASSERT_EQ(as_int(side_of_lines(p1, q1, p2, q2)), momentum) << test::family_name(gen.family) << " case " << i;
    ASSERT_EQ(side_of_lines(p1, q1, p2, q2), orient3d(p1, q1, p2, q2));
  }
}

TEST(Predicates, SideOfLinesMatchesOracle) {
  PointGenerator gen(1);
  int zeros = 0;
  for (int i = 0; i < 30000; ++i) {
    gen.start_case();
    const Point3 p1 = gen.next(), q1 = gen.next(), p2 = gen.next(), q2 = gen.next();
    const auto a = oracle::line_through(to_oracle(p1), to_oracle(q1));
    const auto b = oracle::line_through(to_oracle(p2), to_oracle(q2));
    const int expected = oracle::sign(oracle::side(a, b));
    zeros += expected == 0;
    ASSERT_EQ(as_int(side_of_lines(p1, q1, p2, q2)), expected) << test::family_name(gen.family) << " case " << i;
    ASSERT_EQ(as_int(side_of_lines(to_rational(p1), to_rational(q1), to_rational(p2), to_rational(q2))), expected);
    const auto ea = line_through(to_rational(p1), to_rational(q1));
    const auto eb = line_through(to_rational(p2), to_rational(q2));
    ASSERT_EQ(as_int(side_of_lines(ea, eb)), expected);
  }
  EXPECT_GT(zeros, 3000);  // the adversarial generator really produces degenerate cases
}

TEST(Predicates, Orient3dMatchesOracle) {
  PointGenerator gen(2);
  int zeros = 0;
  for (int i = 0; i < 30000; ++i) {
    gen.start_case();
    const Point3 a = gen.next(), b = gen.next(), c = gen.next(), d = gen.next();
    const int expected = oracle::orient3d(to_oracle(a), to_oracle(b), to_oracle(c), to_oracle(d));
    zeros += expected == 0;
    ASSERT_EQ(as_int(orient3d(a, b, c, d)), expected) << test::family_name(gen.family) << " case " << i;
    ASSERT_EQ(as_int(orient3d(to_rational(a), to_rational(b), to_rational(c), to_rational(d))), expected);
    ASSERT_EQ(as_int(orient3d(b, a, c, d)), -expected);
  }
  EXPECT_GT(zeros, 3000);
  // The documented orientation: d above the plane of a counterclockwise (seen from +z) triangle is positive.
  EXPECT_EQ(orient3d(Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}), Sign::Positive);
}

TEST(Predicates, Orient2dProjectedAndCollinearMatchOracle) {
  PointGenerator gen(3);
  int collinear_count = 0;
  for (int i = 0; i < 30000; ++i) {
    gen.start_case();
    const Point3 a = gen.next(), b = gen.next(), c = gen.next();
    const auto n = oracle::cross(to_oracle(b) - to_oracle(a), to_oracle(c) - to_oracle(a));
    const int e[3] = {oracle::sign(n.x), oracle::sign(n.y), oracle::sign(n.z)};
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(as_int(orient2d_projected(a, b, c, k)), e[k]) << test::family_name(gen.family) << " case " << i;
      ASSERT_EQ(as_int(orient2d_projected(to_rational(a), to_rational(b), to_rational(c), k)), e[k]);
    }
    const bool expected = oracle::is_zero(n);
    collinear_count += expected;
    ASSERT_EQ(collinear(a, b, c), expected);
    ASSERT_EQ(collinear(to_rational(a), to_rational(b), to_rational(c)), expected);
  }
  EXPECT_GT(collinear_count, 1000);
}

// Oracle: does the line through p, q (not in the polygon's plane) meet the closed convex polygon poly
// (a triangle or a parallelogram, fan-split into triangles)? strict: its relative interior?
bool oracle_line_meets_polygon(const oracle::QVec& p, const oracle::QVec& q, const std::vector<oracle::QVec>& poly,
                               bool strict) {
  const auto n = oracle::cross(poly[1] - poly[0], poly[2] - poly[0]);
  const mpq_class hp = oracle::dot(n, p - poly[0]), hq = oracle::dot(n, q - poly[0]);
  if (hp == hq) return false;  // parallel (the in-plane case is excluded by the caller)
  const oracle::QVec x = p + mpq_class(hp / (hp - hq)) * (q - p);
  if (poly.size() == 3)
    return strict ? oracle::oracle_point_in_triangle_relative_interior(x, poly[0], poly[1], poly[2])
                  : oracle::oracle_point_in_closed_triangle(x, poly[0], poly[1], poly[2]);
  // Parallelogram p0 p1 p2 p3: x = p0 + u (p1 - p0) + v (p3 - p0); inside iff u, v in [0,1] (strict: (0,1)).
  const auto e1 = poly[1] - poly[0], e3 = poly[3] - poly[0], r = x - poly[0];
  const mpq_class den = oracle::dot(oracle::cross(e1, e3), n);
  const mpq_class u = oracle::dot(oracle::cross(r, e3), n) / den;
  const mpq_class v = oracle::dot(oracle::cross(e1, r), n) / den;
  if (strict) return u > 0 && u < 1 && v > 0 && v < 1;
  return u >= 0 && u <= 1 && v >= 0 && v <= 1;
}

TEST(Predicates, StabbingTheoremOnConvexPolygons) {
  // A line not in the polygon's plane stabs the closed convex polygon iff it passes all consistently
  // oriented edges on the same side (signs all >= 0 or all <= 0); strictly iff it crosses the interior.
  PointGenerator gen(4);
  int stabs = 0, strict_stabs = 0, tested = 0;
  for (int i = 0; i < 20000; ++i) {
    gen.start_case(i % 2 ? test::Family::SmallInt : test::Family::Unit);
    std::vector<Point3> poly = {gen.fresh(), gen.fresh(), gen.fresh()};
    if (collinear(poly[0], poly[1], poly[2])) continue;
    if (i % 3 == 0) {  // parallelogram (exact for small integers)
      const Point3 d = {poly[0].x + poly[2].x - poly[1].x, poly[0].y + poly[2].y - poly[1].y,
                        poly[0].z + poly[2].z - poly[1].z};
      if (gen.family != test::Family::SmallInt) continue;
      poly = {poly[0], poly[1], poly[2], d};
    }
    for (const auto& v : poly) gen.pool.push_back(v);
    const Point3 p = gen.next(), q = gen.next();
    if (p == q) continue;
    if (orient3d(poly[0], poly[1], poly[2], p) == Sign::Zero && orient3d(poly[0], poly[1], poly[2], q) == Sign::Zero)
      continue;  // line in the plane: all sides are 0, the theorem does not apply
    bool pos = false, neg = false, zero = false;
    for (size_t k = 0; k < poly.size(); ++k) {
      const Sign s = side_of_lines(p, q, poly[k], poly[(k + 1) % poly.size()]);
      pos |= s == Sign::Positive;
      neg |= s == Sign::Negative;
      zero |= s == Sign::Zero;
    }
    std::vector<oracle::QVec> op;
    for (const auto& v : poly) op.push_back(to_oracle(v));
    const bool meets = oracle_line_meets_polygon(to_oracle(p), to_oracle(q), op, false);
    const bool crosses = oracle_line_meets_polygon(to_oracle(p), to_oracle(q), op, true);
    ASSERT_EQ(!(pos && neg), meets) << "case " << i;
    ASSERT_EQ(!zero && !(pos && neg), crosses) << "case " << i;
    ++tested;
    stabs += meets;
    strict_stabs += crosses;
  }
  EXPECT_GT(tested, 5000);
  EXPECT_GT(stabs, 500);
  EXPECT_GT(stabs - strict_stabs, 100);  // boundary stabs (through edges or vertices) were exercised
}

}  // namespace
}  // namespace exactvis
