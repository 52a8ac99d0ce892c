// shadows/receiver_shaft and the shaft-restricted backprojection: (1) refuting sampling, with the oracle's
// own segment-triangle test (tests/oracles, no shadows/ code): every triangle that an open segment from a
// point of the receiver to a point of a light triangle meets is in the shaft's list for that light
// triangle, at random points and at the corners (the shaft's boundary); (2) the discontinuity mesh is
// identical with and without the restriction (ShadowOptions::shaft_restriction) on random scenes and a
// generated room; (3) the restriction drops something on the room (so (2) compares different blocker lists).
#include "events/light_source.hpp"
#include "kernel/scene_generators.hpp"
#include "shadows/receiver_shaft.hpp"
#include "shadows/shadow_mesh.hpp"
#include "tests/shadows/shadow_test_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace exactvis::shadows {
namespace {

using shadow_test::object_triangles;

// A generated room with a square light under its ceiling (as bench_shadows places it).
Scene lit_room(long triangles, unsigned seed, std::vector<int>* light) {
  Scene scene = generate_scene("room", triangles, seed);
  const Box3 b = bounding_box(scene);
  const double cx = (b.lo.x + b.hi.x) / 2, cy = (b.lo.y + b.hi.y) / 2;
  const double sx = (b.hi.x - b.lo.x) * 0.05, sy = (b.hi.y - b.lo.y) * 0.05, z = b.hi.z - 0.02 * (b.hi.z - b.lo.z);
  *light = append_light_polygon(scene, {{cx - sx, cy - sy, z}, {cx + sx, cy - sy, z}, {cx + sx, cy + sy, z},
                                        {cx - sx, cy + sy, z}})
               .triangles;
  return scene;
}

oracle::QVec corner(const Scene& s, std::int64_t ti, int k) {
  const Point3 p = s.corner(s.triangles[ti], k);
  return oracle::qvec(p.x, p.y, p.z);
}

// Every triangle met by the open segment (p, q) is listed (or is the light triangle itself).
void expect_listed(const Scene& s, const std::vector<std::int64_t>& list, int li, const oracle::QVec& p,
                   const oracle::QVec& q, const std::string& where, int* hits) {
  for (std::size_t ti = 0; ti < s.triangles.size(); ++ti) {
    if (static_cast<int>(ti) == li) continue;
    if (!oracle::oracle_open_segment_meets_closed_triangle(p, q, corner(s, ti, 0), corner(s, ti, 1), corner(s, ti, 2)))
      continue;
    ++*hits;
    EXPECT_TRUE(std::binary_search(list.begin(), list.end(), static_cast<std::int64_t>(ti)))
        << where << ": triangle " << ti << " meets a light segment but is not in the shaft";
  }
}

void check_shaft_by_sampling(const Scene& s, const std::vector<int>& light, const std::string& name,
                             std::size_t max_receivers, int* hits) {
  const TriangleIndex index(s);
  std::mt19937_64 rng(11);
  std::vector<std::int64_t> receivers;
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    if (std::find(light.begin(), light.end(), static_cast<int>(i)) == light.end())
      receivers.push_back(static_cast<std::int64_t>(i));
  std::shuffle(receivers.begin(), receivers.end(), rng);
  if (receivers.size() > max_receivers) receivers.resize(max_receivers);
  for (std::int64_t r : receivers) {
    const ReceiverShaft shaft = receiver_shaft(s, index, light, r);
    ASSERT_EQ(shaft.candidates.size(), light.size());
    for (std::size_t k = 0; k < light.size(); ++k) {
      const auto& list = shaft.candidates[k];
      ASSERT_TRUE(std::is_sorted(list.begin(), list.end()));
      const std::string where = name + " receiver " + std::to_string(r) + " light " + std::to_string(light[k]);
      for (int a = 0; a < 3; ++a)  // corner to corner: segments on the shaft's boundary
        for (int b = 0; b < 3; ++b) expect_listed(s, list, light[k], corner(s, r, a), corner(s, light[k], b), where, hits);
      for (int m = 0; m < 12; ++m)
        expect_listed(s, list, light[k], shadow_test::oracle_uniform_point(s, r, rng),
                      shadow_test::oracle_uniform_point(s, light[k], rng), where, hits);
    }
  }
}

TEST(ReceiverShaft, EveryTriangleMetByALightSegmentIsInTheShaft) {
  int hits = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const Scene s = shadow_test::random_blocker_scene(seed, 6);
    check_shaft_by_sampling(s, object_triangles(s, "lamp"), "random seed " + std::to_string(seed), 2, &hits);
  }
  std::vector<int> light;
  const Scene room = lit_room(150, 2, &light);
  check_shaft_by_sampling(room, light, "room", 25, &hits);
  EXPECT_GT(hits, 50);  // the oracle did find blockers to check
}

