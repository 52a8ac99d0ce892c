// shadows/blocker_events: blocker-to-blocker EV events cut penumbra faces where the backprojection's
// topology changes. Oracle: the hand derivation below (similar triangles), no shadows/ code.
//
// Floor z = 0 ([-8, 8]^2), light square [-1, 1]^2 at z = 4, blocker B1 at z = 2: the triangle (0, 0), (-10,
// -10), (-10, 10) (apex V = (0, 0, 2)), blocker B2 at z = 3: the triangle with edge E from (-1/4, -20) to
// (-1/4, 20) and third corner (19.75, 0). Seen from X = (x, y, 0), a point P at height h appears on the light
// plane at X + 4 / h (P - X): B1 as a wedge with apex V' = (-x, -y) opening towards -x', B2 as the half-plane
// x' >= (-1 - x) / 3. For 0 < x < 1, |y| < 1/2 the visible light is
//   x < 1/2: the wedge's tip reaches into B2's half-plane: two pieces (above and below the wedge);
//   x > 1/2: the tip ends before it: one piece around the tip.
// The change happens where V' lies on E's image: x = 1/2, -1 <= y <= 1 (V' inside the light), the EV surface of
// (V, E), neither on the light.
#include "events/light_source.hpp"
#include "kernel/scene_generators.hpp"
#include "shadows/blocker_events.hpp"
#include "shadows/conic_arrangement.hpp"
#include "shadows/shadow_mesh.hpp"
#include "tests/shadows/shadow_test_scenes.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>

