// The shaft occluders of region/occluder_shaft with the clipping shortcut (triangles strictly inside both
// polygon planes keep their corners; edge functionals from the double corners in the fixed layer) against the
// same culling done with rational clipping throughout (the exact-triangle overload, which never takes the
// shortcut) and against edge functionals computed here from rational Plücker coordinates with GMP (mpq/mpz
// only): the same occluders, in the same order, with the same integer vectors. Random triangles on the 1/64
// grid of the scene generators and with arbitrary double coordinates, sources from cell faces and random
// polygons, so that both the shortcut and the clipping path run.
#include "region/occluder_shaft.hpp"

#include "kernel/predicates.hpp"
#include "region/stabbing_pair.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

using Z6 = std::array<mpz_class, 6>;

// Oracle: the side functional (m, d) of the line p -> q, primitive integers (positive factor), GMP only.
Z6 oracle_functional(const RationalPoint3& p, const RationalPoint3& q) {
  const mpq_class px(p.x.mpq()), py(p.y.mpq()), pz(p.z.mpq()), qx(q.x.mpq()), qy(q.y.mpq()), qz(q.z.mpq());
  const std::array<mpq_class, 6> f{py * qz - pz * qy, pz * qx - px * qz, px * qy - py * qx, qx - px, qy - py, qz - pz};
  mpz_class l = 1, g = 0;
  for (const auto& c : f) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  Z6 v;
  for (std::size_t k = 0; k < 6; ++k) {
    const mpq_class s = f[k] * l;
    v[k] = s.get_num();
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), v[k].get_mpz_t());
  }
  for (auto& c : v) c /= g;
  return v;
}

struct Fixture {
  Scene scene;
  std::vector<std::array<RationalPoint3, 3>> exact;  // the same triangles as rationals
};

Fixture random_scene(std::mt19937_64& rng, bool grid, int n) {
  Fixture f;
  std::uniform_int_distribution<int> g(-640, 640);
  std::uniform_real_distribution<double> u(-10, 10);
  auto coord = [&] { return grid ? g(rng) / 64.0 : u(rng); };
  while (static_cast<int>(f.scene.triangles.size()) < n) {
    const Point3 a{coord(), coord(), coord()}, b{coord(), coord(), coord()}, c{coord(), coord(), coord()};
    if (collinear(a, b, c)) continue;
    const int v0 = static_cast<int>(f.scene.vertices.size());
    f.scene.vertices.insert(f.scene.vertices.end(), {a, b, c});
    SceneTriangle t;
    t.id = static_cast<std::int64_t>(f.scene.triangles.size());
    t.v = {v0, v0 + 1, v0 + 2};
    f.scene.triangles.push_back(t);
    f.exact.push_back({to_rational(a), to_rational(b), to_rational(c)});
  }
  f.scene.objects.push_back({"all"});
  return f;
}

}  // namespace

