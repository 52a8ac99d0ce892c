// Discontinuity curves: the EEE conic of a hand-solved configuration (two skew blocker edges and a light
// edge), EV curves' generators against the light-restricted events, and D0 contacts.
#include "kernel/triangle_index.hpp"
#include "shadows/discontinuity_curves.hpp"
#include "shadows/shadow_mesh.hpp"
#include "tests/shadows/shadow_test_scenes.hpp"

#include <gtest/gtest.h>

namespace exactvis::shadows {
namespace {

// Blocker edges l1 = {(x, 0, 2)}, l2 = {(s, s, 3 + s)}, light edge l3 = {(0, y, 4)}; floor z = 0. A line
// meeting all three passes through (a, 0, 2), (s, s, 3 + s), (0, b, 4) with a = 2s / (1 - s), b = 2s / (1 + s)
// and meets the floor at (4s / (1 - s), -2s / (1 + s), 0): the hyperbola xy + x + 2y = 0.
Scene eee_scene() {
  Scene s;
  shadow_test::add_object(s, "floor", {{-20, -20, 0}, {40, -20, 0}, {-20, 40, 0}}, {{0, 1, 2}});
  shadow_test::add_object(s, "b1", {{-1, 0, 2}, {3, 0, 2}, {1, -2, 2}}, {{0, 1, 2}});
  shadow_test::add_object(s, "b2", {{0, 0, 3}, {0.75, 0.75, 3.75}, {0.75, 1.5, 3}}, {{0, 1, 2}});
  shadow_test::add_object(s, "lamp", {{0, -2, 4}, {0, 2, 4}, {-2, 0, 4}}, {{0, 1, 2}});
  return s;
}

TEST(DiscontinuityCurves, EeeConicOfTwoSkewBlockerEdgesAndALightEdgeIsTheHandDerivedHyperbola) {
  const Scene s = eee_scene();
  ShadowOptions opt;
  opt.light = {3};
  opt.receivers = {0};
  opt.vertex_irradiance = false;
  const ShadowResult r = compute_shadows(s, opt);
  const std::array<std::array<int, 2>, 3> want{{{3, 4}, {6, 7}, {9, 10}}};
  int found = 0;
  for (const auto& c : r.receivers[0].curves) {
    if (c.kind != DiscontinuityCurve::Kind::EEE || c.edges != want) continue;
    ++found;
    EXPECT_EQ(c.order, 2);
    EXPECT_EQ(c.light_edge, 2);
    ASSERT_GE(c.points.size(), 3u);
    for (const auto& p : c.points) {
      EXPECT_EQ(p.z, Exact(0));
      EXPECT_EQ(p.x * p.y + p.x + 2 * p.y, Exact(0)) << p.x << " " << p.y;
    }
    // In the floor's frame x = -20 + 60u, y = -20 + 60v the hyperbola is 3600uv - 1140u - 1080v + 340 = 0.
    const std::array<Exact, 6> hand{0, 3600, 0, -1140, -1080, 340};
    const Exact scale = c.conic[1] / hand[1];
    ASSERT_NE(scale, Exact(0));
    for (int k = 0; k < 6; ++k) EXPECT_EQ(c.conic[k], scale * hand[k]) << k;
  }
  EXPECT_EQ(found, 1);
}

TEST(DiscontinuityCurves, EvCurvesHaveTheGeneratorsOfLightRestrictedEvents) {
  const Scene s = shadow_test::textbook_scene();
  const TriangleIndex index(s);
  EvOptions evo;
  evo.light_triangles = {4, 5};
  const EvResult ev = enumerate_ev_events(s, evo);
  const auto curves = event_curves(s, index, {4, 5}, ev, {}, {0, 1});
  int n = 0;
  for (const auto& [rid, list] : curves)
    for (const auto& c : list) {
      bool match = false;
      for (const auto& e : ev.events)
        if (e.vertex == c.vertex && e.edge == c.edge)
          for (const auto& iv : e.intervals) match |= iv.t0 == c.t0 && iv.t1 == c.t1;
      EXPECT_TRUE(match);
      // Exactly one generator is on the light (vertex ids 8..11).
      EXPECT_NE(c.vertex >= 8, c.edge[0] >= 8);
      ++n;
    }
  EXPECT_EQ(n, 36);  // the curves reaching the floor (the JSON of docs/cli.md lists them)
}

// EEE curves against the events' intervals: every light-restricted EEE curve has the generators of an EEE
// event and lies inside one of its free intervals, and each of its interior points (at rational parameters
// inside the run) lies on a line meeting the three edges' segments at a parameter of E1 in the curve's range.
// The line through X meeting the lines of E1 and E2 is recomputed here (planes through X), independently of
// the events' and the conic's code.
TEST(DiscontinuityCurves, EeeCurvesHaveTheGeneratorsAndLinesOfLightRestrictedEvents) {
  int curves = 0, points = 0;
  for (unsigned seed : {1u, 2u, 3u}) {
    const Scene s = seed == 1 ? eee_scene() : shadow_test::random_blocker_scene(seed, 4);
    const std::vector<int> light = seed == 1 ? std::vector<int>{3} : shadow_test::object_triangles(s, "lamp");
    const TriangleIndex index(s);
    EvOptions evo;
    evo.light_triangles = light;
    EeeOptions eeo;
    eeo.light_triangles = light;
    const EvResult ev = enumerate_ev_events(s, evo);
    const EeeResult eee = enumerate_eee_events(s, eeo);
    const auto all = event_curves(s, index, light, ev, eee, {0});
    auto pos = [&](int v) { return Vec3<Exact>{Exact(s.vertices[v].x), Exact(s.vertices[v].y), Exact(s.vertices[v].z)}; };
    for (const auto& [rid, list] : all)
      for (const auto& c : list) {
        if (c.kind != DiscontinuityCurve::Kind::EEE) continue;
        ++curves;
        EXPECT_GE(c.light_edge, 0);
        const EeeEvent* event = nullptr;
        for (const auto& e : eee.events)
          if (e.edges == c.edges) event = &e;
        ASSERT_NE(event, nullptr) << "seed " << seed;
        bool inside = false;
        for (const auto& iv : event->intervals) inside |= iv.t0 <= c.t0 && c.t1 <= iv.t1;
        EXPECT_TRUE(inside) << "seed " << seed;
        // Exactly one generator edge is on the light, the one named light_edge.
        for (int k = 0; k < 3; ++k) {
          bool on_light = false;
          for (int t : light)
            for (int a = 0; a < 3; ++a)
              for (int b = 0; b < 3; ++b)
                on_light |= s.triangles[t].v[a] == c.edges[k][0] && s.triangles[t].v[b] == c.edges[k][1];
          EXPECT_EQ(on_light, k == c.light_edge) << "seed " << seed << " edge " << k;
        }
        std::array<Vec3<Exact>, 3> A, d;
        for (int k = 0; k < 3; ++k) A[k] = pos(c.edges[k][0]), d[k] = pos(c.edges[k][1]) - A[k];
        for (std::size_t i = 1; i + 1 < c.points.size(); ++i) {
          const Vec3<Exact>& X = c.points[i];
          EXPECT_EQ(X.z, Exact(0));  // on the floor
          const Vec3<Exact> dir = cross(cross(A[0] - X, d[0]), cross(A[1] - X, d[1]));
          ASSERT_NE(dir, (Vec3<Exact>{0, 0, 0}));
          EXPECT_EQ(dot(cross(A[2] - X, d[2]), dir), Exact(0)) << "seed " << seed;  // meets E3's line
          // Parameters of the line's meeting points on the three edges' lines: X + s dir = A_k + t d_k.
          std::array<Exact, 3> t;
          for (int k = 0; k < 3; ++k) {
            const Vec3<Exact> n = cross(d[k], dir);
            ASSERT_NE(n, (Vec3<Exact>{0, 0, 0}));
            t[k] = dot(cross(X - A[k], dir), n) / dot(n, n);
            EXPECT_TRUE(t[k] > 0 && t[k] < 1) << "seed " << seed << " edge " << k << " t " << t[k];
          }
          EXPECT_TRUE(c.t0 < RootNumber(t[0]) && RootNumber(t[0]) < c.t1) << "seed " << seed << " t " << t[0];
          ++points;
        }
      }
  }
  EXPECT_GE(curves, 3);
  EXPECT_GE(points, 30);
}

TEST(DiscontinuityCurves, ContactCurvesOfAPiercingBlocker) {
  Scene s = shadow_test::textbook_scene();
  // A triangle piercing the floor along the segment y = 2, x in [0, 4].
  shadow_test::add_object(s, "spike", {{0, 2, -1}, {4, 2, -1}, {2, 2, 3}}, {{0, 1, 2}});
  const TriangleIndex index(s);
  std::vector<DiscontinuityCurve> all;
  for (std::int64_t r : {0, 1})
    for (auto& c : contact_curves(s, index, {4, 5}, r)) all.push_back(c);
  Exact length = 0;
  for (const auto& c : all) {
    EXPECT_EQ(c.order, 0);
    EXPECT_EQ(c.blocker, 6);
    for (const auto& p : c.points) EXPECT_EQ(p.y, Exact(2));
    length += CGAL::abs(c.points[1].x - c.points[0].x);
  }
  // z = 0 cuts the spike at x in [0.5, 3.5] (edges from (0,2,-1)/(4,2,-1) to (2,2,3)).
  EXPECT_EQ(length, Exact(3));
}

}  // namespace
}  // namespace exactvis::shadows
