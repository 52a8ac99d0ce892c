// Orthographic aspect graphs of non-convex closed models (aspect/orthographic_aspect_graph): hand-derived
// counts (L-shaped prism, two boxes), convex models through the general path (cube 26, tetrahedron 14),
// random pairs of convex polytopes; every cell of the partition checked against the independent exact
// slab oracle (tests/oracles/aspect_oracle: oracle::direction_aspect), adjacent regions differing by the
// triangles of the events on their boundary; rejection of models outside the certified class.
#include "aspect/orthographic_aspect_graph.hpp"

#include "tests/aspect/aspect_test_models.hpp"
#include "tests/exact_to_mpq.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace {

using namespace exactvis;
using namespace exactvis::aspect_test;

using exact_to_mpq::q;

AspectGraph3 graph(const Scene& s) {
  const ClosedSolidFronts f = closed_solid_fronts(s);
  EXPECT_TRUE(f.ok) << f.problem;
  return orthographic_aspect_graph(s, f);
}

std::vector<std::int64_t> oracle_ids(const Scene& s, const std::vector<oracle::OTriangle>& model, const Vec3<Exact>& d) {
  std::vector<std::int64_t> ids;
  for (int i : oracle::direction_aspect(model, {q(d.x), q(d.y), q(d.z)})) ids.push_back(s.triangles[i].id);
  return ids;
}

// Every cell of the partition (or `max_cells` of them, evenly spread): the oracle's aspect at its sample is its region's aspect (so the
// aspect is constant on the region's cells); every region's sample likewise; adjacent regions have
// different aspects, and each event names only triangles whose visibility differs across it.
void check(const Scene& s, const AspectGraph3& g, std::size_t max_cells = 1000) {
  const auto model = oracle_model(s);
  const std::size_t stride = std::max<std::size_t>(1, g.sampled_cells.size() / max_cells);
  for (std::size_t c = 0; c < g.sampled_cells.size(); c += stride) {
    const auto& cell = g.sampled_cells[c];
    EXPECT_EQ(oracle_ids(s, model, cell.direction), g.regions[cell.region].aspect) << "cell " << c;
  }
  for (std::size_t r = 0; r < g.regions.size(); ++r)
    EXPECT_EQ(oracle_ids(s, model, g.regions[r].sample), g.regions[r].aspect) << "region " << r;
  for (const auto& a : g.adjacency) {
    const auto& A = g.regions[a.a].aspect;
    const auto& B = g.regions[a.b].aspect;
    EXPECT_NE(A, B);
    std::vector<std::int64_t> diff;
    std::set_symmetric_difference(A.begin(), A.end(), B.begin(), B.end(), std::back_inserter(diff));
    ASSERT_FALSE(a.events.empty());
    for (const auto& e : a.events) {
      EXPECT_EQ(e.type, "EV");
      EXPECT_GE(e.vertex, 0);
      for (std::int64_t t : e.triangles) EXPECT_TRUE(std::binary_search(diff.begin(), diff.end(), t));
    }
  }
}

TEST(OrthographicAspectGraph, ConvexModelsGiveTheConvexCounts) {
  const AspectGraph3 cube = graph(aspect_test::cube());
  EXPECT_EQ(cube.regions.size(), 26u);
  EXPECT_EQ(per_dimension(cube), (std::array<int, 3>{6, 12, 8}));
  check(aspect_test::cube(), cube);
  const AspectGraph3 tet = graph(tetrahedron());
  EXPECT_EQ(tet.regions.size(), 14u);
  check(tetrahedron(), tet);
}

// Hand derivation (docs/theory.md §10.5). Outer faces are seen iff d is on their outer side: the three
// coordinate circles give the cube's 26 cells, all with distinct aspects. The inner wall x = 1 (triangles
// 14, 15) has the front part P = [1,2]x[0,1]x[0,1]; with r = (d_y, d_z) / d_x (d_x > 0) a corner (1, y0, z0)
// is in P's shadow iff y0 + m r_y and z0 + m r_z lie in [0, 1] for some m in [0, 1]: the corners (1,1,0)
// and (1,1,1) always (they lie in P), (1,2,0) iff r_y <= -1 and 0 <= r_z <= -r_y, (1,2,1) iff r_y <= -1 and
// r_y <= r_z <= 0. So 14 is hidden on the arc {d_z = 0, d_y <= -d_x} and 15 on the closed 2D region
// {d_y <= -d_x, d_y <= d_z <= 0}: the octant (+x, -y, -z) splits into 2 regions (15 hidden or not; the
// region's boundary arcs hide 15 too and join it) and the arc {d_z = 0, d_x > 0, d_y < 0} into 2 (14 and 15
// hidden where d_y <= -d_x, including the vertex (1, -1, 0); both seen beyond). The wall y = 1 (12, 13) is
// the mirror image (x <-> y, its diagonal the other way: 12 hidden on a 2D region, 13 on an arc): 2 more
// regions in the octant (-x, +y, +z) and 2 on the arc {d_z = 0, d_x < 0, d_y > 0}. Total 26 + 4 = 30:
// 8 + 2 faces, 12 + 2 arcs, 6 vertices.
TEST(OrthographicAspectGraph, LShapedPrismHandCount) {
  const Scene s = l_prism();
  const AspectGraph3 g = graph(s);
  EXPECT_EQ(g.regions.size(), 30u);
  EXPECT_EQ(per_dimension(g), (std::array<int, 3>{6, 14, 10}));
  // The region where triangle 15 alone of the front-facing ones is hidden.
  const std::vector<std::int64_t> hidden15{0, 1, 2, 3, 8, 9, 10, 11, 14};
  EXPECT_EQ(std::count_if(g.regions.begin(), g.regions.end(), [&](const auto& r) { return r.aspect == hidden15; }), 1);
  check(s, g);
}