namespace exactvis::shadows {
namespace {

using shadow_test::add_object;
using shadow_test::add_quad;
using shadow_test::object_triangles;

Scene two_blocker_scene() {
  Scene s;
  add_quad(s, "floor", {Point3{-8, -8, 0}, Point3{8, -8, 0}, Point3{8, 8, 0}, Point3{-8, 8, 0}});
  add_object(s, "b1", {Point3{0, 0, 2}, Point3{-10, -10, 2}, Point3{-10, 10, 2}}, {{0, 1, 2}});
  add_object(s, "b2", {Point3{-0.25, -20, 3}, Point3{-0.25, 20, 3}, Point3{19.75, 0, 3}}, {{0, 1, 2}});
  add_quad(s, "lamp", {Point3{-1, -1, 4}, Point3{1, -1, 4}, Point3{1, 1, 4}, Point3{-1, 1, 4}});
  return s;
}

int hand_pieces(const Exact& x) { return x < Exact(1, 2) ? 2 : 1; }

TEST(BlockerEvents, TheApexAndTheEdgeGiveTheHandDerivedEvent) {
  const Scene s = two_blocker_scene();
  const EvResult r = blocker_ev_events(s, object_triangles(s, "lamp"));
  const int V = s.triangles[object_triangles(s, "b1")[0]].v[0];
  const auto& b2 = s.triangles[object_triangles(s, "b2")[0]];
  const std::array<int, 2> E{std::min(b2.v[0], b2.v[1]), std::max(b2.v[0], b2.v[1])};
  bool found = false;
  for (const auto& e : r.events) {
    for (const auto& iv : e.intervals) {  // one end on the light, the other not
      const bool fl = iv.front_object >= 4, bl = iv.back_object >= 4;  // lamp triangles have ids 4, 5
      EXPECT_NE(fl, bl);
    }
    if (e.vertex == V && e.edge == E) found = true;
  }
  EXPECT_TRUE(found);
}

// The located face of random points near x = 1/2: every face holds one hand-derived topology with the
// blocker-blocker events, and some face holds both without them (so the check can fail).
int mixed_faces(const Scene& s, bool blocker_events) {
  ShadowOptions opt;
  opt.light = object_triangles(s, "lamp");
  opt.receivers = {0};  // the floor triangle y < x
  opt.vertex_irradiance = false;
  opt.blocker_events = blocker_events;
  const ShadowResult res = compute_shadows(s, opt);
  const ReceiverShadows& rec = res.receivers.at(0);
  const ReceiverFrame frame = receiver_frame(s, rec.triangle);
  const std::vector<ArrangementCurve> curves = arrangement_curves(rec.curves, frame);
  int at_half = 0;
  for (const auto& c : rec.curves) {
    if (c.blocker_blocker) {
      ++at_half;
      for (const auto& p : c.points) {
        EXPECT_EQ(p.x, Exact(1, 2));
        EXPECT_TRUE(p.y >= -1 && p.y <= 1 && p.z == 0);
      }
    }
  }
  EXPECT_EQ(at_half > 0, blocker_events);
  std::mt19937_64 rng(15);
  std::uniform_int_distribution<int> w(1, 999);
  std::vector<std::array<Exact, 2>> queries;
  std::vector<Exact> xs;
  for (int k = 0; k < 300; ++k) {
    const Exact x(w(rng) * 9 + 500, 10000), y(-w(rng) * 45, 100000);  // x in (0.05, 0.95), y in (-0.45, 0)
    xs.push_back(x);
    queries.push_back(frame.to_uv(Vec3<Exact>{x, y, 0}));
  }
  const ReceiverArrangement arr = receiver_arrangement(curves, queries);
  std::map<int, std::set<int>> pieces_by_face;
  for (std::size_t k = 0; k < queries.size(); ++k) pieces_by_face[arr.query_faces[k]].insert(hand_pieces(xs[k]));
  int mixed = 0;
  for (const auto& [f, set] : pieces_by_face) mixed += set.size() > 1;
  // Faces sampled in the probed region are penumbra (visible and hidden parts both non-empty, by hand).
  for (const auto& f : rec.faces)
    if (f.sample.x > Exact(1, 20) && f.sample.x < Exact(19, 20) && f.sample.y > Exact(-9, 20) && f.sample.y < 0) {
      EXPECT_EQ(f.light_class, LightClass::Penumbra);
    }
  return mixed;
}

TEST(BlockerEvents, EveryFaceHasOneBackprojectionTopology) {
  const Scene s = two_blocker_scene();
  EXPECT_EQ(mixed_faces(s, true), 0);
  EXPECT_GT(mixed_faces(s, false), 0);
}

// The cull through the light's tetrahedra (BlockerEvOptions::cull) keeps every event: the same events and
// intervals as the loop over every vertex and edge, on random blocker scenes and generated rooms and towns;
// and it examines fewer pairs there (so the comparison is not of two identical loops).
void expect_same_events(const Scene& s, const std::vector<int>& light, const std::string& name, bool fewer) {
  BlockerEvOptions on, off;
  on.parallel = off.parallel = false;
  off.cull = false;
  const EvResult a = blocker_ev_events(s, light, on), b = blocker_ev_events(s, light, off);
  ASSERT_EQ(a.events.size(), b.events.size()) << name;
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    const auto &ea = a.events[i], &eb = b.events[i];
    ASSERT_EQ(ea.vertex, eb.vertex) << name;
    ASSERT_EQ(ea.edge, eb.edge) << name;
    ASSERT_EQ(ea.intervals.size(), eb.intervals.size()) << name;
    for (std::size_t k = 0; k < ea.intervals.size(); ++k) {
      EXPECT_TRUE(ea.intervals[k].t0 == eb.intervals[k].t0) << name;
      EXPECT_TRUE(ea.intervals[k].t1 == eb.intervals[k].t1) << name;
      EXPECT_EQ(ea.intervals[k].front_object, eb.intervals[k].front_object) << name;
      EXPECT_EQ(ea.intervals[k].back_object, eb.intervals[k].back_object) << name;
    }
  }
  if (fewer) {
    EXPECT_LT(a.stats.pairs, b.stats.pairs) << name;
  }
}

TEST(BlockerEvents, CullThroughTheLightKeepsEveryEvent) {
  std::size_t events = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const Scene s = shadow_test::random_blocker_scene(seed, 6);
    expect_same_events(s, object_triangles(s, "lamp"), "random seed " + std::to_string(seed), false);
    events += blocker_ev_events(s, object_triangles(s, "lamp")).events.size();
  }
  expect_same_events(two_blocker_scene(), object_triangles(two_blocker_scene(), "lamp"), "two blockers", false);
  for (const std::string kind : {"room", "town"}) {
    Scene s = generate_scene(kind, 150, 2);
    const Box3 b = bounding_box(s);
    const double cx = (b.lo.x + b.hi.x) / 2, cy = (b.lo.y + b.hi.y) / 2;
    const double sx = (b.hi.x - b.lo.x) * 0.05, sy = (b.hi.y - b.lo.y) * 0.05;
    const double z = kind == "room" ? b.hi.z - 0.02 * (b.hi.z - b.lo.z) : b.hi.z + 0.5 * (b.hi.z - b.lo.z);
    const auto light = append_light_polygon(s, {{cx - sx, cy - sy, z}, {cx + sx, cy - sy, z}, {cx + sx, cy + sy, z},
                                                {cx - sx, cy + sy, z}})
                           .triangles;
    expect_same_events(s, light, kind, true);
    events += blocker_ev_events(s, light).events.size();
  }
  EXPECT_GT(events, 10u);
}

}  // namespace
}  // namespace exactvis::shadows
