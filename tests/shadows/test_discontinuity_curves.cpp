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
