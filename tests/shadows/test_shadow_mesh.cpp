// The discontinuity mesh: the textbook umbra and penumbra exactly as derived by hand, every face's class
// refuted by oracle light sampling at its sample (and at a second random point of the face), D0 contact
// curves, and the EEE conic of a known configuration.
#include "shadows/conic_arrangement.hpp"
#include "shadows/shadow_mesh.hpp"
#include "tests/shadows/shadow_test_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace exactvis::shadows {
namespace {

using shadow_test::object_triangles;

TEST(ShadowMesh, TextbookUmbraAndPenumbraAreTheHandDerivedSquares) {
  const Scene s = shadow_test::textbook_scene();
  ShadowOptions opt;
  opt.light = object_triangles(s, "lamp");
  opt.receivers = {0, 1};
  opt.vertex_irradiance = false;
  const ShadowResult r = compute_shadows(s, opt);
  ASSERT_EQ(r.receivers.size(), 2u);
  std::map<LightClass, Exact> area;  // (u, v) area; the floor triangles have |e1 x e2| = 256
  for (const auto& rec : r.receivers) {
    const ReceiverFrame f = receiver_frame(s, rec.triangle);
    for (const auto& c : rec.curves) {
      // Hand-derived: every EV boundary runs along x or y in {1, 3, 5, 7}, inside [1, 7]^2, order 1 (a light
      // edge parallel to a blocker edge).
      ASSERT_EQ(c.kind, DiscontinuityCurve::Kind::EV);
      EXPECT_EQ(c.order, 1);
      const auto &a = c.points.front(), &b = c.points.back();
      const bool vertical = a.x == b.x, horizontal = a.y == b.y;
      ASSERT_TRUE(vertical != horizontal);
      const Exact k = vertical ? a.x : a.y;
      EXPECT_TRUE(k == 1 || k == 3 || k == 5 || k == 7) << k;
      for (const auto& p : c.points) {
        EXPECT_TRUE(p.x >= 1 && p.x <= 7 && p.y >= 1 && p.y <= 7 && p.z == 0);
      }
    }
    for (std::size_t fi = 0; fi < rec.faces.size(); ++fi) {
      const auto& face = rec.faces[fi];
      area[face.light_class] += face.area_uv;
      EXPECT_NEAR(face.area, CGAL::to_double(face.area_uv) * 256, 1e-9);
      for (std::size_t t = 0; t < rec.mesh.triangles.size(); ++t) {
        if (rec.mesh.triangle_face[t] != static_cast<int>(fi)) continue;
        for (int v : rec.mesh.triangles[t]) {
          const auto p = f.to_3d(rec.mesh.vertices[v][0], rec.mesh.vertices[v][1]);
          if (face.light_class == LightClass::Umbra) {
            EXPECT_TRUE(p.x >= 3 && p.x <= 5 && p.y >= 3 && p.y <= 5);
          }
          if (face.light_class == LightClass::Penumbra) {
            EXPECT_TRUE(p.x >= 1 && p.x <= 7 && p.y >= 1 && p.y <= 7);
          }
        }
      }
      // The face's fraction at its sample is the hand formula.
      EXPECT_EQ(mpq_class(face.fraction.mpq()),
                shadow_test::textbook_fraction(mpq_class(face.sample.x.mpq()), mpq_class(face.sample.y.mpq())));
    }
  }
  EXPECT_EQ(area[LightClass::Umbra] * 256, Exact(4));       // [3, 5]^2
  EXPECT_EQ(area[LightClass::Penumbra] * 256, Exact(32));   // [1, 7]^2 minus the umbra
  EXPECT_EQ(area[LightClass::Lit] * 256, Exact(256 - 36));  // the rest of the floor
}

// Oracle light sampling at every face's sample and at a second random point of the face.
TEST(ShadowMesh, FaceClassesSurviveOracleLightSampling) {
  std::mt19937_64 rng(7);
  int faces = 0, second_points = 0;
  for (unsigned seed = 1; seed <= 2; ++seed) {
    const Scene s = shadow_test::random_blocker_scene(seed, 2);
    ShadowOptions opt;
    opt.light = object_triangles(s, "lamp");
    opt.receivers = {0, 1};
    opt.vertex_irradiance = false;
    const ShadowResult r = compute_shadows(s, opt);
    for (const auto& rec : r.receivers) {
      const ReceiverFrame f = receiver_frame(s, rec.triangle);
      // At most 24 faces per receiver (chosen at random) keep the test short.
      std::vector<std::size_t> chosen;
      for (std::size_t fi = 0; fi < rec.faces.size(); ++fi) chosen.push_back(fi);
      std::shuffle(chosen.begin(), chosen.end(), rng);
      if (chosen.size() > 24) chosen.resize(24);
      for (std::size_t fi : chosen) {
        const auto& face = rec.faces[fi];
        std::vector<oracle::QVec> at{shadow_test::oracle_point(face.sample)};
        // A second point: strictly inside a random triangle of the mesh mapped to the face, kept when the
        // exact arrangement locates it in the face (near an arc a chord triangle can stick out of it).
        std::vector<std::size_t> tris;
        for (std::size_t t = 0; t < rec.mesh.triangles.size(); ++t)
          if (rec.mesh.triangle_face[t] == static_cast<int>(fi)) tris.push_back(t);
        if (!tris.empty()) {
          const auto& tri = rec.mesh.triangles[tris[rng() % tris.size()]];
          std::uniform_int_distribution<long> w(1, 1000);
          const long w0 = w(rng), w1 = w(rng), w2 = w(rng);
          const Exact sum(w0 + w1 + w2);
          std::array<Exact, 2> uv{0, 0};
          for (int k = 0; k < 2; ++k)
            uv[k] = (Exact(w0) * rec.mesh.vertices[tri[0]][k] + Exact(w1) * rec.mesh.vertices[tri[1]][k] +
                     Exact(w2) * rec.mesh.vertices[tri[2]][k]) / sum;
          bool in_face = true;
          if (!rec.arrangement_failed) {
            const ReceiverArrangement located = receiver_arrangement(arrangement_curves(rec.curves, f), {uv});
            in_face = located.query_faces.at(0) == static_cast<int>(fi);
          }
          if (in_face) at.push_back(shadow_test::oracle_point(f.to_3d(uv[0], uv[1])));
        }
        for (std::size_t a = 0; a < at.size(); ++a) {
          int vis = 0;
          const int n = 80;
          for (int m = 0; m < n; ++m) {
            const int lt = opt.light[m % opt.light.size()];
            vis += shadow_test::oracle_visible(s, at[a], shadow_test::oracle_uniform_point(s, lt, rng));
          }
          const std::string where = "seed " + std::to_string(seed) + " face " + std::to_string(fi) +
                                    (a == 0 ? " sample" : " second point");
          if (face.light_class == LightClass::Umbra) {
            EXPECT_EQ(vis, 0) << where;
          }
          if (face.light_class == LightClass::Lit) {
            EXPECT_EQ(vis, n) << where;
          }
          if (a == 0 && face.light_class == LightClass::Penumbra) {
            // Both light triangles have equal area, so uniform per-triangle sampling is uniform on the light.
            const double f0 = face.fraction_value, sigma = std::sqrt(f0 * (1 - f0) / n);
            EXPECT_NEAR(double(vis) / n, f0, 5 * sigma + 1.0 / n) << where;
          }
          if (a == 1) ++second_points;
        }
        ++faces;
      }
    }
  }
  EXPECT_GT(faces, 20);
  EXPECT_GT(second_points, 20);
}

// Every face's class at its sample and at a random second point, against oracle light sampling (umbra: no
// sample visible; lit: all). Returns the number of faces checked.
int check_faces_with_oracle(const Scene& s, const ShadowOptions& opt, const ShadowResult& r, std::mt19937_64& rng,
                            int samples) {
  int faces = 0;
  for (const auto& rec : r.receivers) {
    const ReceiverFrame f = receiver_frame(s, rec.triangle);
    for (std::size_t fi = 0; fi < rec.faces.size(); ++fi) {
      const auto& face = rec.faces[fi];
      std::vector<oracle::QVec> at{shadow_test::oracle_point(face.sample)};
      for (std::size_t t = 0; t < rec.mesh.triangles.size(); ++t)
        if (rec.mesh.triangle_face[t] == static_cast<int>(fi)) {
          const auto& tri = rec.mesh.triangles[t];
          std::array<Exact, 2> uv;
          for (int k = 0; k < 2; ++k)
            uv[k] = (Exact(2) * rec.mesh.vertices[tri[0]][k] + Exact(3) * rec.mesh.vertices[tri[1]][k] +
                     Exact(5) * rec.mesh.vertices[tri[2]][k]) / Exact(10);
          if (rec.arrangement_failed ||
              receiver_arrangement(arrangement_curves(rec.curves, f), {uv}).query_faces.at(0) == static_cast<int>(fi))
            at.push_back(shadow_test::oracle_point(f.to_3d(uv[0], uv[1])));
          break;
        }
      for (const auto& p : at) {
        int vis = 0;
        for (int m = 0; m < samples; ++m)
          vis += shadow_test::oracle_visible(
              s, p, shadow_test::oracle_uniform_point(s, opt.light[m % opt.light.size()], rng));
        if (face.light_class == LightClass::Umbra) {
          EXPECT_EQ(vis, 0) << "face " << fi;
        }
        if (face.light_class == LightClass::Lit) {
          EXPECT_EQ(vis, samples) << "face " << fi;
        }
      }
      ++faces;
    }
  }
  return faces;
}

TEST(ShadowMesh, DegenerateScenesCoplanarDecalAndBlockerSharingALightVertex) {
  std::mt19937_64 rng(11);
  {
    // A decal lying on the floor under the blocker: coplanar with the receiver, it hides nothing and adds no
    // curve; the umbra stays [3, 5]^2.
    Scene s = shadow_test::textbook_scene();
    shadow_test::add_object(s, "decal", {{2, 2, 0}, {6, 2, 0}, {2, 6, 0}}, {{0, 1, 2}});
    ShadowOptions opt;
    opt.light = {4, 5};
    opt.receivers = {0, 1};
    opt.vertex_irradiance = false;
    const ShadowResult r = compute_shadows(s, opt);
    Exact umbra = 0;
    for (const auto& rec : r.receivers) {
      for (const auto& c : rec.curves) EXPECT_NE(c.blocker, 6);
      for (const auto& f : rec.faces)
        if (f.light_class == LightClass::Umbra) umbra += f.area_uv * 256;
    }
    EXPECT_EQ(umbra, Exact(4));
    EXPECT_GT(check_faces_with_oracle(s, opt, r, rng, 40), 10);
  }
  {
    // A vertical blocker hanging from a light corner (shared vertex id with the light) and one touching the
    // floor with an edge.
    Scene s = shadow_test::textbook_scene();
    const int corner = s.triangles[4].v[0];  // (3, 3, 4)
    s.vertices.push_back({6, 3, 1});
    s.vertices.push_back({3, 6, 1});
    const int a = static_cast<int>(s.vertices.size()) - 2;
    s.objects.push_back({"hanging"});
    s.triangles.push_back({6, {corner, a, a + 1}, static_cast<int>(s.objects.size()) - 1});
    shadow_test::add_object(s, "fin", {{8, 0, 0}, {8, 4, 0}, {8, 2, 3}}, {{0, 1, 2}});
    s.faces_read = static_cast<std::int64_t>(s.triangles.size());
    ShadowOptions opt;
    opt.light = {4, 5};
    opt.receivers = {0, 1};
    opt.vertex_irradiance = false;
    const ShadowResult r = compute_shadows(s, opt);
    int d0 = 0;
    for (const auto& rec : r.receivers)
      for (const auto& c : rec.curves) d0 += c.order == 0 && c.blocker == 7;
    EXPECT_GE(d0, 1);  // the fin's floor edge
    EXPECT_GT(check_faces_with_oracle(s, opt, r, rng, 40), 10);
  }
}

TEST(ShadowMesh, BoxOnTheFloorGivesContactCurvesAndUmbraUnderIt) {
  Scene s = shadow_test::textbook_scene();
  s.triangles.resize(2);  // floor only
  s.objects.resize(1);
  const int base = static_cast<int>(s.vertices.size());
  // A closed box [4, 6] x [4, 6] x [0, 1] resting on the floor (no bottom face), and the light at z = 4.
  const std::vector<Point3> v{{4, 4, 0}, {6, 4, 0}, {6, 6, 0}, {4, 6, 0}, {4, 4, 1}, {6, 4, 1}, {6, 6, 1}, {4, 6, 1}};
  shadow_test::add_object(s, "box", v,
                          {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7},
                           {4, 5, 6}, {4, 6, 7}});
  (void)base;
  shadow_test::add_quad(s, "lamp", {Point3{3, 3, 4}, Point3{5, 3, 4}, Point3{5, 5, 4}, Point3{3, 5, 4}});
  ShadowOptions opt;
  opt.light = object_triangles(s, "lamp");
  opt.receivers = {0, 1};
  opt.vertex_irradiance = false;
  const ShadowResult r = compute_shadows(s, opt);
  int d0 = 0;
  Exact umbra = 0;
  for (const auto& rec : r.receivers) {
    for (const auto& c : rec.curves)
      if (c.order == 0) {
        ++d0;
        for (const auto& p : c.points) EXPECT_TRUE(p.x >= 4 && p.x <= 6 && p.y >= 4 && p.y <= 6 && p.z == 0);
      }
    for (const auto& f : rec.faces)
      if (f.light_class == LightClass::Umbra) umbra += f.area_uv * 256;
  }
  EXPECT_GE(d0, 4);  // the four sides of the footprint (split by the floor's diagonal)
  EXPECT_GE(umbra, Exact(4));  // at least the footprint
}

}  // namespace
}  // namespace exactvis::shadows
