// Orthographic aspect graphs of models that are not closed solids (open surfaces, a non-manifold "book", two
// cubes sharing an edge, an inconsistently oriented cube), every triangle a two-sided occluder (docs/theory.md §10.10), through
// aspect/general_orthographic_aspect_graph: hand-derived counts (one triangle, a planar quad, two parallel
// triangles, the reoriented cube) and, on every model, the independent slab oracle (tests/aspect/
// sphere_graph_checks.hpp: every cell's sample, adjacent regions' samples, random directions located by their
// sign vector); and which failures of closed_solid_fronts send a model to this route.
#include "aspect/general_orthographic_aspect_graph.hpp"

#include "aspect/closed_solid_fronts.hpp"
#include "aspect/triangle_contacts.hpp"
#include "tests/aspect/aspect_test_models.hpp"
#include "tests/aspect/sphere_graph_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace {

using namespace exactvis;
using namespace exactvis::aspect_test;

// The model must be outside the closed-solid route (not_solid) and acceptable to the CLI's open route.
GeneralOrthographicResult open_graph(const Scene& s) {
  const ClosedSolidFronts f = closed_solid_fronts(s);
  EXPECT_FALSE(f.ok);
  EXPECT_TRUE(f.not_solid) << f.problem;
  EXPECT_EQ(triangle_contact_problem(s), "");
  GeneralOrthographicResult r = general_orthographic_aspect_graph(s);
  EXPECT_TRUE(r.ok) << r.problem;
  return r;
}

// (dimension, aspect) of every region, sorted.
std::multiset<std::pair<int, std::vector<std::int64_t>>> regions_of(const AspectGraph3& g) {
  std::multiset<std::pair<int, std::vector<std::int64_t>>> out;
  for (const auto& r : g.regions) out.insert({r.dimension, r.aspect});
  return out;
}

using Ids = std::vector<std::int64_t>;

// One triangle: seen (two-sided) from both open hemispheres of its plane, which are separated by the great
// circle of its plane, where it is edge-on (empty aspect): 3 regions, 2 adjacencies.
TEST(OpenOrthographicAspectGraph, OneTriangleHasThreeRegions) {
  const Scene s = make_scene({{0, 0, 0}, {2, 0, 1}, {0, 2, 1}}, {{0, 1, 2}});
  const auto r = open_graph(s);
  EXPECT_EQ(regions_of(r.graph), (std::multiset<std::pair<int, Ids>>{{2, {0}}, {2, {0}}, {1, {}}}));
  EXPECT_EQ(r.graph.adjacency.size(), 2u);
  check_against_oracle(s, r.graph, 31, 40);
}

