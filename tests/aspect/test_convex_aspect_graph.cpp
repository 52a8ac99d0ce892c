// Aspect graphs of convex models: the counts of the issue (cube 26/26, tetrahedron 14/14), random convex
// polytopes against the great-circle oracle (Euler's formula) and the simple-arrangement formula, every
// region's aspect against the ray-casting oracle at its sample, and adjacent regions differing exactly by
// their events.
#include "aspect/convex_aspect_graph.hpp"

#include "tests/aspect/aspect_test_models.hpp"
#include "tests/exact_to_mpq.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace {

using namespace exactvis;
using namespace exactvis::aspect_test;

using exact_to_mpq::q;

AspectGraph3 graph(const Scene& s, ViewModel v) {
  const ConvexModel m = convex_model(s);
  EXPECT_TRUE(m.convex) << m.problem;
  return convex_aspect_graph(s, m, v);
}

std::array<int, 4> per_dimension(const AspectGraph3& g) {
  std::array<int, 4> d{0, 0, 0, 0};
  for (const auto& r : g.regions) ++d[r.dimension];
  return d;
}

// Every region: its aspect is what the oracle sees from its sample; aspects are distinct (for a convex
// model each aspect's viewpoints form a convex, hence connected, set); adjacent regions' aspects are nested
// and differ exactly by the triangles of the events on their boundary.
// `stride` > 1 checks every stride-th region against the (slow) oracle, the others only for distinctness.
void check_against_oracle(const Scene& s, const AspectGraph3& g, std::size_t stride = 1) {
  const auto model = oracle_model(s);
  std::set<std::vector<std::int64_t>> aspects;
  for (std::size_t i = 0; i < g.regions.size(); ++i) {
    const auto& r = g.regions[i];
    EXPECT_TRUE(aspects.insert(r.aspect).second);
    if (i % stride) continue;
    const oracle::QVec p{q(r.sample.x), q(r.sample.y), q(r.sample.z)};
    const std::vector<int> seen = g.view == ViewModel::Orthographic ? oracle::convex_direction_aspect(model, p)
                                                                    : oracle::convex_point_aspect(model, p);
    std::vector<std::int64_t> ids;
    for (int i : seen) ids.push_back(s.triangles[i].id);
    EXPECT_EQ(ids, r.aspect);
  }
  for (const auto& a : g.adjacency) {
    ASSERT_LT(a.a, a.b);
    const auto& A = g.regions[a.a].aspect;
    const auto& B = g.regions[a.b].aspect;
    const auto& small = A.size() < B.size() ? A : B;
    const auto& big = A.size() < B.size() ? B : A;
    EXPECT_TRUE(std::includes(big.begin(), big.end(), small.begin(), small.end()));
    std::vector<std::int64_t> diff, events;
    std::set_difference(big.begin(), big.end(), small.begin(), small.end(), std::back_inserter(diff));
    ASSERT_FALSE(a.events.empty());
    for (const auto& e : a.events) {
      EXPECT_EQ(e.type, "EV");
      events.insert(events.end(), e.triangles.begin(), e.triangles.end());
    }
    std::sort(events.begin(), events.end());
    EXPECT_EQ(diff, events);
  }
}

TEST(ConvexAspectGraph, CubeHas26RegionsBothWays) {
  const AspectGraph3 o = graph(cube(), ViewModel::Orthographic);
  EXPECT_EQ(o.regions.size(), 26u);
  EXPECT_EQ(per_dimension(o), (std::array<int, 4>{6, 12, 8, 0}));  // directions, arcs, octants
  check_against_oracle(cube(), o);
  const AspectGraph3 p = graph(cube(), ViewModel::Perspective);
  EXPECT_EQ(p.regions.size(), 26u);
  EXPECT_EQ(per_dimension(p), (std::array<int, 4>{0, 0, 0, 26}));
  check_against_oracle(cube(), p);
  // Octants see three faces (6 triangles), arcs two, the six axis directions one.
  for (const auto& r : o.regions) EXPECT_EQ(r.aspect.size(), 2u * (r.dimension + 1));
}

TEST(ConvexAspectGraph, TetrahedronHas14RegionsBothWays) {
  for (ViewModel v : {ViewModel::Orthographic, ViewModel::Perspective}) {
    const AspectGraph3 g = graph(tetrahedron(), v);
    EXPECT_EQ(g.regions.size(), 14u);
    for (const auto& r : g.regions) EXPECT_EQ(r.dimension, v == ViewModel::Orthographic ? 2 : 3);
    check_against_oracle(tetrahedron(), g);
  }
}

