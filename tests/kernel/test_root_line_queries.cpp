// kernel/root_line_queries on the transversals of random and adversarial quadruples: side signs against the
// oracle's sign in Q(sqrt D), meeting points checked on both lines by exact substitution.
#include "kernel/root_line_queries.hpp"
#include "kernel/line_through_point_meeting_two_lines.hpp"
#include "kernel/lines_through_four_lines.hpp"
#include "kernel_test_inputs.hpp"

#include <gtest/gtest.h>

namespace exactvis {
namespace {

using test::PointGenerator;
using test::to_mpq;

oracle::RootLine to_root_line(const PluckerLine<RootNumber>& l) {
  oracle::RootLine r;
  r.root = 0;
  for (int i = 0; i < 6; ++i) {
    r.a[i] = to_mpq(l[i].a0());
    r.b[i] = l[i].is_extended() ? to_mpq(l[i].a1()) : mpq_class(0);
    if (l[i].is_extended()) r.root = to_mpq(l[i].root());
  }
  return r;
}

oracle::RootPoint to_root_point(const Vec3<RootNumber>& p) {
  oracle::RootPoint r;
  r.root = 0;
  for (int i = 0; i < 3; ++i) {
    r.a[i] = to_mpq(p[i].a0());
    r.b[i] = p[i].is_extended() ? to_mpq(p[i].a1()) : mpq_class(0);
    if (p[i].is_extended()) r.root = to_mpq(p[i].root());
  }
  return r;
}

TEST(RootLineQueries, MatchOracleOnTransversals) {
  PointGenerator gen(71);
  int points = 0, parallel = 0, signs[3] = {0, 0, 0}, irrational = 0;
  for (int i = 0; i < 1500; ++i) {
    gen.start_case();
    gen.degenerate_probability = (i % 2 == 0) ? 0.0 : 0.5;
    const auto drawn = test::next_lines<5>(gen);  // four inputs and one probe line
    if (!drawn) continue;
    const std::array<PluckerLine<Exact>, 5>& in = *drawn;
    const auto r = lines_through_four_lines({in[0], in[1], in[2], in[3]});
    const std::string where = std::string(test::family_name(gen.family)) + " case " + std::to_string(i);
    for (const auto& x : r.lines) {
      const auto rx = to_root_line(x);
      irrational += oracle::sign(rx.root) != 0;
      for (int k = 0; k < 5; ++k) {
        const auto ol = test::to_oracle(in[k]);
        const int s = to_int(side_sign(x, in[k]));
        ASSERT_EQ(s, oracle::side_sign(rx, ol)) << where << " line " << k;
        if (k < 4) {
          ASSERT_EQ(s, 0) << where;
        }
        signs[s + 1]++;
        const auto mp = meeting_point(x, in[k]);
        if (!mp) {
          // No finite meeting point: skew (side != 0) or parallel (d_x x d_l = 0, checked in Q(sqrt D)).
          if (s == 0) {
            for (int a = 0; a < 3; ++a) {
              const int b = (a + 1) % 3;
              const mpq_class u0 = rx.a[a] * to_mpq(in[k].d[b]) - rx.a[b] * to_mpq(in[k].d[a]);
              const mpq_class u1 = rx.b[a] * to_mpq(in[k].d[b]) - rx.b[b] * to_mpq(in[k].d[a]);
              ASSERT_TRUE(oracle::is_zero_in_extension(u0, u1, rx.root)) << where << ": meeting lines, no point";
            }
            ++parallel;
          }
          continue;
        }
        ASSERT_EQ(s, 0) << where;
        const auto op = to_root_point(*mp);
        ASSERT_TRUE(oracle::on_line(op, rx)) << where;
        ASSERT_TRUE(oracle::on_line(op, ol)) << where;
        ++points;
      }
    }
  }
  EXPECT_GT(points, 1000);
  EXPECT_GT(irrational, 200);
  EXPECT_GT(signs[0], 100);
  EXPECT_GT(signs[2], 100);
  EXPECT_GT(parallel, 0);
}

TEST(RootLineQueries, ToDoubleApproximatesTheExactLine) {
  // Transversals x = (-b +- sqrt D) u + 2a v of the hyperboloid configuration with the diagonal line:
  // to_double must agree with a + b sqrt(D) evaluated in long double to double precision.
  const auto hyp = [](int t) {
    const Exact c = Exact(1 - t * t) / Exact(1 + t * t), s = Exact(2 * t) / Exact(1 + t * t);
    const RationalPoint3 p{c, s, 0};
    return line_through(p, p + RationalPoint3{-s, c, 1});
  };
  const auto diag = line_through(RationalPoint3{0, 0, 0}, RationalPoint3{1, 1, 0});
  const auto r = lines_through_four_lines({hyp(0), hyp(1), hyp(2), diag});
  ASSERT_EQ(r.lines.size(), 2u);
  for (const auto& x : r.lines) {
    const auto d = to_double(x);
    for (int i = 0; i < 6; ++i) {
      const long double expected =
          (long double)CGAL::to_double(x[i].a0()) +
          (x[i].is_extended() ? (long double)CGAL::to_double(x[i].a1()) *
                                    std::sqrt((long double)CGAL::to_double(x[i].root()))
                              : 0.0L);
      EXPECT_NEAR(d[i], (double)expected, 1e-12 * (1 + std::fabs((double)expected))) << i;
    }
  }
}

}  // namespace
}  // namespace exactvis
