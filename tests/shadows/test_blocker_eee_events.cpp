// shadows/blocker_eee_events: blocker-to-blocker EEE events bound umbra where a hole between three blockers
// closes over the light. Oracle: the hand derivation below (similar triangles), no shadows/ code; and, on
// random scenes, the exact class of random points of every face (every point of a face has its class).
//
// Floor z = 0 ([-8, 8]^2), light square [-1, 1]^2 at z = 4 (object "lamp"), three blockers with one long
// edge each: B1 at z = 2 covering y <= 0 (edge E1 on y = 0), B2 at z = 3 covering x <= 0 (edge E2 on x = 0),
// B3 at z = 1 covering x + y >= 1/4 (edge E3 on x + y = 1/4). Seen from X = (x, y, 0), a point P at height
// h appears on the light plane at X + 4 / h (P - X): B1 as y' <= -y, B2 as x' <= -x / 3, B3 as
// x' + y' >= 1 - 3 (x + y). The visible light is the triangle ("hole") y' > -y, x' > -x / 3,
// x' + y' < 1 - 3 (x + y), non-empty iff its corner (-x / 3, -y) satisfies the third inequality:
// 4 x + 3 y < 3 / 2. Near the probed region (the hole's corner inside the light) X is in penumbra on that
// side and in umbra on the other: the umbra boundary is the line 4 x + 3 y = 3 / 2, where the three edges'
// images are concurrent (a blocker-blocker EEE event; its regulus meets the floor in a line, all three
// edges being horizontal).
#include "shadows/backprojection.hpp"
#include "shadows/blocker_eee_events.hpp"
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

Scene hole_scene() {
  Scene s;
  add_quad(s, "floor", {Point3{-8, -8, 0}, Point3{8, -8, 0}, Point3{8, 8, 0}, Point3{-8, 8, 0}});
  add_object(s, "b1", {Point3{-20, 0, 2}, Point3{20, 0, 2}, Point3{0, -20, 2}}, {{0, 1, 2}});
  add_object(s, "b2", {Point3{0, -20, 3}, Point3{0, 20, 3}, Point3{-20, 0, 3}}, {{0, 1, 2}});
  add_object(s, "b3", {Point3{10.25, -10, 1}, Point3{-9.75, 10, 1}, Point3{10, 10, 1}}, {{0, 1, 2}});
  add_quad(s, "lamp", {Point3{-1, -1, 4}, Point3{1, -1, 4}, Point3{1, 1, 4}, Point3{-1, 1, 4}});
  return s;
}

bool hand_umbra(const Exact& x, const Exact& y) { return 4 * x + 3 * y >= Exact(3, 2); }

TEST(BlockerEeeEvents, TheThreeEdgesGiveTheHandDerivedEvent) {
  const Scene s = hole_scene();
  const EeeResult r = blocker_eee_events(s, object_triangles(s, "lamp"));
  auto edge_of = [&](const std::string& name, int a, int b) {
    const auto& t = s.triangles[object_triangles(s, name)[0]];
    return std::array<int, 2>{std::min(t.v[a], t.v[b]), std::max(t.v[a], t.v[b])};
  };
  std::array<std::array<int, 2>, 3> want{edge_of("b1", 0, 1), edge_of("b2", 0, 1), edge_of("b3", 0, 1)};
  std::sort(want.begin(), want.end());
  bool found = false;
  for (const auto& e : r.events) found = found || e.edges == want;
  EXPECT_TRUE(found);
  EXPECT_GE(r.stats.candidate_triples, 1u);
}

// Random points of the probed region located in the floor triangle's faces: with the blocker-blocker EEE
// events every face holds one hand-derived class, and the curve lies on 4 x + 3 y = 3 / 2; without them
// some face holds both (so the check can fail).
int mixed_faces(const Scene& s, bool blocker_events) {
  ShadowOptions opt;
  opt.light = object_triangles(s, "lamp");
  opt.receivers = {0};  // the floor triangle y < x
  opt.vertex_irradiance = false;
  opt.blocker_events = blocker_events;
  const ShadowResult res = compute_shadows(s, opt);
  const ReceiverShadows& rec = res.receivers.at(0);
  const ReceiverFrame frame = receiver_frame(s, rec.triangle);
  int on_line = 0;
  for (const auto& c : rec.curves)
    if (c.kind == DiscontinuityCurve::Kind::EEE && c.blocker_blocker) {
      ++on_line;
      EXPECT_EQ(c.light_edge, -1);
      for (const auto& p : c.points) EXPECT_EQ(4 * p.x + 3 * p.y, Exact(3, 2));
    }
  EXPECT_EQ(on_line > 0, blocker_events);
  std::mt19937_64 rng(15);
  std::uniform_int_distribution<int> w(0, 9999);
  std::vector<std::array<Exact, 2>> queries;
  std::vector<bool> umbra;
  for (int k = 0; k < 300; ++k) {
    // x in (0.25, 0.5), y in (-0.1, 0): the hole's corner lies inside the light, the floor triangle y < x.
    const Exact x = Exact(1, 4) + Exact(w(rng) + 1, 40002), y = -Exact(w(rng) + 1, 100020);
    umbra.push_back(hand_umbra(x, y));
    queries.push_back(frame.to_uv(Vec3<Exact>{x, y, 0}));
  }
  const ReceiverArrangement arr = receiver_arrangement(arrangement_curves(rec.curves, frame), queries);
  EXPECT_FALSE(arr.failed);
  std::map<int, std::set<bool>> classes;
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const int f = arr.query_faces[k];
    classes[f].insert(umbra[k]);
    if (blocker_events) {  // the face's exact class is the hand class of every point
      EXPECT_EQ(rec.faces.at(f).light_class == LightClass::Umbra, umbra[k]) << k;
    }
  }
  int mixed = 0;
  for (const auto& [f, set] : classes) mixed += set.size() > 1;
  return mixed;
}