// Random convex polytopes, orthographic: the great circles of the face normals counted by the oracle; in a
// simple arrangement every arc and vertex joins the face on its negative side, so regions = F = 2 - V + E,
// and adjacencies = E (faces across an arc) + V (the face opposite the vertex's own region).
TEST(ConvexAspectGraph, RandomPolytopesOrthographicMatchEulerCount) {
  int simple = 0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const Scene s = random_convex(seed, 6 + seed, 30);
    const AspectGraph3 g = graph(s, ViewModel::Orthographic);
    check_against_oracle(s, g, g.regions.size() / 40 + 1);
    std::vector<oracle::QVec> normals;
    for (const auto& t : oracle_model(s)) normals.push_back(oracle::cross(t[1] - t[0], t[2] - t[0]));
    const auto c = oracle::great_circle_counts(normals);
    EXPECT_EQ(g.cells[0], c.vertices);
    EXPECT_EQ(g.cells[1], c.arcs);
    EXPECT_EQ(g.cells[2], c.faces);
    if (!c.simple) continue;
    ++simple;
    EXPECT_EQ(static_cast<std::int64_t>(g.regions.size()), c.faces);
    EXPECT_EQ(static_cast<std::int64_t>(g.adjacency.size()), c.arcs + c.vertices);
  }
  EXPECT_GE(simple, 4);
}

// Perspective on a simple polytope whose face planes are in general position (a tetrahedron with one or two
// corners cut off): every cell outside joins a 3-cell, so regions = (cells of the simple arrangement of m
// planes) - 1 = C(m,3) + C(m,2) + m.
TEST(ConvexAspectGraph, TruncatedTetrahedraPerspectiveMatchTheSimpleArrangement) {
  // Tetrahedron (0,0,0), (8,0,0), (0,8,0), (0,0,8); corner 0 cut by 4x + 2y + z = 4, then corner (8,0,0)
  // by x - 3y - z = 4 (crossings at integer points; no three normals coplanar).
  const std::vector<Point3> one{{1, 0, 0}, {0, 2, 0}, {0, 0, 4}, {8, 0, 0}, {0, 8, 0}, {0, 0, 8}};
  const std::vector<Point3> two{{1, 0, 0}, {0, 2, 0}, {0, 0, 4}, {4, 0, 0}, {7, 1, 0}, {6, 0, 2}, {0, 8, 0}, {0, 0, 8}};
  for (const auto& pts : {one, two}) {
    const Scene s = hull_scene(pts);
    const ConvexModel m = convex_model(s);
    ASSERT_TRUE(m.convex) << m.problem;
    std::vector<std::pair<oracle::QVec, mpq_class>> planes;
    for (const auto& p : m.planes) planes.push_back({{q(p.normal.x), q(p.normal.y), q(p.normal.z)}, q(p.offset)});
    ASSERT_TRUE(oracle::plane_arrangement_is_simple(planes));
    const std::int64_t k = static_cast<std::int64_t>(m.planes.size());
    const AspectGraph3 g = convex_aspect_graph(s, m, ViewModel::Perspective);
    EXPECT_EQ(static_cast<std::int64_t>(g.regions.size()), k * (k - 1) * (k - 2) / 6 + k * (k - 1) / 2 + k);
    check_against_oracle(s, g);
  }
}

TEST(ConvexAspectGraph, RandomPolytopesPerspectiveAgreeWithTheOracle) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Scene s = random_convex(seed, 7, 20);
    const AspectGraph3 g = graph(s, ViewModel::Perspective);
    check_against_oracle(s, g);
    for (const auto& r : g.regions) EXPECT_FALSE(r.aspect.empty());
  }
}

// Viewpoints on a plane: the traces of the face planes are lines of the plane; in a simple line arrangement
// every lower cell joins a face, so regions = faces of the line arrangement outside the model's section.
TEST(ConvexAspectGraph, PlanesOfViewpoints) {
  struct Case {
    Scene s;
    Exact h;
    std::size_t regions;
  };
  const std::vector<Case> cases{{cube(), Exact(0), 8},        // 3 x 3 grid minus the section
                                {cube(), Exact(2), 9},        // above the top: the whole grid
                                {cube(), Exact(1), 8},        // in the top face's plane
                                {tetrahedron(), Exact(1) / 4, 6},  // 3 lines (z = 0 is parallel): 7 - 1
                                {tetrahedron(), Exact(2), 7}};
  for (const auto& c : cases) {
    const ConvexModel m = convex_model(c.s);
    const AspectGraph3 g = convex_aspect_graph_on_plane(c.s, m, Vec3<Exact>(0, 0, 1), c.h);
    EXPECT_EQ(g.regions.size(), c.regions) << "z = " << c.h;
    for (const auto& r : g.regions) {
      EXPECT_EQ(r.sample.z, c.h);
      EXPECT_LE(r.dimension, 2);
    }
    check_against_oracle(c.s, g);
  }
}

}  // namespace
