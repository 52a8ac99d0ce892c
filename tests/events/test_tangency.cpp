// Vertex rule (b) on a non-convex closed solid, against an independent inside/outside test.
#include "events/scene_adjacency.hpp"
#include "events/tangency.hpp"

#include <gtest/gtest.h>
#include <gmpxx.h>

#include <random>

namespace exactvis {
namespace {

// L-shaped prism: the L polygon (0,0),(2,0),(2,1),(1,1),(1,2),(0,2) extruded over z in [0, 1], closed.
Scene l_prism() {
  const double L[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  Scene s;
  for (int z = 0; z < 2; ++z)
    for (const auto& p : L) s.vertices.push_back({p[0], p[1], double(z)});
  std::vector<std::array<int, 3>> t;
  // Bottom and top: fans from the reflex corner 3 (star-shaped polygon).
  for (int k : {4, 5, 0, 1}) {
    const int k2 = (k + 1) % 6;
    t.push_back({3, k2, k});            // bottom, facing down
    t.push_back({9, 6 + k, 6 + k2});    // top, facing up
  }
  for (int k = 0; k < 6; ++k) {
    const int k2 = (k + 1) % 6;
    t.push_back({k, k2, 6 + k2});
    t.push_back({k, 6 + k2, 6 + k});
  }
  for (std::size_t i = 0; i < t.size(); ++i) s.triangles.push_back({static_cast<std::int64_t>(i), t[i], 0});
  s.objects.push_back({"L"});
  return s;
}

// +1 strictly inside, -1 strictly outside, 0 on the boundary (independent of the mesh: the solid's formula).
int classify(const mpq_class& x, const mpq_class& y, const mpq_class& z) {
  if (x < 0 || y < 0 || z < 0 || z > 1 || x > 2 || y > 2 || (x > 1 && y > 1)) return -1;
  if (x > 0 && y > 0 && z > 0 && z < 1 && x < 2 && y < 2 && !(x >= 1 && y >= 1)) {
    if (y < 1 || x < 1) return 1;
  }
  return 0;
}

TEST(Tangency, VertexRuleMatchesInsideOutsideOnNonConvexSolid) {
  const Scene s = l_prism();
  const SceneAdjacency adj = build_scene_adjacency(s);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> c(-3, 3);
  int decided = 0, pierced = 0;
  for (int v = 0; v < 12; ++v) {
    const VertexFan fan = build_vertex_fan(s, adj, v);
    ASSERT_EQ(fan.cycles.size(), 1u) << v;  // a closed manifold: every link is one cycle
    for (int i = 0; i < 300; ++i) {
      const int dx = c(rng), dy = c(rng), dz = c(rng);
      if (dx == 0 && dy == 0 && dz == 0) continue;
      // A reference vector not parallel to d.
      const Vec3<Exact> d(dx, dy, dz);
      const Vec3<Exact> ref = (dx != 0 || dy != 0) ? Vec3<Exact>(-dy, dx, 0) : Vec3<Exact>(1, 0, 0);
      const mpq_class eps(1, 64);
      const auto& p = s.vertices[v];
      const int plus = classify(p.x + eps * dx, p.y + eps * dy, p.z + eps * dz);
      const int minus = classify(p.x - eps * dx, p.y - eps * dy, p.z - eps * dz);
      if (plus == 0 || minus == 0) continue;  // grazing a face: rule (a)'s business
      const bool pierces = plus != minus;
      EXPECT_EQ(line_tangent_at_vertex(s, fan, d, ref).tangent, !pierces)
          << "v=" << v << " d=(" << dx << "," << dy << "," << dz << ")";
      ++decided;
      pierced += pierces;
    }
  }
  EXPECT_GT(decided, 1000);
  EXPECT_GT(pierced, 100);
  EXPECT_LT(pierced, decided);
}

}  // namespace
}  // namespace exactvis
