// The direction cone of three lines (aspect/eee_direction_cone) against an independent construction
// (tests/oracles/rational_geometry: Plücker side products in plain GMP rationals): for a direction d, the
// one line of direction d meeting l_1 and l_2 is built explicitly (the plane through l_1 parallel to d cut
// with l_2), and some line of direction d meets all three iff that line meets l_3. Random lines and
// directions (fixed seed), directions from the parametrisation (on the cone), and directions off it.
#include "aspect/eee_direction_cone.hpp"

#include "oracles/rational_geometry.hpp"
#include "tests/exact_to_mpq.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <random>

namespace {

using namespace exactvis;

using exact_to_mpq::q;
using exact_to_mpq::qv;

// Whether a line of direction d meets l_1, l_2 and l_3 (std::nullopt when the construction does not apply:
// d parallel to l_1, or l_2 parallel to the plane through l_1 along d).
std::optional<bool> oracle_has_transversal(const std::array<oracle::QVec, 3>& A, const std::array<oracle::QVec, 3>& u,
                                           const oracle::QVec& d) {
  const oracle::QVec N = oracle::cross(u[0], d);
  if (oracle::is_zero(N)) return std::nullopt;
  const mpq_class den = oracle::dot(N, u[1]);
  if (den == 0) return std::nullopt;
  const mpq_class s = oracle::dot(N, A[0] - A[1]) / den;
  const oracle::QVec Q = A[1] + s * u[1];
  const oracle::QLine L = oracle::line_through(Q, Q + d);
  return oracle::side(L, oracle::line_through(A[2], A[2] + u[2])) == 0;
}

struct Lines {
  std::array<Vec3<Exact>, 3> A, u;
  std::array<oracle::QVec, 3> qA, qu;
};

Lines random_lines(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> c(-6, 6);
  Lines l;
  for (int i = 0; i < 3; ++i) {
    l.A[i] = {Exact(c(rng)), Exact(c(rng)), Exact(c(rng))};
    do l.u[i] = {Exact(c(rng)), Exact(c(rng)), Exact(c(rng))};
    while (l.u[i].x == 0 && l.u[i].y == 0 && l.u[i].z == 0);
    l.qA[i] = qv(l.A[i]);
    l.qu[i] = qv(l.u[i]);
  }
  return l;
}

TEST(EeeDirectionCone, ParametrisedDirectionsAreOnTheConeAndMeetTheLines) {
  std::mt19937_64 rng(16);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Lines l = random_lines(rng);
    const EeeDirectionCone cone = eee_direction_cone(l.A, l.u);
    if (cone.degenerate) continue;
    for (const Exact t : {Exact(0), Exact(1), Exact(-3, 7), Exact(5, 2)}) {
      const Vec3<Exact> d = cone_direction_at(cone, t);
      if (d.x == 0 && d.y == 0 && d.z == 0) continue;
      EXPECT_EQ(cone_value(cone, d), 0) << "trial " << trial;
      // The line through P(t) along d meets l_2 and l_3 (and l_1 at P(t)).
      const oracle::QVec P = l.qA[0] + q(t) * l.qu[0];
      const oracle::QLine L = oracle::line_through(P, P + qv(d));
      for (int j = 1; j < 3; ++j)
        EXPECT_EQ(oracle::side(L, oracle::line_through(l.qA[j], l.qA[j] + l.qu[j])), 0) << "trial " << trial;
      if (const auto has = oracle_has_transversal(l.qA, l.qu, qv(d))) EXPECT_TRUE(*has);
      ++checked;
    }
  }
  EXPECT_GT(checked, 400);
}

TEST(EeeDirectionCone, ConeSignMatchesTheExplicitConstruction) {
  std::mt19937_64 rng(61);
  std::uniform_int_distribution<int> c(-9, 9);
  int on = 0, off = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Lines l = random_lines(rng);
    const EeeDirectionCone cone = eee_direction_cone(l.A, l.u);
    if (cone.degenerate) continue;
    for (int k = 0; k < 10; ++k) {
      const Vec3<Exact> d = k < 2 ? cone_direction_at(cone, Exact(c(rng), 1 + std::abs(c(rng))))
                                  : Vec3<Exact>{Exact(c(rng)), Exact(c(rng)), Exact(c(rng))};
      if (d.x == 0 && d.y == 0 && d.z == 0) continue;
      const auto has = oracle_has_transversal(l.qA, l.qu, qv(d));
      if (!has) continue;
      EXPECT_EQ(*has, cone_value(cone, d) == 0) << "trial " << trial;
      ++(*has ? on : off);
    }
  }
  EXPECT_GT(on, 100);
  EXPECT_GT(off, 500);
}

TEST(EeeDirectionCone, LineDirectionsAreOnTheConeAndParallelDirectionsAreDegenerate) {
  std::mt19937_64 rng(7);
  const Lines l = random_lines(rng);
  const EeeDirectionCone cone = eee_direction_cone(l.A, l.u);
  ASSERT_FALSE(cone.degenerate);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(cone_value(cone, l.u[i]), 0);  // transversals meeting l_i at infinity
  // Three lines parallel to the plane z = 0: a hyperbolic paraboloid's ruling.
  const std::array<Vec3<Exact>, 3> A{{{Exact(0), Exact(0), Exact(0)}, {Exact(0), Exact(0), Exact(1)}, {Exact(0), Exact(0), Exact(2)}}};
  const std::array<Vec3<Exact>, 3> u{{{Exact(1), Exact(0), Exact(0)}, {Exact(0), Exact(1), Exact(0)}, {Exact(1), Exact(1), Exact(0)}}};
  EXPECT_TRUE(eee_direction_cone(A, u).degenerate);
  EXPECT_THROW(eee_direction_cone(A, {u[0], u[1], Vec3<Exact>{Exact(0), Exact(0), Exact(0)}}), std::invalid_argument);
}

}  // namespace
