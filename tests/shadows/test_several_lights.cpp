// Several lights at once (issue #15: "one or more convex polygonal area lights"): the textbook floor under the
// horizontal lamp and a second, tilted lamp. Oracles: light sampling by area over both lamps (umbra: no
// sample visible; lit: all; penumbra: the fraction within the sampling error), and the per-light
// backprojections at the same point (fractions and irradiance are the area-weighted / plain sums).
#include "kernel/triangle_index.hpp"
#include "shadows/backprojection.hpp"
#include "shadows/point_irradiance.hpp"
#include "shadows/shadow_mesh.hpp"
#include "tests/shadows/shadow_test_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

namespace exactvis::shadows {
namespace {

using shadow_test::object_triangles;

double triangle_area(const Scene& s, int t) {
  const Point3 a = s.corner(s.triangles[t], 0), b = s.corner(s.triangles[t], 1), c = s.corner(s.triangles[t], 2);
  const Point3 n = cross(b - a, c - a);
  return 0.5 * std::sqrt(dot(n, n));
}

TEST(SeveralLights, TwoLampsInDifferentPlanesAgreeWithSamplingAndWithEachLampAlone) {
  Scene s = shadow_test::textbook_scene();
  // A 5 x 4 lamp tilted by atan(4/3) beside the blocker, not in the first lamp's plane.
  shadow_test::add_quad(s, "lamp2", {Point3{7, 2, 5}, Point3{7, 6, 5}, Point3{10, 6, 9}, Point3{10, 2, 9}});
  const std::vector<int> lamp = object_triangles(s, "lamp"), lamp2 = object_triangles(s, "lamp2");
  ShadowOptions opt;
  opt.light = lamp;
  opt.light.insert(opt.light.end(), lamp2.begin(), lamp2.end());
  opt.receivers = {0, 1};
  opt.vertex_irradiance = false;
  const ShadowResult r = compute_shadows(s, opt);
  ShadowOptions one = opt;
  one.light = lamp;
  const ShadowResult r1 = compute_shadows(s, one);

  const TriangleIndex index(s);
  std::vector<double> areas;
  double total_area = 0;
  for (int t : opt.light) areas.push_back(triangle_area(s, t)), total_area += areas.back();
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> pick(0, total_area);
  std::map<LightClass, int> classes;
  std::size_t faces = 0, faces1 = 0;
  for (const auto& rec : r1.receivers) faces1 += rec.faces.size();
  for (const auto& rec : r.receivers) {
    for (std::size_t fi = 0; fi < rec.faces.size(); ++fi) {
      const auto& face = rec.faces[fi];
      ++faces;
      ++classes[face.light_class];
      const std::string where = "receiver " + std::to_string(rec.triangle) + " face " + std::to_string(fi);
      EXPECT_FALSE(face.fraction_exact) << where;  // two planes: the fraction is a double of exact areas
      // Each lamp alone at the same point: the fraction is the area-weighted mean, the irradiance the sum.
      const Backprojection b1 = backproject(s, index, lamp, face.sample), b2 = backproject(s, index, lamp2, face.sample);
      const double a1 = areas[0] + areas[1], a2 = areas[2] + areas[3];
      EXPECT_NEAR(face.fraction_value, (a1 * b1.fraction_value + a2 * b2.fraction_value) / (a1 + a2), 1e-12) << where;
      const Vec3<Exact> n{0, 0, 1};
      EXPECT_NEAR(face.irradiance,
                  point_irradiance(s, face.sample, n, b1) + point_irradiance(s, face.sample, n, b2), 1e-12)
          << where;
      // Light sampling by area over both lamps.
      const oracle::QVec p = shadow_test::oracle_point(face.sample);
      const int m = 120;
      int vis = 0;
      for (int k = 0; k < m; ++k) {
        double x = pick(rng);
        std::size_t t = 0;
        while (t + 1 < areas.size() && x >= areas[t]) x -= areas[t++];
        vis += shadow_test::oracle_visible(s, p, shadow_test::oracle_uniform_point(s, opt.light[t], rng));
      }
      if (face.light_class == LightClass::Umbra) {
        EXPECT_EQ(vis, 0) << where;
      }
      if (face.light_class == LightClass::Lit) {
        EXPECT_EQ(vis, m) << where;
      }
      if (face.light_class == LightClass::Penumbra) {
        const double f0 = face.fraction_value, sigma = std::sqrt(f0 * (1 - f0) / m);
        EXPECT_NEAR(double(vis) / m, f0, 5 * sigma + 1.0 / m) << where;
      }
    }
  }
  // The second lamp adds its own curves: more faces than under the first lamp alone; both lamps light part
  // of the floor and the blocker's umbra under the first lamp is partly lit by the second.
  EXPECT_GT(faces, faces1);
  EXPECT_GT(classes[LightClass::Lit], 0);
  EXPECT_GT(classes[LightClass::Penumbra], 0);
}

}  // namespace
}  // namespace exactvis::shadows
