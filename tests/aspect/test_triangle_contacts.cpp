// aspect/triangle_contacts: hand-made pairs for every rule (each way of meeting properly, each way of crossing,
// overlapping or touching), and random jittered terrain grids against CGAL's own self-intersection test of
// the same surface (Polygon_mesh_processing::does_self_intersect on a Surface_mesh: a different
// implementation, which also allows exactly the shared corners and edges of the mesh).
#include "aspect/triangle_contacts.hpp"

#include "kernel/predicates.hpp"
#include "tests/scene_test_util.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <gtest/gtest.h>

#include <random>

namespace {

using namespace exactvis;
using scene_test::make_scene;

bool proper(const std::vector<Point3>& v, const std::vector<std::array<int, 3>>& t) {
  return triangle_contact_problem(make_scene(v, t)).empty();
}

TEST(TriangleContacts, ProperContacts) {
  // Disjoint.
  EXPECT_TRUE(proper({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}, {{0, 1, 2}, {3, 4, 5}}));
  // A shared corner, different planes.
  EXPECT_TRUE(proper({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 1, 1}}, {{0, 1, 2}, {0, 3, 4}}));
  // A shared corner, one plane, a bow tie.
  EXPECT_TRUE(proper({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}}, {{0, 1, 2}, {0, 3, 4}}));
  // A shared edge, one plane, both sides (a planar quad).
  EXPECT_TRUE(proper({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}}));
  // A shared edge, different planes (a fold).
  EXPECT_TRUE(proper({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 1}}, {{0, 1, 2}, {0, 2, 3}}));
  // Shared corners by coordinates, not by vertex ids: the quad with its diagonal's corners duplicated.
  EXPECT_TRUE(proper({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {3, 4, 5}}));
}

TEST(TriangleContacts, ImproperContacts) {
  // Crossing, no shared corner.
  const Scene crossing = make_scene({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0}},
                                    {{0, 1, 2}, {3, 4, 5}});
  const std::string p = triangle_contact_problem(crossing);
  EXPECT_NE(p.find("triangles 0 and 1"), std::string::npos) << p;
  // A T-junction: a corner of one inside an edge of the other.
  EXPECT_FALSE(proper({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {1, -1, 0}, {2, -1, 0}}, {{0, 1, 2}, {3, 4, 5}}));
  // A shared corner, one plane, overlapping (the second inside the first's angle).
  EXPECT_FALSE(proper({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}, {2, 1, 0}}, {{0, 1, 2}, {0, 3, 4}}));
  // A shared corner, different planes meeting along a segment from it (the second's far edge crosses the first).
  EXPECT_FALSE(proper({{0, 0, 0}, {2, -1, 0}, {2, 1, 0}, {1, 0, -1}, {1, 0, 1}}, {{0, 1, 2}, {0, 3, 4}}));
  // A shared corner, the first's far edge touching the second at one point.
  EXPECT_FALSE(proper({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, -1}, {1, 1, 1}}, {{0, 1, 2}, {0, 3, 4}}));
  // A shared edge, one plane, the same side (folded flat).
  EXPECT_FALSE(proper({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}}, {{0, 1, 2}, {0, 1, 3}}));
  // The same triangle twice.
  EXPECT_FALSE(proper({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}}));
  // A degenerate triangle.
  const std::string d = triangle_contact_problem(make_scene({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}));
  EXPECT_NE(d.find("triangle 0 is degenerate"), std::string::npos) << d;
}

// Random 4 x 4 grids of squares, corners jittered in x and y by multiples of 1/4 (large enough to fold some
// triangles over their neighbours) and heights in {0, 1/2, 1} (coplanar neighbours too): both answers occur,
// and triangle_contact_problem agrees with CGAL's test of the same mesh on each.
TEST(TriangleContacts, RandomGridsAgreeWithCgal) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  std::mt19937 rng(41);
  std::uniform_int_distribution<int> jitter(-3, 3), height(0, 2);
  int good = 0, bad = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 5;  // vertices per side
    std::vector<Point3> v;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) v.push_back({i + jitter(rng) / 4.0, j + jitter(rng) / 4.0, height(rng) / 2.0});
    std::vector<std::array<int, 3>> t;
    for (int i = 0; i + 1 < n; ++i)
      for (int j = 0; j + 1 < n; ++j) {
        const int a = n * i + j, b = a + n;
        t.push_back({a, b, b + 1});
        t.push_back({a, b + 1, a + 1});
      }
    bool degenerate = false;
    for (const auto& x : t) degenerate |= collinear(v[x[0]], v[x[1]], v[x[2]]);
    for (std::size_t a = 0; a < v.size(); ++a)
      for (std::size_t b = a + 1; b < v.size(); ++b)
        degenerate |= v[a].x == v[b].x && v[a].y == v[b].y && v[a].z == v[b].z;
    // CGAL's test presumes non-degenerate faces, and tells equal points of distinct mesh vertices apart.
    if (degenerate) continue;
    Mesh mesh;
    std::vector<Mesh::Vertex_index> vi;
    for (const auto& p : v) vi.push_back(mesh.add_vertex(K::Point_3(p.x, p.y, p.z)));
    for (const auto& x : t) ASSERT_NE(mesh.add_face(vi[x[0]], vi[x[1]], vi[x[2]]), Mesh::null_face());
    const bool cgal_ok = !CGAL::Polygon_mesh_processing::does_self_intersect(mesh);
    const std::string p = triangle_contact_problem(make_scene(v, t));
    EXPECT_EQ(p.empty(), cgal_ok) << "trial " << trial << ": " << p;
    (cgal_ok ? good : bad)++;
  }
  EXPECT_GT(good, 20);
  EXPECT_GT(bad, 20);
}

}  // namespace
