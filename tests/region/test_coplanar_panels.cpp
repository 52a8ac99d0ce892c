// Coplanar convex panels (region/coplanar_panels.hpp): hand-made unions that are and are not one convex polygon,
// and random coplanar grids (holes, random diagonals, tilted planes, duplicated and flipped triangles) whose
// panels are checked by the oracle's rational geometry: every panel's triangles are coplanar, their areas sum to
// the loop polygon's area, random points of the polygon are covered by a triangle and lie in the relative
// interior of at most one, and points just outside the polygon are covered by none.
#include "oracles/rational_geometry.hpp"
#include "region/coplanar_panels.hpp"
#include "tests/region/region_scene_builder.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::region;
using oracle::QVec;

namespace {

QVec q(const Point3& p) { return oracle::qvec(p.x, p.y, p.z); }

// Twice the area of the polygon, as the length of the summed cross products (compared squared: exact).
mpq_class twice_area_squared(const std::vector<QVec>& poly) {
  QVec s = oracle::qvec(0, 0, 0);
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) s = s + oracle::cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
  return oracle::dot(s, s);
}

// Do the triangles share an edge (two corners with equal coordinates)?
bool shares_edge(const Scene& s, std::size_t a, std::size_t b) {
  int shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) shared += s.corner(s.triangles[a], i) == s.corner(s.triangles[b], j) ? 1 : 0;
  return shared >= 2;
}

// Oracle check of one panel; returns a failure description or "".
std::string check_panel(const Scene& scene, const CoplanarPanel& panel, std::mt19937_64& rng) {
  if (panel.triangles.size() < 2) return "panel of fewer than two triangles";
  if (panel.loop.size() < 3) return "loop of fewer than three corners";
  std::vector<std::array<QVec, 3>> tris;
  for (const std::int64_t t : panel.triangles) {
    const SceneTriangle& st = scene.triangles[static_cast<std::size_t>(t)];
    tris.push_back({q(scene.corner(st, 0)), q(scene.corner(st, 1)), q(scene.corner(st, 2))});
  }
  std::vector<QVec> loop;
  for (const Point3& p : panel.loop) loop.push_back(q(p));
  for (const auto& t : tris)
    for (const QVec& c : t)
      if (oracle::orient3d(loop[0], loop[1], loop[2], c) != 0) return "a triangle off the loop's plane";
  // Areas: the sum of the triangles' areas equals the polygon's (all normals parallel: compare the summed
  // cross products' lengths; the triangles' normals must all point one way).
  const QVec n0 = oracle::cross(tris[0][1] - tris[0][0], tris[0][2] - tris[0][0]);
  QVec sum = oracle::qvec(0, 0, 0);
  for (const auto& t : tris) {
    const QVec n = oracle::cross(t[1] - t[0], t[2] - t[0]);
    if (oracle::sign(oracle::dot(n, n0)) <= 0) return "triangles of opposite orientation";
    sum = sum + n;
  }
  if (oracle::dot(sum, sum) != twice_area_squared(loop)) return "areas differ from the loop polygon's";
  // Random points of the polygon (convex combinations of its corners): covered, in at most one interior.
  std::uniform_int_distribution<int> w(0, 1000);
  for (int s = 0; s < 40; ++s) {
    std::vector<mpq_class> weights(loop.size());
    mpq_class total = 0;
    for (auto& x : weights) total += (x = w(rng));
    if (total == 0) continue;
    QVec p = oracle::qvec(0, 0, 0);
    for (std::size_t i = 0; i < loop.size(); ++i) p = p + mpq_class(weights[i] / total) * loop[i];
    int closed = 0, interior = 0;
    for (const auto& t : tris) {
      closed += oracle::oracle_point_in_closed_triangle(p, t[0], t[1], t[2]) ? 1 : 0;
      interior += oracle::oracle_point_in_triangle_relative_interior(p, t[0], t[1], t[2]) ? 1 : 0;
    }
    if (closed == 0) return "a point of the polygon covered by no triangle";
    if (interior > 1) return "a point in the interiors of two triangles";
  }
  // Points just outside each corner (away from the centroid): covered by none.
  QVec centroid = oracle::qvec(0, 0, 0);
  for (const QVec& c : loop) centroid = centroid + mpq_class(1, static_cast<long>(loop.size())) * c;
  for (const QVec& c : loop) {
    const QVec p = c + mpq_class(1, 1000) * (c - centroid);
    for (const auto& t : tris)
      if (oracle::oracle_point_in_closed_triangle(p, t[0], t[1], t[2])) return "a point outside the polygon covered";
  }
  return "";
}

