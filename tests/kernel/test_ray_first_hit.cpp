// ray_first_hit against a brute force over every triangle with the independent rational oracle
// (tests/oracles/rational_geometry: segment_triangle_interval on a segment reaching beyond the scene):
// the first hit of the open ray, its exact parameter, ties to the lowest index. Rays: from vertices, edge
// points and random (also rational) points, towards vertices (through vertices and edges), along axes, in
// random and rational directions, and along triangle planes (coplanar triangles, origin on or off them).
#include "kernel/filtered_predicate.hpp"
#include "kernel/predicate_counters.hpp"
#include "kernel/ray_first_hit.hpp"
#include "kernel/scene_generators.hpp"

#include "oracles/rational_geometry.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

using namespace exactvis;
using oracle::QVec;
using oracle::qvec;
using oracle::segment_triangle_interval;

namespace {

QVec q(const Vec3<Exact>& v) { return {mpq_class(v.x.mpq()), mpq_class(v.y.mpq()), mpq_class(v.z.mpq())}; }
QVec q(const Point3& p) { return qvec(p.x, p.y, p.z); }

struct OracleHit {
  int triangle = -1;
  mpq_class s;
};

OracleHit brute_first_hit(const Scene& scene, const QVec& o, const QVec& d) {
  // a segment o + [0, S] d that leaves every triangle's box: S |d|_inf >= 2^24 (coordinates are below 2^20)
  mpq_class m = 0;
  for (const mpq_class* c : {&d.x, &d.y, &d.z}) m = std::max(m, mpq_class(abs(*c)));
  const mpq_class S = mpq_class(1 << 24) / m;
  const QVec far = o + S * d;
  OracleHit best;
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    const auto& t = scene.triangles[i];
    const auto iv = segment_triangle_interval(o, far, q(scene.corner(t, 0)), q(scene.corner(t, 1)), q(scene.corner(t, 2)));
    if (!iv || iv->second <= 0) continue;  // missed, or met only at the origin (the ray is open)
    const mpq_class s = iv->first * S;
    if (best.triangle < 0 || s < best.s) best = {static_cast<int>(i), s};
  }
  return best;
}

Vec3<Exact> exact(const Point3& p) { return {Exact(p.x), Exact(p.y), Exact(p.z)}; }

// dir_scale multiplies every direction (a tiny scale makes the direction's double enclosures contain 0, so
// ray_first_hit takes its exact cover instead of the interval one).
void check_scene(const std::string& kind, std::int64_t n, std::uint64_t seed, int rays, int* hits, int* coplanar,
                 const Exact& dir_scale = Exact(1)) {
  const Scene scene = generate_scene(kind, n, seed);
  const TriangleIndex index(scene);
  const Box3 box = bounding_box(scene);
  std::mt19937_64 rng(seed);
  auto pick = [&](std::size_t k) { return std::uniform_int_distribution<std::size_t>(0, k - 1)(rng); };
  auto unit = [&] { return std::uniform_real_distribution<double>(0, 1)(rng); };
  auto vertex = [&] { return exact(scene.vertices[pick(scene.vertices.size())]); };
  auto inside = [&] {
    return Vec3<Exact>(Exact(box.lo.x + unit() * (box.hi.x - box.lo.x)), Exact(box.lo.y + unit() * (box.hi.y - box.lo.y)),
                       Exact(box.lo.z + unit() * (box.hi.z - box.lo.z)));
  };
  for (int i = 0; i < rays; ++i) {
    Vec3<Exact> o, d;
    const auto& t = scene.triangles[pick(scene.triangles.size())];
    const Vec3<Exact> a = exact(scene.corner(t, 0)), b = exact(scene.corner(t, 1)), c = exact(scene.corner(t, 2));
    switch (i % 6) {
      case 0: o = vertex(), d = vertex() - o; break;                                  // vertex to vertex
      case 1: o = inside(), d = vertex() - o; break;                                  // through a vertex
      case 2: o = inside(), d = (Exact(1, 3) * (a + b) + Exact(1, 3) * c) - o; break;  // through a triangle
      case 3: o = Exact(1, 2) * (a + b), d = inside() - o; break;                     // from an edge point
      case 4: {  // along the triangle's plane, from a point of the plane (inside, on or off the triangle)
        const Exact u(static_cast<int>(pick(7)) - 2, 3), v(static_cast<int>(pick(7)) - 2, 3);
        o = a + u * (b - a) + v * (c - a);
        d = (pick(2) ? b - a : c - b) + Exact(static_cast<int>(pick(3)) - 1, 2) * (c - a);
        break;
      }
      default: {  // axis-parallel or rational direction from a random or rational point
        o = pick(2) ? inside() : Vec3<Exact>(Exact(static_cast<int>(pick(60)), 7), Exact(static_cast<int>(pick(60)), 7),
                                             Exact(static_cast<int>(pick(60)), 7));
        const int axis = static_cast<int>(pick(4));
        if (axis < 3) d = Vec3<Exact>(), d[axis] = pick(2) ? 1 : -1;
        else d = Vec3<Exact>(Exact(unit() - 0.5), Exact(static_cast<int>(pick(9)) - 4, 5), Exact(unit() - 0.5));
      }
    }
    if (d.x == 0 && d.y == 0 && d.z == 0) continue;
    d = dir_scale * d;
    const RayHit got = ray_first_hit(scene, index, box, o, d);
    const OracleHit want = brute_first_hit(scene, q(o), q(d));
    ASSERT_EQ(got.triangle, want.triangle) << kind << " seed " << seed << " ray " << i;
    if (want.triangle < 0) continue;
    ++*hits;
    if (i % 6 == 4) ++*coplanar;
    ASSERT_EQ(mpq_class(got.s.mpq()), want.s) << kind << " seed " << seed << " ray " << i;
  }
}