// Two unit cubes with a gap of 1 along x: a triangle of the face x = 1 of the first cube is hidden iff its
// three corners are in the second cube's shadow; the corner (1, y0, z0) is iff (d_y, d_z) / d_x lies in
// [-y0, 1 - y0] x [-z0, 1 - z0], and the three squares of a triangle's corners meet only at 0: the face is
// hidden only from d = +x (and the mirror face only from -x). So the 26 cells of the coordinate circles,
// with the vertex +x seeing only the far cube's +x face: 26 regions.
TEST(OrthographicAspectGraph, TwoBoxesHandCount) {
  const Scene s = two_boxes();
  const AspectGraph3 g = graph(s);
  EXPECT_EQ(g.regions.size(), 26u);
  EXPECT_EQ(per_dimension(g), (std::array<int, 3>{6, 12, 8}));
  bool found = false;
  for (const auto& r : g.regions)
    if (r.sample == Vec3<Exact>(1, 0, 0)) {
      found = true;
      EXPECT_EQ(r.aspect, (std::vector<std::int64_t>{22, 23}));
    }
  EXPECT_TRUE(found);
  check(s, g);
}

// Hand derivation, as for the L-prism. The notch floor z = 1 (triangles 12, 13) has the front part
// [0,2]x[0,2]x[1,2]; with r = (d_x, d_y) / d_z (d_z > 0) its corners (2, y0, 1) lie in it, (3, 0, 1) is in
// the shadow iff r_x <= -1 and 0 <= r_y <= -2 r_x, (3, 2, 1) iff r_x <= -1 and 2 r_x <= r_y <= 0: 12 is hidden
// on the arc {d_y = 0, d_x <= -d_z}, 13 on a closed 2D region of the octant (-x, +y, +z). The notch wall
// x = 2 (14, 15), front part [2,3]x[0,2]x[0,1], r = (d_y, d_z) / d_x: (2, 2, 2) is in the shadow iff r_z <= -1
// and 2 r_z <= r_y <= 0, (2, 0, 2) iff r_z <= -1 and 0 <= r_y <= -2 r_z: 14 hidden on a 2D region of the
// octant (+x, -y, -z), 15 on the arc {d_y = 0, d_z <= -d_x}. The other faces are outer (empty front parts).
// So two octants and two arcs of the cube's 26 cells split in two: 30 regions (10, 14, 6).
TEST(OrthographicAspectGraph, NotchedBoxHandCount) {
  const Scene s = notched_box();
  const AspectGraph3 g = graph(s);
  EXPECT_EQ(g.regions.size(), 30u);
  EXPECT_EQ(per_dimension(g), (std::array<int, 3>{6, 14, 10}));
  check(s, g);
}

// Two random convex polytopes side by side (their front parts are convex: for a triangle of one, the
// part of the other in front of its plane).
TEST(OrthographicAspectGraph, RandomPairsOfConvexPolytopes) {
  for (unsigned seed = 1; seed <= 2; ++seed) {
    const Scene s = combined(random_convex(seed, 5, 8), translated(random_convex(seed + 100, 5, 8), 10, 3, 2));
    const AspectGraph3 g = graph(s);
    SCOPED_TRACE(seed);
    EXPECT_GT(g.regions.size(), 0u);
    check(s, g, 20);
  }
}

TEST(OrthographicAspectGraph, RejectsModelsOutsideTheCertifiedClass) {
  // A cube with a corner notch: the part in front of an inner wall is L-shaped (not convex).
  std::vector<Point3> v;
  std::vector<std::array<int, 3>> t;
  add_box(v, t, 0, 0, 0, 1, 1, 1);
  Scene open = make_scene(v, t);
  open.triangles.pop_back();
  EXPECT_FALSE(closed_solid_fronts(open).ok);
  EXPECT_NE(closed_solid_fronts(open).problem.find("not closed"), std::string::npos);
  // Two boxes one above the other with a third beside: the part in front of a face is two boxes.
  add_box(v, t, 2, 0, 0, 3, 1, 1);
  add_box(v, t, 2, 0, 2, 3, 1, 3);
  const ClosedSolidFronts f = closed_solid_fronts(make_scene(v, t));
  EXPECT_FALSE(f.ok);
  EXPECT_NE(f.problem.find("not convex"), std::string::npos) << f.problem;
}

}  // namespace
