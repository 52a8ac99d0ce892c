// Irradiance (Lambert's formula on the exact visible polygons) against numeric integration of
// cos(theta) cos(theta') / (pi r^2) over the light, with the horizon and a blocker.
#include "kernel/triangle_index.hpp"
#include "shadows/backprojection.hpp"
#include "shadows/point_irradiance.hpp"
#include "tests/shadows/shadow_test_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace exactvis::shadows {
namespace {

// Midpoint rule over an axis-aligned rectangle light [x0, x1] x [y0, y1] at height h (normal +-z), receiver
// point p with unit normal n; `hidden(x, y)` removes light points; cosines clamped at 0 (two-sided light).
template <class Hidden>
double integrate(double x0, double x1, double y0, double y1, double h, Point3 p, Point3 n, Hidden hidden) {
  const int N = 800;
  double sum = 0;
  const double dx = (x1 - x0) / N, dy = (y1 - y0) / N;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      const double x = x0 + (i + 0.5) * dx, y = y0 + (j + 0.5) * dy;
      if (hidden(x, y)) continue;
      const Point3 r{x - p.x, y - p.y, h - p.z};
      const double r2 = dot(r, r), rl = std::sqrt(r2);
      const double c1 = std::max(0.0, dot(n, r) / rl), c2 = std::abs(r.z) / rl;
      sum += c1 * c2 / (std::numbers::pi * r2) * dx * dy;
    }
  return sum;
}

TEST(PointIrradiance, UnblockedSquareLightMatchesNumericIntegration) {
  const Scene s = shadow_test::textbook_scene();
  const TriangleIndex index(s);
  for (const Vec3<Exact>& p : {Vec3<Exact>{10, 11, 0}, Vec3<Exact>{-3, 0, 0}, Vec3<Exact>{8, -2, 0}}) {
    const auto bp = backproject(s, index, {4, 5}, p);
    ASSERT_EQ(bp.light_class, LightClass::Lit);
    const double e = point_irradiance(s, p, {0, 0, 1}, bp);
    const Point3 pd{CGAL::to_double(p.x), CGAL::to_double(p.y), 0};
    const double want = integrate(3, 5, 3, 5, 4, pd, {0, 0, 1}, [](double, double) { return false; });
    EXPECT_NEAR(e, want, 1e-5 * want);
    // The receiver's orientation does not matter (two-sided, oriented towards the light).
    EXPECT_DOUBLE_EQ(point_irradiance(s, p, {0, 0, -5}, bp), e);
  }
}

TEST(PointIrradiance, PenumbraMatchesIntegrationOverTheUnhiddenLight) {
  const Scene s = shadow_test::textbook_scene();
  const TriangleIndex index(s);
  const Vec3<Exact> p{Exact(9, 2), Exact(7, 4), 0};
  const auto bp = backproject(s, index, {4, 5}, p);
  ASSERT_EQ(bp.light_class, LightClass::Penumbra);
  const double e = point_irradiance(s, p, {0, 0, 1}, bp);
  // Hidden iff the line crosses z = 2 inside the blocker: ((x + px) / 2, (y + py) / 2) in [3, 5]^2.
  const double px = 4.5, py = 1.75;
  const double want = integrate(3, 5, 3, 5, 4, {px, py, 0}, {0, 0, 1}, [&](double x, double y) {
    const double cx = (x + px) / 2, cy = (y + py) / 2;
    return cx >= 3 && cx <= 5 && cy >= 3 && cy <= 5;
  });
  EXPECT_NEAR(e, want, 2e-3 * want);
}

TEST(PointIrradiance, LightStraddlingTheReceiverPlaneIsClippedAtTheHorizon) {
  // A vertical receiver x = 4 at the point (4, 4, 1) with normal +-x; the light [3, 5]^2 at z = 4 straddles
  // the plane x = 4, its centroid on the plane: the normal stays +x and only the half x > 4 counts.
  const Scene s = shadow_test::textbook_scene();
  const TriangleIndex index(s);
  const Vec3<Exact> p{4, 4, 3};
  const auto bp = backproject(s, index, {4, 5}, p);
  const double e = point_irradiance(s, p, {1, 0, 0}, bp);
  const double want = integrate(3, 5, 3, 5, 4, {4, 4, 3}, {1, 0, 0}, [](double, double) { return false; });
  EXPECT_NEAR(e, want, 1e-3 * want);
  EXPECT_GT(e, 0);
}

}  // namespace
}  // namespace exactvis::shadows