// Grid cells [i, i+1] x [j, j+1] (cut positions cu, cv) in the plane spanned from `origin` by u and v
// (dyadic vectors, so the corners are exact doubles), each split by a random diagonal, skipped where `hole`.
void grid(region_test::SceneBuilder& b, const Point3& origin, const Point3& u, const Point3& v,
          const std::vector<double>& cu, const std::vector<double>& cv, const std::vector<char>& hole,
          std::mt19937_64& rng, bool flip_one = false) {
  auto P = [&](std::size_t i, std::size_t j) {
    return Point3{origin.x + cu[i] * u.x + cv[j] * v.x, origin.y + cu[i] * u.y + cv[j] * v.y,
                  origin.z + cu[i] * u.z + cv[j] * v.z};
  };
  for (std::size_t i = 0; i + 1 < cu.size(); ++i)
    for (std::size_t j = 0; j + 1 < cv.size(); ++j) {
      if (hole[i * (cv.size() - 1) + j]) continue;
      const Point3 a = P(i, j), bb = P(i + 1, j), c = P(i + 1, j + 1), d = P(i, j + 1);
      if (rng() % 2) {
        b.triangle(a, bb, c);
        if (flip_one && i == 0 && j == 0) b.triangle(a, d, c);  // the other orientation
        else b.triangle(a, c, d);
      } else {
        b.triangle(a, bb, d);
        b.triangle(bb, c, d);
      }
    }
}

}  // namespace

TEST(CoplanarPanels, HandMadeUnions) {
  region_test::SceneBuilder b;
  // 0-1: a unit square; 2-3: the next square (a 2x1 rectangle with 0-1); 4-5: a square above 0-1 (an L).
  b.rect(2, 0, 0, 1, 0, 1);
  b.rect(2, 0, 1, 2, 0, 1);
  b.rect(2, 0, 0, 1, 1, 2);
  // 6-7: a concave quadrilateral split along its inner diagonal.
  b.triangle({10, 0, 0}, {12, 0, 0}, {11, 0.5, 0});
  b.triangle({10, 0, 0}, {11, 0.5, 0}, {11, 2, 0});
  // 8-9: a triangle and its copy (overlapping).
  b.triangle({20, 0, 0}, {21, 0, 0}, {20, 1, 0});
  b.triangle({20, 0, 0}, {21, 0, 0}, {20, 1, 0});
  // 10-17: a fan of 8 triangles around the centre of a square (a roof): convex as a whole, not halfway.
  const Point3 ring[8] = {{30, 0, 5}, {31, 0, 5}, {32, 0, 5}, {32, 1, 5}, {32, 2, 5}, {31, 2, 5}, {30, 2, 5}, {30, 1, 5}};
  for (int i = 0; i < 8; ++i) b.triangle({31, 1, 5}, ring[i], ring[(i + 1) % 8]);
  const Scene& s = b.scene;
  EXPECT_EQ(convex_union_loop(s, {0, 1}).size(), 4u);
  EXPECT_EQ(convex_union_loop(s, {0, 1, 2, 3}).size(), 4u);  // the collinear corners dropped
  EXPECT_TRUE(convex_union_loop(s, {0, 1, 2, 3, 4, 5}).empty());  // L-shaped
  EXPECT_EQ(convex_union_loop(s, {0, 1, 3}).size(), 4u);  // a trapezoid
  EXPECT_EQ(convex_union_loop(s, {0, 3}).size(), 4u);     // a parallelogram
  EXPECT_TRUE(convex_union_loop(s, {0, 1, 2}).empty());   // triangle 2 touches the square at a corner only
  EXPECT_TRUE(convex_union_loop(s, {6, 7}).empty());
  EXPECT_TRUE(convex_union_loop(s, {8, 9}).empty());
  EXPECT_EQ(convex_union_loop(s, {10, 11, 12, 13, 14, 15, 16, 17}).size(), 4u);
  EXPECT_TRUE(convex_union_loop(s, {10, 11, 12, 13, 14}).empty());  // reflex at the centre
  const CoplanarPanels panels = coplanar_panels(s);
  ASSERT_EQ(panels.panel_of.size(), s.triangles.size());
  // The fan is one panel; 0..5 are one component, not convex: greedy panels; 6-7 and 8-9 are none.
  EXPECT_GE(panels.panel_of[10], 0);
  for (int t = 11; t < 18; ++t) EXPECT_EQ(panels.panel_of[static_cast<std::size_t>(t)], panels.panel_of[10]);
  for (int t : {6, 7, 8, 9}) EXPECT_EQ(panels.panel_of[static_cast<std::size_t>(t)], -1) << t;
  EXPECT_GE(panels.panel_of[0], 0);
  std::mt19937_64 rng(1);
  for (const CoplanarPanel& p : panels.panels) EXPECT_EQ(check_panel(s, p, rng), "");
}