TEST(OccluderShaft, ShortcutGivesTheRationalClippingsOccluders) {
  std::mt19937_64 rng(2026);
  int pairs = 0, occluders = 0, compared_edges = 0;
  const ConeLayerCounts before = cone_layer_counts();
  for (int trial = 0; trial < 60; ++trial) {
    const bool grid = trial % 3 != 2;
    Fixture f = random_scene(rng, grid, 40);
    // Source: a face of a small box (cell-like) or a random triangle; target: a scene triangle.
    Polygon3 source;
    if (trial % 2 == 0) {
      const Exact z(static_cast<long>(rng() % 5) - 2);
      source = {{Exact(-1), Exact(-1), z}, {Exact(1), Exact(-1), z}, {Exact(1), Exact(1), z}, {Exact(-1), Exact(1), z}};
    } else {
      source = {f.exact[0][0], f.exact[0][1], f.exact[0][2]};
    }
    const std::int64_t target = 1 + static_cast<std::int64_t>(rng() % 39);
    std::vector<std::int64_t> candidates;
    std::vector<std::array<RationalPoint3, 3>> others;
    std::vector<std::int64_t> other_index;
    for (std::int64_t i = 0; i < 40; ++i) {
      candidates.push_back(i);
      if (i == target) continue;
      others.push_back(f.exact[static_cast<std::size_t>(i)]);
      other_index.push_back(i);
    }
    for (const auto& pair : stabbing_pairs(source, f.exact[static_cast<std::size_t>(target)])) {
      ++pairs;
      const auto fast = shaft_occluders(f.scene, candidates, target, pair);
      const auto slow = shaft_occluders(others, pair);
      ASSERT_EQ(fast.size(), slow.size()) << "trial " << trial;
      for (std::size_t k = 0; k < fast.size(); ++k) {
        ++occluders;
        EXPECT_EQ(fast[k].triangle, other_index[static_cast<std::size_t>(slow[k].triangle)]);
        ASSERT_EQ(fast[k].edges.size(), slow[k].edges.size());
        for (std::size_t e = 0; e < fast[k].edges.size(); ++e) EXPECT_EQ(fast[k].edges[e], slow[k].edges[e]);
        // Unclipped triangles (three edges): the oracle's functionals of the corner loop, in order.
        if (fast[k].edges.size() == 3) {
          const auto& t = f.exact[static_cast<std::size_t>(fast[k].triangle)];
          bool all_match = true;
          for (std::size_t e = 0; e < 3; ++e)
            all_match = all_match && fast[k].edges[e].to_gmp() == oracle_functional(t[e], t[(e + 1) % 3]);
          compared_edges += all_match ? 1 : 0;
        }
      }
    }
  }
  const ConeLayerCounts after = cone_layer_counts();
  EXPECT_GT(pairs, 40);
  EXPECT_GT(occluders, 200);
  EXPECT_GT(compared_edges, 50);  // unclipped triangles whose edges are the corner loop's lines
  // The shortcut ran (fixed-layer edge functionals).
  EXPECT_GT(after.constructions[1] - before.constructions[1], 100u);
}