// A planar quad of two triangles (an open surface with an inner diagonal): as one triangle, both seen
// together: 3 regions.
TEST(OpenOrthographicAspectGraph, PlanarQuadHasThreeRegions) {
  const Scene s = make_scene({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
  const auto r = open_graph(s);
  EXPECT_EQ(regions_of(r.graph), (std::multiset<std::pair<int, Ids>>{{2, {0, 1}}, {2, {0, 1}}, {1, {}}}));
  EXPECT_EQ(r.graph.adjacency.size(), 2u);
  check_against_oracle(s, r.graph, 32, 40);
}

// Two parallel triangles: B = (0,0,0) (3,0,0) (0,3,0) (id 0) below T = 3B about B's centroid (1,1) lifted to
// z = 1 (id 1). From above (d_z > 0) B is hidden iff its three corners' rays meet T, i.e. iff
// (d_x, d_y) / d_z lies in the closed triangle T - B (Minkowski difference, 2B about (1,1) shifted: non-empty,
// bounded): one closed 2D region {1}. Elsewhere above both are seen ({0, 1}, an annulus); below both are seen
// (T, larger, never fits in B's image); on d_z = 0 both are edge-on ({}), which separates the two {0, 1}
// regions. 4 regions, 3 adjacencies.
TEST(OpenOrthographicAspectGraph, ParallelTrianglesHaveFourRegions) {
  const Scene s = make_scene({{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {-2, -2, 1}, {7, -2, 1}, {-2, 7, 1}}, {{0, 1, 2}, {3, 4, 5}});
  const auto r = open_graph(s);
  EXPECT_EQ(regions_of(r.graph),
            (std::multiset<std::pair<int, Ids>>{{2, {1}}, {2, {0, 1}}, {2, {0, 1}}, {1, {}}}));
  EXPECT_EQ(r.graph.adjacency.size(), 3u);
  check_against_oracle(s, r.graph, 33, 60);
}

// The unit box without its top (floor 0-1, then walls -y, +y, -x, +x: add_box's faces without +z). Looking
// straight down only the floor is seen (the walls are edge-on); from below only the floor's outside.
TEST(OpenOrthographicAspectGraph, OpenBox) {
  std::vector<Point3> v;
  std::vector<std::array<int, 3>> t;
  add_box(v, t, 0, 0, 0, 1, 1, 1);
  t.erase(t.begin() + 2, t.begin() + 4);  // the +z face
  const Scene s = make_scene(v, t);
  const auto r = open_graph(s);
  const auto& g = r.graph;
  const auto region_at = [&](const Vec3<Exact>& d) {
    for (const auto& c : g.sampled_cells)
      if (c.direction == d) return g.regions[c.region].aspect;
    ADD_FAILURE() << "no cell sample at " << d.x << " " << d.y << " " << d.z;
    return Ids{};
  };
  EXPECT_EQ(region_at({Exact(0), Exact(0), Exact(1)}), (Ids{0, 1}));
  EXPECT_EQ(region_at({Exact(0), Exact(0), Exact(-1)}), (Ids{0, 1}));
  check_against_oracle(s, g, 34, 120);
}

// Three triangles on one edge (a non-manifold "book"), two-sided.
TEST(OpenOrthographicAspectGraph, NonManifoldBook) {
  const Scene s = make_scene({{0, 0, 0}, {0, 0, 2}, {2, 0, 1}, {-1, 2, 1}, {-1, -2, 1}}, {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}});
  const auto r = open_graph(s);
  check_against_oracle(s, r.graph, 35, 80);
}

// A small terrain patch: a 3 x 3 grid of heights over [0,2]^2, two triangles per square.
TEST(OpenOrthographicAspectGraph, TerrainPatch) {
  const Scene s = terrain_grid({{0, 1, 0}, {1, 2, 1}, {0, 1, 1}});
  const auto r = open_graph(s);
  check_against_oracle(s, r.graph, 36, 120);
}

// A terrain patch (the same grid, other heights) with lower cells off every free arc whose aspect is not a
// neighbouring face's: on part of a triangle's plane circle the triangle is edge-on (so it leaves the aspect)
// while its EV lines there are blocked, and no free arc lies on that part (docs/theory.md 10.11 "Aspects").
// Taking a face's aspect for such cells (the rule 10.10 had) puts one cell in the wrong region here; every
// rational cell is now evaluated, and the oracle checks every cell's sample.
TEST(OpenOrthographicAspectGraph, TerrainPatchWithEdgeOnCellsOffTheFreeArcs) {
  const Scene s = terrain_grid({{0, 0, 0}, {1, 0.5, 1}, {1, 0.5, 0}});
  const auto r = open_graph(s);
  EXPECT_EQ(r.eee_arcs, 0u);
  EXPECT_EQ(r.graph.regions.size(), 115u);
  check_against_oracle(s, r.graph, 37, 60);
}

// The cube with one triangle reversed: closed but inconsistently oriented, so not a closed solid for
// closed_solid_fronts; taken with two-sided triangles, it has the cube's 26 regions (the inner sides are never
// seen from outside).
TEST(OpenOrthographicAspectGraph, InconsistentlyOrientedCubeHasTheCubesRegions) {
  Scene s = cube();
  std::swap(s.triangles[5].v[1], s.triangles[5].v[2]);
  const auto r = open_graph(s);
  const auto c = general_orthographic_aspect_graph(cube());
  ASSERT_TRUE(c.ok);
  EXPECT_EQ(r.graph.regions.size(), 26u);
  EXPECT_EQ(regions_of(r.graph), regions_of(c.graph));
  EXPECT_EQ(r.graph.adjacency.size(), c.graph.adjacency.size());
  check_against_oracle(s, r.graph, 37, 40);
}

// Two unit cubes sharing the edge x = y = 1 (a closed surface with a non-manifold edge of four triangles): not a
// closed 2-manifold, so the two-sided route; its triangles meet only in shared corners and edges.
TEST(OpenOrthographicAspectGraph, CubesSharingAnEdge) {
  std::vector<Point3> v;
  std::vector<std::array<int, 3>> t;
  add_box(v, t, 0, 0, 0, 1, 1, 1);
  add_box(v, t, 1, 1, 0, 2, 2, 1);
  const Scene s = make_scene(v, t);
  const auto r = open_graph(s);
  check_against_oracle(s, r.graph, 38, 60);
}

// Which failures of closed_solid_fronts mean "not a closed solid" (the two-sided route) and which do not.
TEST(OpenOrthographicAspectGraph, NotSolidIsReportedOnlyForSurfacesThatAreNotClosedManifolds) {
  const ClosedSolidFronts open = closed_solid_fronts(make_scene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  EXPECT_TRUE(!open.ok && open.not_solid && !open.outside_class) << open.problem;
  Scene flipped = cube();
  std::swap(flipped.triangles[0].v[1], flipped.triangles[0].v[2]);
  const ClosedSolidFronts f = closed_solid_fronts(flipped);
  EXPECT_TRUE(!f.ok && f.not_solid) << f.problem;
  // Two overlapping cubes: each a closed manifold, together self-intersecting: refused, not two-sided.
  const ClosedSolidFronts x = closed_solid_fronts(combined(cube(), translated(cube(), 1, 1, 1)));
  EXPECT_TRUE(!x.ok && !x.not_solid) << x.problem;
  EXPECT_NE(x.problem.find("intersects itself"), std::string::npos) << x.problem;
  EXPECT_NE(triangle_contact_problem(combined(cube(), translated(cube(), 1, 1, 1))), "");
  // Three boxes in a row: a closed solid outside the class of 10.5.
  const ClosedSolidFronts row = closed_solid_fronts(three_boxes());
  EXPECT_TRUE(!row.ok && row.outside_class && !row.not_solid) << row.problem;
  EXPECT_TRUE(closed_solid_fronts(l_prism()).ok);
}

}  // namespace