TEST(CoplanarPanels, RandomGridsWithHolesAgreeWithTheOracle) {
  std::int64_t panels_seen = 0, multi = 0, covered = 0, triangles = 0, pairs_seen = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937_64 rng(seed);
    region_test::SceneBuilder b;
    const int nu = 1 + static_cast<int>(rng() % 6), nv = 1 + static_cast<int>(rng() % 6);
    auto cuts = [&](int n) {
      std::vector<double> c{0};
      for (int i = 0; i < n; ++i) c.push_back(c.back() + 0.25 * static_cast<double>(1 + rng() % 4));
      return c;
    };
    const std::vector<double> cu = cuts(nu), cv = cuts(nv);
    std::vector<char> hole(static_cast<std::size_t>(nu * nv), 0);
    // Holes anywhere, or (every other seed) only away from the border: the outline stays convex.
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j)
        hole[static_cast<std::size_t>(i * nv + j)] =
            rng() % 5 == 0 && (seed % 2 == 0 || (i > 0 && j > 0 && i + 1 < nu && j + 1 < nv));
    // Axis-aligned or tilted planes (dyadic spanning vectors: exact corners).
    const Point3 u = seed % 3 == 0 ? Point3{1, 0, 0.5} : Point3{1, 0, 0};
    const Point3 v = seed % 3 == 0 ? Point3{0, 1, -0.25} : (seed % 3 == 1 ? Point3{0, 0, 1} : Point3{0, 1, 0});
    grid(b, {0, 0, 0}, u, v, cu, cv, hole, rng, seed % 7 == 0);
    // A second grid in a parallel plane and one in the same plane far away (not edge-connected).
    grid(b, {0, 0, 3}, u, v, cu, cv, hole, rng);
    grid(b, {40, 40, 0}, u, v, cu, cv, std::vector<char>(hole.size(), 0), rng);
    if (seed % 5 == 0) b.triangle(b.scene.corner(b.scene.triangles[0], 0), b.scene.corner(b.scene.triangles[0], 1),
                                  b.scene.corner(b.scene.triangles[0], 2));  // a duplicate
    const Scene& s = b.scene;
    const CoplanarPanels panels = coplanar_panels(s);
    triangles += static_cast<std::int64_t>(s.triangles.size());
    std::vector<int> seen(s.triangles.size(), 0);
    for (std::size_t p = 0; p < panels.panels.size(); ++p) {
      const CoplanarPanel& panel = panels.panels[p];
      EXPECT_EQ(check_panel(s, panel, rng), "") << "seed " << seed << " panel " << p;
      for (const std::int64_t t : panel.triangles) {
        ++seen[static_cast<std::size_t>(t)];
        EXPECT_EQ(panels.panel_of[static_cast<std::size_t>(t)], static_cast<std::int32_t>(p));
      }
      ++panels_seen;
      multi += panel.triangles.size() > 2 ? 1 : 0;
      covered += static_cast<std::int64_t>(panel.triangles.size());
    }
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      EXPECT_LE(seen[t], 1);
      if (!seen[t]) {
        EXPECT_EQ(panels.panel_of[t], -1);
      }
    }
    // The pairs: 2-triangle panels by the same oracle check, disjoint, and maximal (no two unpaired triangles
    // sharing an edge would pass the certificate: the greedy matching leaves none).
    std::vector<int> paired(s.triangles.size(), 0);
    ASSERT_EQ(panels.pair_of.size(), s.triangles.size());
    for (std::size_t p = 0; p < panels.pairs.size(); ++p) {
      const CoplanarPanel& pr = panels.pairs[p];
      ASSERT_EQ(pr.triangles.size(), 2u);
      EXPECT_EQ(check_panel(s, pr, rng), "") << "seed " << seed << " pair " << p;
      for (const std::int64_t t : pr.triangles) {
        ++paired[static_cast<std::size_t>(t)];
        EXPECT_EQ(panels.pair_of[static_cast<std::size_t>(t)], static_cast<std::int32_t>(p));
      }
      ++pairs_seen;
    }
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      EXPECT_LE(paired[t], 1);
      if (!paired[t]) {
        EXPECT_EQ(panels.pair_of[t], -1);
      }
    }
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
      for (std::size_t o = t + 1; o < s.triangles.size() && !paired[t]; ++o)
        if (!paired[o]) {
          EXPECT_TRUE(convex_union_loop(s, {static_cast<std::int64_t>(t), static_cast<std::int64_t>(o)}).empty() ||
                      !shares_edge(s, t, o))
              << "seed " << seed << ": unpaired triangles " << t << ", " << o << " would make a pair";
        }
  }
  EXPECT_GT(multi, 20);  // panels of more than a pair are found
  EXPECT_GT(pairs_seen, 40);
  EXPECT_GT(covered, triangles / 2);
  EXPECT_GT(panels_seen, 40);
}