// shaft_planes against the planes computed here with GMP rationals only (mpq): for every edge of one polygon
// and vertex of the other (source edges first), the plane through them when it is not collinear and has every
// point of both polygons on one closed side, oriented so that they are on its side >= 0, in that order. Grid
// coordinates put many points exactly on the candidate planes (the intervals cannot decide them); rational
// pieces of split polygons and arbitrary doubles make the enclosures wide.
TEST(OccluderShaft, ShaftPlanesAreTheSupportingPlanesOfTheOracle) {
  std::mt19937_64 rng(77);
  int pairs = 0, planes_seen = 0;
  auto q = [](const RationalPoint3& p) {
    return std::array<mpq_class, 3>{mpq_class(p.x.mpq()), mpq_class(p.y.mpq()), mpq_class(p.z.mpq())};
  };
  using Q3 = std::array<mpq_class, 3>;
  auto sub = [](const Q3& a, const Q3& b) { return Q3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  auto cross = [](const Q3& a, const Q3& b) {
    return Q3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto dot = [](const Q3& a, const Q3& b) { return mpq_class(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]); };
  for (int trial = 0; trial < 80; ++trial) {
    Fixture f = random_scene(rng, trial % 3 != 2, 4);
    Polygon3 source;
    if (trial % 2 == 0) {
      const Exact z(static_cast<long>(rng() % 5) - 2);
      source = {{Exact(-1), Exact(-1), z}, {Exact(1), Exact(-1), z}, {Exact(1), Exact(1), z}, {Exact(-1), Exact(1), z}};
    } else {
      source = {f.exact[0][0], f.exact[0][1], f.exact[0][2]};
    }
    for (int t = 1; t < 4; ++t)
      for (const auto& pair : stabbing_pairs(source, f.exact[static_cast<std::size_t>(t)])) {
        ++pairs;
        std::vector<Q3> pts;
        for (const auto& p : pair.source) pts.push_back(q(p));
        for (const auto& p : pair.target) pts.push_back(q(p));
        const std::size_t ns = pair.source.size();
        std::vector<std::pair<Q3, mpq_class>> expected;  // (normal, offset)
        auto consider = [&](std::size_t e0, std::size_t ne, std::size_t v0, std::size_t nv) {
          for (std::size_t i = 0; i < ne; ++i)
            for (std::size_t c = 0; c < nv; ++c) {
              const Q3 &a = pts[e0 + i], &b = pts[e0 + (i + 1) % ne], &cc = pts[v0 + c];
              Q3 n = cross(sub(b, a), sub(cc, a));
              if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;
              bool pos = false, neg = false;
              for (const Q3& p : pts) {
                const int sg = sgn(dot(n, sub(p, a)));
                pos |= sg > 0;
                neg |= sg < 0;
              }
              if (pos && neg) continue;
              if (neg) n = Q3{-n[0], -n[1], -n[2]};
              expected.emplace_back(n, dot(n, a));
            }
        };
        consider(0, ns, ns, pair.target.size());
        consider(ns, pair.target.size(), 0, ns);
        const std::vector<Plane3> got = shaft_planes(pair);
        ASSERT_EQ(got.size(), expected.size() + 2) << "trial " << trial;
        for (std::size_t k = 0; k < expected.size(); ++k) {
          const Plane3& g = got[k + 2];
          const Q3 gn{mpq_class(g.normal.x.mpq()), mpq_class(g.normal.y.mpq()), mpq_class(g.normal.z.mpq())};
          EXPECT_TRUE(gn == expected[k].first) << "trial " << trial << " plane " << k;
          EXPECT_TRUE(mpq_class(g.offset.mpq()) == expected[k].second) << "trial " << trial << " plane " << k;
          ++planes_seen;
        }
      }
  }
  EXPECT_GT(pairs, 100);
  EXPECT_GT(planes_seen, 500);
}

// The occluders' edge functionals equal the lines through consecutive corners of clip_polygon's clipping
// (both polygon planes), computed by the oracle from the rational points: the tracked clipping takes the
// functionals of edges on triangle edges from the triangle's corners, which must be the same directed lines.
// Grid scenes put many corners exactly on the planes (kept vertices of value 0 next to crossings).
TEST(OccluderShaft, TrackedClippingGivesTheLinesOfTheClippedCorners) {
  std::mt19937_64 rng(77);
  int clipped = 0;
  for (int trial = 0; trial < 60; ++trial) {
    Fixture f = random_scene(rng, trial % 4 != 3, 40);
    const Exact z(static_cast<long>(rng() % 5) - 2);
    const Polygon3 source{{Exact(-1), Exact(-1), z}, {Exact(1), Exact(-1), z}, {Exact(1), Exact(1), z}, {Exact(-1), Exact(1), z}};
    const std::size_t target = 1 + rng() % 39;
    std::vector<std::array<RationalPoint3, 3>> others;
    for (std::size_t i = 0; i < 40; ++i)
      if (i != target) others.push_back(f.exact[i]);
    for (const auto& pair : stabbing_pairs(source, f.exact[target])) {
      for (const auto& occ : shaft_occluders(others, pair)) {
        const auto& t = others[static_cast<std::size_t>(occ.triangle)];
        Polygon3 poly = clip_polygon({t[0], t[1], t[2]}, pair.source_plane);
        poly = clip_polygon(poly, pair.target_plane);
        ASSERT_EQ(occ.edges.size(), poly.size());
        for (std::size_t e = 0; e < poly.size(); ++e)
          EXPECT_EQ(occ.edges[e].to_gmp(), oracle_functional(poly[e], poly[(e + 1) % poly.size()])) << "trial " << trial;
        clipped += poly.size() != 3 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(clipped, 30);
}
