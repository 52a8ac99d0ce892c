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

}  // namespace
}  // namespace exactvis::shadows