TEST(RayFirstHit, MatchesBruteForceOnGeneratedScenes) {
  int hits = 0, coplanar = 0;
  for (const char* kind : {"random", "town", "room", "forest"})
    for (std::uint64_t seed = 1; seed <= 2; ++seed) check_scene(kind, 100, seed, 150, &hits, &coplanar);
  EXPECT_GT(hits, 400);
  EXPECT_GT(coplanar, 50);  // rays along a triangle's plane that hit something
}

TEST(RayFirstHit, TinyDirectionsTakeTheExactCoverAndAgree) {
  Exact tiny(1);
  for (int i = 0; i < 1100; ++i) tiny /= 2;  // 2^-1100: below the smallest double
  int hits = 0, coplanar = 0;
  check_scene("town", 60, 3, 60, &hits, &coplanar, tiny);
  EXPECT_GT(hits, 10);
}

TEST(RayFirstHit, RayLeavingTheBoxAtOnceHitsNothing) {
  // A triangle on the top face of the scene box (z = 1) and a ray from that face going up: the open ray is
  // outside the box at once. The same ray going down hits the bottom triangle.
  Scene s;
  s.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 1}, {4, 0, 1}, {0, 4, 1}};
  s.objects.push_back({"o"});
  s.triangles.push_back({0, {0, 1, 2}, 0});
  s.triangles.push_back({1, {3, 4, 5}, 0});
  const TriangleIndex index(s);
  const Box3 box = bounding_box(s);
  const Vec3<Exact> o(Exact(1), Exact(1), Exact(1));
  EXPECT_EQ(ray_first_hit(s, index, box, o, Vec3<Exact>(Exact(1, 3), Exact(0), Exact(1))).triangle, -1);
  EXPECT_EQ(ray_first_hit(s, index, box, o, Vec3<Exact>(Exact(1, 3), Exact(0), Exact(-1))).triangle, 0);
  EXPECT_EQ(ray_first_hit(s, index, box, Vec3<Exact>(Exact(1), Exact(1), Exact(1, 2)), Vec3<Exact>(Exact(0), Exact(0), Exact(1)))
                .triangle,
            1);
}

// Rays from points A + t (B - A) of a triangle's edge line (t inside and outside [0, 1]) with that edge given
// as RayOriginOnEdgeLine: the triangles through the edge (closed meshes: both faces) are then decided without
// evaluating their plane offset. Directions: towards scene vertices and random points, and along the plane of
// one of the edge's faces (coplanar triangles through the origin), each against the brute force.
TEST(RayFirstHit, OriginOnAKnownEdgeLineAgreesWithBruteForce) {
  int hits = 0, coplanar_hits = 0;
  for (const char* kind : {"town", "room", "random"})
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      const Scene scene = generate_scene(kind, 80, seed);
      const TriangleIndex index(scene);
      const Box3 box = bounding_box(scene);
      std::mt19937_64 rng(seed + 40);
      auto pick = [&](std::size_t k) { return std::uniform_int_distribution<std::size_t>(0, k - 1)(rng); };
      auto unit = [&] { return std::uniform_real_distribution<double>(0, 1)(rng); };
      for (int i = 0; i < 150; ++i) {
        const SceneTriangle& t = scene.triangles[pick(scene.triangles.size())];
        const int k = static_cast<int>(pick(3));
        const int ia = t.v[k], ib = t.v[(k + 1) % 3];
        const Vec3<Exact> a = exact(scene.vertices[ia]), b = exact(scene.vertices[ib]);
        const Vec3<Exact> c = exact(scene.vertices[t.v[(k + 2) % 3]]);
        const Exact u(static_cast<int>(pick(11)) - 2, 7);  // -2/7 .. 8/7
        const Vec3<Exact> o = a + u * (b - a);
        Vec3<Exact> d;
        switch (i % 3) {
          case 0: d = exact(scene.vertices[pick(scene.vertices.size())]) - o; break;
          case 1:
            d = Vec3<Exact>(Exact(box.lo.x + unit() * (box.hi.x - box.lo.x)), Exact(box.lo.y + unit() * (box.hi.y - box.lo.y)),
                            Exact(box.lo.z + unit() * (box.hi.z - box.lo.z))) - o;
            break;
          default: d = (c - o) + Exact(static_cast<int>(pick(5)) - 2, 3) * (b - a);  // in t's plane
        }
        if (d.x == 0 && d.y == 0 && d.z == 0) continue;
        const RayHit got = ray_first_hit(scene, index, box, o, d, {ia, ib});
        const OracleHit want = brute_first_hit(scene, q(o), q(d));
        ASSERT_EQ(got.triangle, want.triangle) << kind << " seed " << seed << " ray " << i;
        if (want.triangle < 0) continue;
        ++hits;
        if (i % 3 == 2) ++coplanar_hits;
        ASSERT_EQ(mpq_class(got.s.mpq()), want.s) << kind << " seed " << seed << " ray " << i;
      }
    }
  EXPECT_GT(hits, 600);
  EXPECT_GT(coplanar_hits, 200);
}

TEST(RayFirstHit, DecisionsAreCountedAndUnchangedWithoutFilters) {
  int hits = 0, coplanar = 0;
  reset_predicate_counters();
  check_scene("town", 80, 7, 60, &hits, &coplanar);
  std::uint64_t calls = 0;
  for (const auto& c : predicate_counters())
    if (c.name.rfind("ray_", 0) == 0) calls += c.calls;
  EXPECT_GT(calls, 1000u);
  set_filter_enabled(false);
  check_scene("town", 80, 7, 60, &hits, &coplanar);
  set_filter_enabled(true);
}

}  // namespace