TEST(ReceiverShaft, DropsTrianglesOfTheBoxThatMissTheShaft) {
  std::vector<int> light;
  const Scene room = lit_room(300, 1, &light);
  const TriangleIndex index(room);
  std::uint64_t box = 0, kept = 0;
  for (std::size_t r = 0; r < room.triangles.size(); ++r) {
    if (std::find(light.begin(), light.end(), static_cast<int>(r)) != light.end()) continue;
    const ReceiverShaft shaft = receiver_shaft(room, index, light, static_cast<std::int64_t>(r));
    box += shaft.box_candidates;
    for (const auto& c : shaft.candidates) kept += c.size();
  }
  EXPECT_LT(kept, box);
  EXPECT_GT(kept, 0u);
}

void expect_same_polygon(const region::Polygon3& a, const region::Polygon3& b, const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << where;
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(a[i] == b[i]) << where << " vertex " << i;
}

void expect_same_mesh(const ShadowResult& a, const ShadowResult& b, const std::string& name) {
  ASSERT_EQ(a.receivers.size(), b.receivers.size()) << name;
  for (std::size_t i = 0; i < a.receivers.size(); ++i) {
    const auto &ra = a.receivers[i], &rb = b.receivers[i];
    const std::string where = name + " receiver " + std::to_string(ra.triangle);
    ASSERT_EQ(ra.triangle, rb.triangle);
    EXPECT_EQ(ra.curves.size(), rb.curves.size()) << where;
    ASSERT_EQ(ra.faces.size(), rb.faces.size()) << where;
    for (std::size_t f = 0; f < ra.faces.size(); ++f) {
      const auto &fa = ra.faces[f], &fb = rb.faces[f];
      const std::string wf = where + " face " + std::to_string(f);
      EXPECT_EQ(fa.light_class, fb.light_class) << wf;
      EXPECT_TRUE(fa.sample == fb.sample) << wf;
      EXPECT_EQ(fa.fraction_exact, fb.fraction_exact) << wf;
      EXPECT_TRUE(fa.fraction == fb.fraction) << wf;
      EXPECT_EQ(fa.fraction_value, fb.fraction_value) << wf;
      EXPECT_EQ(fa.irradiance, fb.irradiance) << wf;
      EXPECT_EQ(fa.blockers, fb.blockers) << wf;
      ASSERT_EQ(fa.visible.size(), fb.visible.size()) << wf;
      for (std::size_t p = 0; p < fa.visible.size(); ++p) {
        ASSERT_EQ(fa.visible[p].pieces.size(), fb.visible[p].pieces.size()) << wf;
        EXPECT_TRUE(fa.visible[p].visible_area_2d == fb.visible[p].visible_area_2d) << wf;
        for (std::size_t q = 0; q < fa.visible[p].pieces.size(); ++q) {
          expect_same_polygon(fa.visible[p].pieces[q].outer, fb.visible[p].pieces[q].outer, wf);
          ASSERT_EQ(fa.visible[p].pieces[q].holes.size(), fb.visible[p].pieces[q].holes.size()) << wf;
          for (std::size_t h = 0; h < fa.visible[p].pieces[q].holes.size(); ++h)
            expect_same_polygon(fa.visible[p].pieces[q].holes[h], fb.visible[p].pieces[q].holes[h], wf);
        }
      }
    }
    EXPECT_EQ(ra.vertex_irradiance, rb.vertex_irradiance) << where;
  }
}

ShadowResult mesh(const Scene& s, const std::vector<int>& light, bool shaft,
                  const std::vector<std::int64_t>& receivers = {}) {
  ShadowOptions opt;
  opt.light = light;
  opt.receivers = receivers;
  opt.vertex_irradiance = true;
  opt.parallel = false;
  opt.shaft_restriction = shaft;
  return compute_shadows(s, opt);
}

TEST(ReceiverShaft, MeshIsIdenticalWithAndWithoutTheRestriction) {
  std::uint64_t umbra = 0, penumbra = 0;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    // The floor only: CGAL's conic arrangement (CORE) of tilted blockers' EEE curves is slow on the blockers.
    const Scene s = shadow_test::random_blocker_scene(seed, 3);
    const std::vector<int> light = object_triangles(s, "lamp");
    const ShadowResult on = mesh(s, light, true, {0, 1}), off = mesh(s, light, false, {0, 1});
    expect_same_mesh(on, off, "random seed " + std::to_string(seed));
    EXPECT_EQ(on.stats.shaft_outside_points, 0u);
    for (const auto& r : on.receivers)
      for (const auto& f : r.faces) {
        umbra += f.light_class == LightClass::Umbra;
        penumbra += f.light_class == LightClass::Penumbra;
      }
  }
  std::vector<int> light;
  const Scene room = lit_room(120, 3, &light);
  std::vector<std::int64_t> some;  // every fourth triangle (the whole room takes about a minute twice)
  for (std::size_t i = 0; i < room.triangles.size(); i += 4)
    if (std::find(light.begin(), light.end(), static_cast<int>(i)) == light.end()) some.push_back(i);
  const ShadowResult on = mesh(room, light, true, some), off = mesh(room, light, false, some);
  expect_same_mesh(on, off, "room");
  EXPECT_EQ(on.stats.shaft_outside_points, 0u);
  EXPECT_LT(on.stats.shaft_candidates, on.stats.shaft_box_candidates);
  EXPECT_GT(umbra, 0u);
  EXPECT_GT(penumbra, 0u);
}

}  // namespace
}  // namespace exactvis::shadows
