// EeeOccluderFilter: it may only prove disjointness that is true. Oracle: configurations built to intersect
// (a rational point X constructed inside both conv(H) and the triangle, including touching and nearly flat
// cases) must never be reported separated; far-apart configurations (H inside a box, the triangle beyond
// a plane outside it, checked by construction) must be, so the filter is not vacuous.
#include "events/eee_occluder_filter.hpp"

#include "kernel/filtered_predicate.hpp"

#include <gtest/gtest.h>

#include <random>

namespace exactvis {
namespace {

Vec3<Exact> q(const Point3& p) { return {Exact(p.x), Exact(p.y), Exact(p.z)}; }

struct Gen {
  std::mt19937_64 rng;
  explicit Gen(std::uint64_t seed) : rng(seed) {}
  double coord(double scale) { return scale * (static_cast<double>(rng() % 2001) / 1000.0 - 1.0); }
  Point3 point(double scale) { return {coord(scale), coord(scale), coord(scale)}; }
};

TEST(EeeOccluderFilter, NeverSeparatesIntersectingConfigurations) {
  Gen g(20261202);
  int cases = 0;
  for (int it = 0; it < 3000; ++it) {
    const double scale = it % 3 == 0 ? 1e-6 : 1.0;  // tiny triangles near X as well
    const Point3 t0 = g.point(4), t1 = t0 + g.point(scale), t2 = t0 + g.point(scale);
    // X in T: the centroid, or (every fourth case) the corner t0 itself (touching).
    const Vec3<Exact> x = it % 4 == 0 ? q(t0) : Exact(1, 3) * (q(t0) + q(t1) + q(t2));
    std::array<Vec3<Exact>, 6> h;
    for (int i = 0; i < 5; ++i) h[i] = q(g.point(it % 5 == 0 ? 1e-3 : 3));
    if (it % 7 == 0) h[4] = h[0] + Exact(1, 2) * (h[1] - h[0]);  // a collinear triple
    // X = midpoint of h[0] and h[5] (or h[5] = X when it % 6 == 0: X a vertex of conv(H)).
    h[5] = it % 6 == 0 ? x : Exact(2) * x - h[0];
    if (it % 11 == 0) h[5] = h[0] = x;  // repeated points
    const EeeOccluderFilter f(h);
    EXPECT_FALSE(f.separated(t0, t1, t2)) << "case " << it;
    ++cases;
  }
  EXPECT_EQ(cases, 3000);
}

TEST(EeeOccluderFilter, SeparatesFarConfigurations) {
  Gen g(7);
  int proved = 0;
  for (int it = 0; it < 500; ++it) {
    std::array<Vec3<Exact>, 6> h;
    for (auto& p : h) p = q(g.point(1));  // inside [-1, 1]^3
    // The triangle beyond the plane x + y + z = 4 (outside the box) or strictly inside a far corner region.
    Point3 t[3];
    for (auto& p : t) {
      p = g.point(1);
      p = {p.x + 5, p.y + 5, p.z + 5};
    }
    const EeeOccluderFilter f(h);
    proved += f.separated(t[0], t[1], t[2]);
  }
  EXPECT_EQ(proved, 500);
  // A triangle whose plane has all of H on one side although the triangle is large (proved by T's plane).
  std::array<Vec3<Exact>, 6> h;
  for (int i = 0; i < 6; ++i) h[i] = q({static_cast<double>(i % 2), static_cast<double>(i / 2), 0.5 + i * 0.1});
  EXPECT_TRUE(EeeOccluderFilter(h).separated({-100, -100, 0}, {100, -100, 0}, {0, 100, 0}));
  // Touching that plane: not proved.
  h[0].z = Exact(0);
  EXPECT_FALSE(EeeOccluderFilter(h).separated({-100, -100, 0}, {100, -100, 0}, {0, 100, 0}));
}

TEST(EeeOccluderFilter, ProvesNothingWithTheFilterOff) {
  std::array<Vec3<Exact>, 6> h;
  for (int i = 0; i < 6; ++i) h[i] = q({static_cast<double>(i % 2), static_cast<double>(i / 2), 0.5 + i * 0.1});
  set_filter_enabled(false);
  const bool off = EeeOccluderFilter(h).separated({-100, -100, 0}, {100, -100, 0}, {0, 100, 0});
  set_filter_enabled(true);
  EXPECT_FALSE(off);
}

}  // namespace
}  // namespace exactvis
