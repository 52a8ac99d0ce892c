// Stabbing pairs: the edge constraints must characterise exactly the directed lines that cross relint S'
// and then relint T'. Checked with the independent oracle on random lines through points of S and T.
#include "region/stabbing_pair.hpp"

#include "oracles/rational_geometry.hpp"
#include "region/int_vector6.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

oracle::QVec qv(const RationalPoint3& p) { return {mpq_class(p.x.mpq()), mpq_class(p.y.mpq()), mpq_class(p.z.mpq())}; }

RationalPoint3 rnd(std::mt19937_64& rng, int range) {
  auto c = [&] { return Exact(static_cast<long>(rng() % (2 * range + 1)) - range) / Exact(4); };
  return {c(), c(), c()};
}

bool in_relint_polygon(const oracle::QVec& p, const Polygon3& poly) {
  // Fan triangles of a convex polygon: p in relint iff in the relint of a fan triangle, or in the relint
  // of a diagonal shared by two fan triangles.
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const auto a = qv(poly[0]), b = qv(poly[i]), c = qv(poly[i + 1]);
    if (oracle::oracle_point_in_triangle_relative_interior(p, a, b, c)) return true;
    if (i + 2 < poly.size() && oracle::oracle_point_in_closed_triangle(p, a, b, c) &&
        oracle::oracle_point_in_closed_triangle(p, a, c, qv(poly[i + 2])) &&
        !(p == a) && !(p == c))
      return true;
  }
  return false;
}

}  // namespace

TEST(StabbingPair, ConstraintsCharacteriseStabbers) {
  std::mt19937_64 rng(8);
  int pairs_seen = 0, stabbers = 0, non_stabbers = 0;
  for (int trial = 0; trial < 150; ++trial) {
    Polygon3 s{rnd(rng, 8), rnd(rng, 8), rnd(rng, 8)};
    std::array<RationalPoint3, 3> t{rnd(rng, 8), rnd(rng, 8), rnd(rng, 8)};
    if (is_degenerate(s) || is_degenerate({t[0], t[1], t[2]})) continue;
    for (const auto& pair : stabbing_pairs(s, t)) {
      ++pairs_seen;
      const Plane3 ps = pair.source_plane, pt = pair.target_plane;
      // S' lies on the positive side of plane(T), T' on the positive side of plane(S).
      for (const auto& v : pair.source) EXPECT_GE(CGAL::sign(pt.value(v)), 0);
      for (const auto& v : pair.target) EXPECT_GE(CGAL::sign(ps.value(v)), 0);
      for (int k = 0; k < 60; ++k) {
        // A random line through a point of plane(S') and a point of plane(T') near the polygons.
        auto pick = [&](const Polygon3& poly) {
          RationalPoint3 acc{Exact(0), Exact(0), Exact(0)};
          Exact tot(0);
          for (const auto& v : poly) {
            const Exact w(static_cast<long>(rng() % 7) - 1);  // some weights negative: also outside points
            acc = acc + w * v;
            tot += w;
          }
          if (tot == 0) return poly[0];
          return RationalPoint3{acc.x / tot, acc.y / tot, acc.z / tot};
        };
        const RationalPoint3 p = pick(pair.source), q = pick(pair.target);
        if (p == q) continue;
        const auto line = line_through(p, q);
        bool all_positive = true;
        for (const auto& e : pair.edge_lines) all_positive = all_positive && side_of_lines(line, e) == Sign::Positive;
        const bool stabs = in_relint_polygon(qv(p), pair.source) && in_relint_polygon(qv(q), pair.target);
        EXPECT_EQ(all_positive, stabs) << "trial " << trial;
        (stabs ? stabbers : non_stabbers)++;
        // The reversed line never satisfies the constraints.
        bool rev_positive = true;
        for (const auto& e : pair.edge_lines) rev_positive = rev_positive && side_of_lines(reversed(line), e) == Sign::Positive;
        EXPECT_FALSE(rev_positive);
      }
    }
  }
  EXPECT_GT(pairs_seen, 50);
  EXPECT_GT(stabbers, 100);
  EXPECT_GT(non_stabbers, 100);
}

TEST(StabbingPair, CoplanarSourceAndTargetGiveNoPair) {
  const Polygon3 s{to_rational({0, 0, 0}), to_rational({1, 0, 0}), to_rational({0, 1, 0})};
  const std::array<RationalPoint3, 3> t{to_rational({2, 2, 0}), to_rational({3, 2, 0}), to_rational({2, 3, 0})};
  EXPECT_TRUE(stabbing_pairs(s, t).empty());
}

TEST(StabbingPair, CrossingPolygonsSplitIntoFourPairs) {
  // S in plane z = 0 crossing the plane x = 0 of T, T crossing z = 0: four (S', T') pairs.
  const Polygon3 s{to_rational({-1, -1, 0}), to_rational({1, -1, 0}), to_rational({1, 1, 0}), to_rational({-1, 1, 0})};
  const std::array<RationalPoint3, 3> t{to_rational({0, -5, -1}), to_rational({0, 5, -1}), to_rational({0, 0, 1})};
  EXPECT_EQ(stabbing_pairs(s, t).size(), 4u);
}
