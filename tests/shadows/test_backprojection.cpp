// Backprojection: the textbook configuration against the hand-derived fraction, and the exact visible
// polygons against light sampling with the independent oracle (every sample's visibility must match its
// membership in the visible polygons, exactly).
#include "kernel/triangle_index.hpp"
#include "shadows/backprojection.hpp"
#include "tests/shadows/shadow_test_scenes.hpp"

#include <gtest/gtest.h>

namespace exactvis::shadows {
namespace {

using shadow_test::oracle_point;

std::vector<int> object_triangles(const Scene& s, const std::string& name) {
  std::vector<int> out;
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    if (s.objects[s.triangles[i].object].name == name) out.push_back(static_cast<int>(i));
  return out;
}

// Crossing-parity membership in the 2D chart; nullopt when q is on a boundary edge (measure zero).
std::optional<bool> in_visible(const PlaneChart& ch, const std::vector<VisiblePolygon>& pieces, const Vec3<Exact>& q) {
  const auto p = ch.to_2d(q);
  int crossings = 0;
  auto loop = [&](const region::Polygon3& l) -> bool {
    for (std::size_t k = 0; k < l.size(); ++k) {
      const auto a = ch.to_2d(l[k]), b = ch.to_2d(l[(k + 1) % l.size()]);
      const Exact cr = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
      if (cr == 0 && std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= p[1] &&
          p[1] <= std::max(a[1], b[1]))
        return false;  // on the edge
      if ((a[1] > p[1]) != (b[1] > p[1])) {
        const Exact x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
        if (x > p[0]) ++crossings;
      }
    }
    return true;
  };
  for (const auto& pc : pieces) {
    if (!loop(pc.outer)) return std::nullopt;
    for (const auto& h : pc.holes)
      if (!loop(h)) return std::nullopt;
  }
  return crossings % 2 == 1;
}

TEST(Backprojection, TextbookFractionsMatchTheHandDerivation) {
  const Scene s = shadow_test::textbook_scene();
  const TriangleIndex index(s);
  const auto light = object_triangles(s, "lamp");
  ASSERT_EQ(light.size(), 2u);
  int umbra = 0, pen = 0, lit = 0;
  for (int i = -4; i <= 40; ++i)
    for (int j = -4; j <= 40; j += 3) {
      const Exact px(i, 4), py(j, 4);
      const auto bp = backproject(s, index, light, {px, py, 0});
      const mpq_class want = shadow_test::textbook_fraction(mpq_class(px.mpq()), mpq_class(py.mpq()));
      ASSERT_TRUE(bp.fraction_exact);
      EXPECT_EQ(mpq_class(bp.fraction.mpq()), want) << "at " << px << ", " << py;
      const LightClass c = want == 0 ? LightClass::Umbra : (want == 1 ? LightClass::Lit : LightClass::Penumbra);
      EXPECT_EQ(bp.light_class, c) << "at " << px << ", " << py;
      (c == LightClass::Umbra ? umbra : c == LightClass::Lit ? lit : pen)++;
      if (c != LightClass::Lit) {
        EXPECT_FALSE(bp.blockers.empty());
      } else {
        EXPECT_TRUE(bp.blockers.empty());
      }
    }
  EXPECT_GT(umbra, 0);
  EXPECT_GT(pen, 0);
  EXPECT_GT(lit, 0);
}

// Every light sample is visible (oracle) exactly when it lies in the visible polygons.
TEST(Backprojection, VisiblePolygonsAgreeWithOracleLightSamples) {
  std::mt19937_64 rng(20261202);
  int checked = 0, visible_samples = 0, hidden_samples = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const Scene s = shadow_test::random_blocker_scene(seed, 6);
    const TriangleIndex index(s);
    const auto light = object_triangles(s, "lamp");
    for (int k = 0; k < 6; ++k) {
      const oracle::QVec po = shadow_test::oracle_random_point(s, k % 2, rng);
      const Vec3<Exact> p{Exact(po.x.get_mpq_t()), Exact(po.y.get_mpq_t()), Exact(po.z.get_mpq_t())};
      const auto bp = backproject(s, index, light, p);
      int vis = 0, total = 0;
      for (const auto& part : bp.parts) {
        for (int m = 0; m < 40; ++m) {
          const oracle::QVec q = shadow_test::oracle_random_point(s, part.light_triangle, rng);
          const Vec3<Exact> qe{Exact(q.x.get_mpq_t()), Exact(q.y.get_mpq_t()), Exact(q.z.get_mpq_t())};
          const auto in = in_visible(part.chart, part.pieces, qe);
          if (!in) continue;
          const bool v = shadow_test::oracle_visible(s, po, q);
          ASSERT_EQ(*in, v) << "seed " << seed << " point " << k;
          vis += v;
          ++total;
          ++checked;
        }
      }
      visible_samples += vis;
      hidden_samples += total - vis;
      if (bp.light_class == LightClass::Umbra) {
        EXPECT_EQ(vis, 0);
      }
      if (bp.light_class == LightClass::Lit) {
        EXPECT_EQ(vis, total);
      }
      if (bp.light_class != LightClass::Umbra) {
        // The witness of lightcheck: a point strictly inside a visible piece sees p.
        for (const auto& part : bp.parts)
          if (!part.pieces.empty()) {
            const auto q = interior_point(part.chart, part.pieces.front());
            EXPECT_TRUE(shadow_test::oracle_visible(s, po, oracle_point(q)));
            EXPECT_EQ(in_visible(part.chart, part.pieces, q), std::optional<bool>(true));
          }
      }
    }
  }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(visible_samples, 100);
  EXPECT_GT(hidden_samples, 100);
}

TEST(Backprojection, BlockerThroughThePointOrInTheLightPlaneHidesNothing) {
  Scene s = shadow_test::textbook_scene();
  // A vertical wall through p = (8, 8, 0) and a decal in the light's plane.
  shadow_test::add_quad(s, "wall", {Point3{8, 0, 0}, Point3{8, 16, 0}, Point3{8, 16, 6}, Point3{8, 0, 6}});
  shadow_test::add_quad(s, "decal", {Point3{3, 3, 4}, Point3{4, 3, 4}, Point3{4, 4, 4}, Point3{3, 4, 4}});
  const TriangleIndex index(s);
  const auto light = object_triangles(s, "lamp");
  const auto bp = backproject(s, index, light, {8, 8, 0});
  EXPECT_EQ(bp.light_class, LightClass::Lit);
  EXPECT_EQ(bp.fraction, Exact(1));
}

}  // namespace
}  // namespace exactvis::shadows