TEST(BlockerEeeEvents, TheClosingHoleBoundsTheUmbra) {
  const Scene s = hole_scene();
  EXPECT_EQ(mixed_faces(s, true), 0);
  EXPECT_GT(mixed_faces(s, false), 0);
}

// Floor, `blockers` random horizontal triangles at distinct heights strictly between the floor and a
// triangular light at z = 10. Horizontal edges make every EEE surface meet the floor in a straight line
// (the regulus of three lines parallel to one plane is a hyperbolic paraboloid whose sections parallel to that
// plane are lines), so every receiver arrangement is exact and polygonal: CGAL 5.5's hyperbolic-arc
// construction (docs/theory.md section 11, "When CGAL fails") never enters the check. The light is one
// triangle (a split polygon's inner edge would cut visible regions without any visual event).
Scene horizontal_blocker_scene(unsigned seed, int blockers) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> xy(0, 40);
  Scene s;
  add_quad(s, "floor", {Point3{-10, -10, 0}, Point3{20, -10, 0}, Point3{20, 20, 0}, Point3{-10, 20, 0}});
  std::vector<int> heights{9, 12, 15, 18, 21, 24, 27, 30, 33};
  std::shuffle(heights.begin(), heights.end(), rng);
  for (int b = 0; b < blockers; ++b) {
    std::vector<Point3> v;
    for (int k = 0; k < 3; ++k) v.push_back({xy(rng) / 4.0, xy(rng) / 4.0, heights[b] / 4.0});
    if (cross(v[1] - v[0], v[2] - v[0]).z == 0) {
      --b;
      continue;
    }
    add_object(s, "blocker" + std::to_string(b), v, {{0, 1, 2}});
  }
  add_object(s, "lamp", {Point3{2, 2, 10}, Point3{8, 3, 10}, Point3{4, 8, 10}}, {{0, 1, 2}});
  return s;
}

// The combinatorial type of a backprojection: per light triangle, its visible pieces, holes and vertices.
std::vector<std::array<std::size_t, 3>> topology(const std::vector<VisibleLightPart>& parts) {
  std::vector<std::array<std::size_t, 3>> out;
  for (const auto& p : parts) {
    std::array<std::size_t, 3> t{p.pieces.size(), 0, 0};
    for (const auto& piece : p.pieces) {
      t[1] += piece.holes.size();
      t[2] += piece.outer.size();
      for (const auto& h : piece.holes) t[2] += h.size();
    }
    out.push_back(t);
  }
  return out;
}

// Random scenes with several blockers: random points of each floor triangle, located in the exact
// arrangement; the exact class at each point (backprojection) is its face's class, and so is the
// backprojection's combinatorial type (visible pieces, holes, vertices per light triangle: it changes only
// across visual events of the light, blocker-blocker ones included).
TEST(BlockerEeeEvents, EveryPointOfAFaceHasTheFaceClass) {
  std::mt19937_64 rng(41);
  int points = 0, receivers = 0;
  std::uint64_t bb_eee = 0;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Scene s = horizontal_blocker_scene(100 + seed, 4);
    ShadowOptions opt;
    opt.light = object_triangles(s, "lamp");
    opt.receivers = {0, 1};
    opt.vertex_irradiance = false;
    const ShadowResult r = compute_shadows(s, opt);
    bb_eee += r.stats.blocker_eee_events;
    const TriangleIndex index(s);
    for (const auto& rec : r.receivers) {
      const ReceiverFrame f = receiver_frame(s, rec.triangle);
      std::vector<std::array<Exact, 2>> queries;
      std::vector<Vec3<Exact>> at;
      for (int k = 0; k < 50; ++k) {
        const oracle::QVec q = shadow_test::oracle_uniform_point(s, rec.triangle, rng);
        const Vec3<Exact> p{Exact(q.x.get_mpq_t()), Exact(q.y.get_mpq_t()), Exact(q.z.get_mpq_t())};
        at.push_back(p);
        queries.push_back(f.to_uv(p));
      }
      const ReceiverArrangement arr = receiver_arrangement(arrangement_curves(rec.curves, f), queries);
      ASSERT_FALSE(arr.failed || rec.arrangement_failed) << arr.failure;
      EXPECT_EQ(arr.trimmed_arcs, 0u);
      ++receivers;
      for (std::size_t k = 0; k < queries.size(); ++k) {
        const int fi = arr.query_faces[k];
        ASSERT_GE(fi, 0);
        const Backprojection bp = backproject(s, index, opt.light, at[k]);
        EXPECT_EQ(bp.light_class, rec.faces.at(fi).light_class)
            << "seed " << seed << " receiver " << rec.triangle << " face " << fi << " point " << k;
        EXPECT_EQ(topology(bp.parts), topology(rec.faces.at(fi).visible))
            << "seed " << seed << " receiver " << rec.triangle << " face " << fi << " point " << k;
        ++points;
      }
    }
  }
  EXPECT_EQ(receivers, 6);
  EXPECT_EQ(points, 300);
  EXPECT_GT(bb_eee, 0u);
}

}  // namespace
}  // namespace exactvis::shadows
