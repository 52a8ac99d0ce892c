// kernel/line_through_point_meeting_two_lines against an oracle that builds the line differently: the
// point X where b crosses the plane (P, a), then the line PX.
#include "kernel/line_through_point_meeting_two_lines.hpp"
#include "kernel_test_inputs.hpp"

#include <gtest/gtest.h>

namespace exactvis {
namespace {

using test::PointGenerator;
using test::to_oracle;

struct OracleAnswer {
  PointTwoLinesKind kind;
  oracle::QLine line;  // Unique: the line P -> X
};

OracleAnswer oracle_answer(const oracle::QVec& p, const oracle::QVec& a1, const oracle::QVec& a2,
                           const oracle::QVec& b1, const oracle::QVec& b2) {
  using oracle::cross;
  using oracle::dot;
  if (a1 == a2 || b1 == b2) return {PointTwoLinesKind::DegenerateInput, {}};
  if (oracle::is_zero(cross(a2 - a1, p - a1)) || oracle::is_zero(cross(b2 - b1, p - b1)))
    return {PointTwoLinesKind::Infinite, {}};
  const oracle::QVec n = cross(a1 - p, a2 - p);  // normal of plane (P, a)
  const mpq_class h1 = dot(n, b1 - p), h2 = dot(n, b2 - p);
  if (h1 == h2) {
    // b parallel to the plane (P,a): in it -> the planes coincide; else the candidate is parallel to b.
    return {sgn(h1) == 0 ? PointTwoLinesKind::Infinite : PointTwoLinesKind::None, {}};
  }
  const oracle::QVec x = b1 + mpq_class(h1 / (h1 - h2)) * (b2 - b1);
  const oracle::QLine px = oracle::line_through(p, x);
  if (oracle::is_zero(cross(px.d, a2 - a1))) return {PointTwoLinesKind::None, px};
  return {PointTwoLinesKind::Unique, px};
}

bool proportional(const oracle::QLine& x, const oracle::QLine& y) {
  const std::array<mpq_class, 6> u = {x.d.x, x.d.y, x.d.z, x.m.x, x.m.y, x.m.z};
  const std::array<mpq_class, 6> v = {y.d.x, y.d.y, y.d.z, y.m.x, y.m.y, y.m.z};
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j)
      if (u[i] * v[j] != u[j] * v[i]) return false;
  return true;
}

TEST(LineThroughPointMeetingTwoLines, HandPickedCases) {
  // a: the x-axis; b: the line x = 1, z = 1 (direction y); P = (0, 0, 2)... the line through P meeting
  // both passes through (x0,0,0) and (1,y,1) collinear with P: x0 = 2, y = 0.
  const auto a = exact_line_through(Point3{0, 0, 0}, Point3{1, 0, 0});
  const auto b = exact_line_through(Point3{1, 0, 1}, Point3{1, 1, 1});
  auto r = line_through_point_meeting_two_lines(Point3{0, 0, 2}, a, b);
  ASSERT_EQ(r.kind, PointTwoLinesKind::Unique);
  EXPECT_TRUE(proportional(test::to_oracle(r.line),
                           oracle::line_through(oracle::qvec(0, 0, 2), oracle::qvec(2, 0, 0))));
  EXPECT_EQ(line_through_point_meeting_two_lines(Point3{5, 0, 0}, a, b).kind, PointTwoLinesKind::Infinite);
  // P in the plane z = 0 of a, b parallel to a at height 0: planes coincide.
  const auto b2 = exact_line_through(Point3{0, 3, 0}, Point3{1, 3, 0});
  EXPECT_EQ(line_through_point_meeting_two_lines(Point3{0, 1, 0}, a, b2).kind, PointTwoLinesKind::Infinite);
  // b parallel to a, P off their plane: the only candidate is parallel to both.
  const auto b3 = exact_line_through(Point3{0, 3, 1}, Point3{1, 3, 1});
  EXPECT_EQ(line_through_point_meeting_two_lines(Point3{0, 0, 5}, a, b3).kind, PointTwoLinesKind::None);
  PluckerLine<Exact> bad = a;
  bad.d = {0, 0, 0};
  EXPECT_EQ(line_through_point_meeting_two_lines(Point3{0, 0, 5}, bad, b).kind, PointTwoLinesKind::DegenerateInput);
}

TEST(LineThroughPointMeetingTwoLines, MatchesOracle) {
  PointGenerator gen(41);
  int kinds[4] = {0, 0, 0, 0};
  for (int i = 0; i < 20000; ++i) {
    gen.start_case();
    const Point3 a1 = gen.next(), a2 = gen.next(), b1 = gen.next(), b2 = gen.next(), p = gen.next();
    const std::string where = std::string(test::family_name(gen.family)) + " case " + std::to_string(i);
    const auto a = exact_line_through(a1, a2), b = exact_line_through(b1, b2);
    const auto r = line_through_point_meeting_two_lines(p, a, b);
    const auto o = oracle_answer(to_oracle(p), to_oracle(a1), to_oracle(a2), to_oracle(b1), to_oracle(b2));
    kinds[static_cast<int>(r.kind)]++;
    ASSERT_EQ(r.kind, o.kind) << where;
    ASSERT_EQ(line_through_point_meeting_two_lines(to_rational(p), a, b).kind, r.kind);
    if (r.kind != PointTwoLinesKind::Unique && r.kind != PointTwoLinesKind::None) continue;
    // By substitution: a real line through P with side 0 to both a and b.
    const auto ol = test::to_oracle(r.line);
    ASSERT_FALSE(oracle::is_zero(ol.d)) << where;
    ASSERT_EQ(sgn(oracle::quadric(ol)), 0) << where;
    ASSERT_TRUE(oracle::on_line(to_oracle(p), ol)) << where;
    ASSERT_EQ(sgn(oracle::side(ol, oracle::line_through(to_oracle(a1), to_oracle(a2)))), 0) << where;
    ASSERT_EQ(sgn(oracle::side(ol, oracle::line_through(to_oracle(b1), to_oracle(b2)))), 0) << where;
    if (r.kind == PointTwoLinesKind::Unique) {
      ASSERT_TRUE(proportional(ol, o.line)) << where;
    }
  }
  EXPECT_GT(kinds[static_cast<int>(PointTwoLinesKind::Unique)], 5000);
  EXPECT_GT(kinds[static_cast<int>(PointTwoLinesKind::None)], 50);
  EXPECT_GT(kinds[static_cast<int>(PointTwoLinesKind::Infinite)], 500);
  EXPECT_GT(kinds[static_cast<int>(PointTwoLinesKind::DegenerateInput)], 200);
}

}  // namespace
}  // namespace exactvis
