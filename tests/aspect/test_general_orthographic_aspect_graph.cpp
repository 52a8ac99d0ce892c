// The orthographic aspect graph of general models from free EV arcs (aspect/general_orthographic_aspect_graph)
// against the independent slab oracle (oracle::direction_aspect): every cell's sample gives its region's
// aspect, adjacent regions' samples give different aspects, random directions give the aspect of the face
// whose sign vector they have (a refuting sampler: a missing boundary would show as a face with two aspects);
// on the models of §10.5 the regions equal those of aspect/orthographic_aspect_graph (another method); three
// boxes in a row (outside §10.5) and the cube (26); models with free EEE arcs (three skew triangles, 2 x 2
// terrains, a face split by an EEE chord, irrational crossings of free arcs) against the oracle, and two outside
// the EEE subset (EEE arcs crossing or nearly meeting) refused.
#include "aspect/general_orthographic_aspect_graph.hpp"

#include "aspect/closed_solid_fronts.hpp"
#include "aspect/direction_event_arcs.hpp"
#include "aspect/orthographic_aspect_graph.hpp"
#include "tests/aspect/aspect_test_models.hpp"
#include "tests/aspect/sphere_graph_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <random>
#include <set>

namespace {

using namespace exactvis;
using namespace exactvis::aspect_test;

// Regions as (dimension, aspect) multisets, for comparing two methods.
std::multiset<std::pair<int, std::vector<std::int64_t>>> region_set(const AspectGraph3& g) {
  std::multiset<std::pair<int, std::vector<std::int64_t>>> out;
  for (const auto& r : g.regions) out.insert({r.dimension, r.aspect});
  return out;
}

GeneralOrthographicResult general(const Scene& s) {
  GeneralOrthographicResult r = general_orthographic_aspect_graph(s);
  EXPECT_TRUE(r.ok) << r.problem;
  return r;
}

TEST(GeneralOrthographicAspectGraph, CubeHas26Regions) {
  const auto r = general(cube());
  EXPECT_EQ(r.graph.regions.size(), 26u);
  check_against_oracle(cube(), r.graph, 1, 40);
}

TEST(GeneralOrthographicAspectGraph, ConvexFrontModelsAgreeWithTheSection105Graph) {
  unsigned seed = 2;
  for (const Scene& s : {l_prism(), two_boxes(), notched_box()}) {
    const auto r = general(s);
    const ClosedSolidFronts f = closed_solid_fronts(s);
    ASSERT_TRUE(f.ok);
    const AspectGraph3 h = orthographic_aspect_graph(s, f);
    EXPECT_EQ(region_set(r.graph), region_set(h));
    EXPECT_EQ(r.graph.adjacency.size(), h.adjacency.size());
    check_against_oracle(s, r.graph, seed++, 60);
  }
}

TEST(GeneralOrthographicAspectGraph, ThreeBoxesInARow) {
  const Scene s = three_boxes();
  const ClosedSolidFronts f = closed_solid_fronts(s);
  EXPECT_FALSE(f.ok);
  EXPECT_TRUE(f.outside_class);
  const auto r = general(s);
  // As for two boxes (theory 10.5): a triangle of a facing face is hidden only from the directions +-x
  // joining the boxes, so the cube's 26 cells stay distinct regions; from +x only the last box's +x face.
  EXPECT_EQ(r.graph.regions.size(), 26u);
  bool found = false;
  for (const auto& reg : r.graph.regions)
    if (reg.aspect == std::vector<std::int64_t>{34, 35}) found = true;
  EXPECT_TRUE(found);
  check_against_oracle(s, r.graph, 9, 80);
}

// Checks for graphs with free EEE arcs, against the slab oracle: every sampled cell (faces cut by EEE arcs
// included) has its region's aspect; adjacent regions' samples differ; every adjacency across a cell on an
// EEE arc names an EEE generator; random directions off every circle see one of the aspects of the faces with
// their sign vector (a face of the great circles cut by EEE arcs has several: a refuting sampler still, since
// a missing boundary inside a face of the circles would show as an aspect of none of its parts).
void check_eee_graph(const Scene& s, const GeneralOrthographicResult& r, unsigned seed, int random_directions) {
  const AspectGraph3& g = r.graph;
  ASSERT_FALSE(g.sampled_cells.empty());
  for (const auto& c : g.sampled_cells)
    EXPECT_EQ(oracle_ids(s, c.direction), g.regions[c.region].aspect)
        << "cell of dimension " << c.dimension << " in region " << c.region << " at " << c.direction.x << " "
        << c.direction.y << " " << c.direction.z;
  for (const auto& a : g.adjacency) {
    EXPECT_NE(oracle_ids(s, g.regions[a.a].sample), oracle_ids(s, g.regions[a.b].sample));
    EXPECT_FALSE(a.events.empty());
  }
  std::map<std::string, std::set<int>> face_regions;
  for (const auto& c : g.sampled_cells)
    if (c.dimension == 2) face_regions[c.signs].insert(c.region);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-40, 40);
  auto check_direction = [&](const Vec3<Exact>& d) {
    std::string signs;
    for (const auto& n : g.circles) {
      const int sg = CGAL::sign(dot(n, d));
      if (sg == 0) return false;
      signs += sg > 0 ? '+' : '-';
    }
    const auto it = face_regions.find(signs);
    EXPECT_NE(it, face_regions.end());
    if (it == face_regions.end()) return true;
    const auto seen = oracle_ids(s, d);
    bool found = false;
    for (int reg : it->second) found |= g.regions[reg].aspect == seen;
    EXPECT_TRUE(found) << "d = " << d.x << " " << d.y << " " << d.z;
    return true;
  };
  int checked = 0;
  while (checked < random_directions)
    if (check_direction(Vec3<Exact>(Exact(coord(rng)), Exact(coord(rng)), Exact(coord(rng))))) ++checked;
  // The suspected gap of docs/theory.md 10.12: a triangle whose plane is no circle of the partition is seen
  // edge-on (not in the aspect) on that plane's great circle, while the faces crossed there may see it; directions
  // on such a plane (off every circle) must still have the aspect of a region of their face.
  int planes_off = 0;
  for (const auto& tri : s.triangles) {
    const Vec3<Exact> p0(Exact(s.corner(tri, 0).x), Exact(s.corner(tri, 0).y), Exact(s.corner(tri, 0).z));
    const Vec3<Exact> n = cross(Vec3<Exact>(Exact(s.corner(tri, 1).x), Exact(s.corner(tri, 1).y), Exact(s.corner(tri, 1).z)) - p0,
                                Vec3<Exact>(Exact(s.corner(tri, 2).x), Exact(s.corner(tri, 2).y), Exact(s.corner(tri, 2).z)) - p0);
    bool is_circle = false;
    for (const auto& c : g.circles) {
      const Vec3<Exact> x = cross(c, n);
      is_circle |= CGAL::sign(x.x) == 0 && CGAL::sign(x.y) == 0 && CGAL::sign(x.z) == 0;
    }
    if (is_circle) continue;
    ++planes_off;
    for (int k = 0; k < 20; ++k) check_direction(cross(n, Vec3<Exact>(Exact(coord(rng)), Exact(coord(rng)), Exact(coord(rng)))));
  }
  std::printf("triangle planes that are no circle: %d\n", planes_off);
  // Both sides of every EEE sub-arc (sampled cells of dimension 1 off every circle): its sample moved by small
  // steps along the coordinate axes lands on either side, in components that must hold the oracle's aspect.
  for (const auto& c : g.sampled_cells) {
    if (c.dimension != 1 || c.signs.find('0') != std::string::npos) continue;
    for (int k = 0; k < 3; ++k)
      for (int sg : {1, -1}) {
        Vec3<Exact> d = c.direction;
        d[k] += Exact(sg, 256);
        check_direction(d);
      }
  }
}

// The number of adjacencies that name an EEE generator.
std::size_t eee_adjacencies(const AspectGraph3& g) {
  std::size_t k = 0;
  for (const auto& a : g.adjacency)
    for (const auto& e : a.events)
      if (e.type == "EEE") {
        ++k;
        break;
      }
  return k;
}

// Three triangles whose pairwise skew edges are all met by the line x = y = 0 (a free EEE family).
Scene three_skew_triangles() {
  return make_scene({{-1, 0, 0}, {1, 0, 0}, {0, -3, 0}, {0, -1, 1}, {0, 1, 1}, {3, 0, 1}, {-1, -1, 2}, {1, 1, 2},
                     {2, -2, 2}},
                    {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
}

TEST(GeneralOrthographicAspectGraph, FreeEeeArcsOfThreeSkewTriangles) {
  const Scene s = three_skew_triangles();
  const auto r = general(s);
  ASSERT_TRUE(r.ok) << r.problem;
  EXPECT_GT(r.eee_arcs, 0u);  // on great circles (three edges parallel to z = 0: the cone degenerates)
  check_eee_graph(s, r, 12, 150);
}

// The 2 x 2 terrain of docs/performance.md with seed 1 (heights random.Random(1).randint(0, 3) / 2, i-major),
// refused before: its free EEE arcs are conics cutting faces of the circles, and some regions are separated by
// them (adjacencies naming EEE generators). (Its EEE arcs carry lower-dimensional regions; they do not separate
// faces of different aspects, so a mutation that leaves the faces unsplit survives this test: see theory 10.12.)
TEST(GeneralOrthographicAspectGraph, TerrainWithFreeEeeConics) {
  const Scene s = terrain_grid({{0.5, 0, 1}, {0, 1.5, 1.5}, {1.5, 1.5, 0.5}});
  const auto r = general(s);
  ASSERT_TRUE(r.ok) << r.problem;
  EXPECT_EQ(r.eee_arcs, 4u);
  EXPECT_GT(eee_adjacencies(r.graph), 0u);
  check_eee_graph(s, r, 14, 100);
}

// A hole closing at an EEE event: A (z = 0) has its edge e1 on y = 0 and lies below it; B (z = 1) covers the
// side y < x - 1 of its edge e2, C (z = 2) the side y < -x - 1 of its edge e3. From above, A is seen only through
// the small triangle y <= 0, y >= x - 1, y >= -x - 1 between the three edges' images (B and C cover the rest of
// A); tilting the view towards -y moves the images of e2 and e3 up (by d_y / d_z and 2 d_y / d_z) until the three
// images are concurrent (at d = (0, -2/3, 1) in the plane d_x = 0), and beyond, the triangle is empty: A leaves
// the aspect on the free EEE conic of (e1, e2, e3), which crosses faces of the great circles of the EV arcs
// from boundary to boundary (chords), so some face has two components with different aspects (docs/theory.md
// 10.11, "Faces").
Scene eee_hole() {
  return make_scene({{-10, 0, 0}, {10, 0, 0}, {0, -10, 0}, {-20, -21, 0.625}, {20, 19, 1.375}, {40, -40, 1},
                     {20, -21, 2.375}, {-20, 19, 1.625}, {-40, -40, 2}},
                    {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
}

TEST(GeneralOrthographicAspectGraph, EeeChordSplitsAFaceOfTheCircles) {
  const Scene s = eee_hole();
  const auto r = general(s);
  ASSERT_TRUE(r.ok) << r.problem;
  EXPECT_GT(r.eee_arcs, 0u);
  // The design, by the oracle: A (id 0) seen from above, not from the tilted direction past the event.
  const auto seen = [&](const Vec3<Exact>& d) {
    const auto ids = oracle_ids(s, d);
    return std::find(ids.begin(), ids.end(), 0) != ids.end();
  };
  EXPECT_TRUE(seen({Exact(0), Exact(0), Exact(1)}));
  EXPECT_FALSE(seen({Exact(0), Exact(-1), Exact(1)}));
  // Some face of the circles holds two components of different regions (a chord of an EEE arc splits it).
  std::map<std::string, std::set<int>> face_regions;
  for (const auto& c : r.graph.sampled_cells)
    if (c.dimension == 2) face_regions[c.signs].insert(c.region);
  std::size_t split = 0;
  for (const auto& [signs, regs] : face_regions) split += regs.size() > 1;
  EXPECT_GT(split, 0u);
  EXPECT_GT(eee_adjacencies(r.graph), 0u);
  check_eee_graph(s, r, 16, 300);
}

// The 2 x 2 terrain of seed 4 (refused before session 10): free EEE arcs cross free EV arcs at directions in
// Q(sqrt D) (docs/theory.md 10.11, "Irrational crossings"), whose aspect is the intersection of the aspects of
// the circle's pieces next to them. The rational cells against the oracle as above; each crossing X against the
// openness of the sets seeing a triangle (part (i) of the proof): every triangle of its aspect is seen from the
// rational directions within 2^-24 of X's double approximation (the approximation itself and its six axis
// neighbours, on all sides of the two arcs); copying a face's aspect or uniting the pieces' would break this.
TEST(GeneralOrthographicAspectGraph, TerrainWithIrrationalCrossingsOfFreeArcs) {
  const Scene s = terrain_grid({{0.5, 1, 0}, {1.5, 1.5, 0.5}, {0, 0, 0}});
  const auto r = general(s);
  ASSERT_TRUE(r.ok) << r.problem;
  EXPECT_EQ(r.eee_arcs, 3u);
  ASSERT_FALSE(r.irrational_crossings.empty());
  check_eee_graph(s, r, 18, 100);
  for (const auto& x : r.irrational_crossings) {
    std::vector<Vec3<Exact>> near;
    const Vec3<Exact> d(Exact(x.direction[0]), Exact(x.direction[1]), Exact(x.direction[2]));
    near.push_back(d);
    for (int k = 0; k < 3; ++k)
      for (int sg : {1, -1}) {
        Vec3<Exact> e = d;
        e[k] += Exact(sg, 1 << 24);
        near.push_back(e);
      }
    std::set<std::int64_t> seen_everywhere;
    bool first = true;
    for (const auto& e : near) {
      const auto ids = oracle_ids(s, e);
      if (first) seen_everywhere.insert(ids.begin(), ids.end());
      else
        for (auto it = seen_everywhere.begin(); it != seen_everywhere.end();)
          it = std::find(ids.begin(), ids.end(), *it) == ids.end() ? seen_everywhere.erase(it) : std::next(it);
      first = false;
    }
    for (std::int64_t id : x.aspect)
      EXPECT_TRUE(seen_everywhere.count(id)) << "triangle " << id << " of the crossing's aspect hidden nearby, at "
                                             << x.direction[0] << " " << x.direction[1] << " " << x.direction[2];
  }
}

// Part (i) of the crossings' proofs, against the oracle: every triangle of the aspect of a crossing X (given by a
// double approximation) is seen from the rational directions within 2^-24 of it (the approximation and its six
// axis neighbours, on all sides of the two arcs). Copying a neighbour's aspect or uniting the pieces' breaks it.
void check_crossings(const Scene& s, const std::vector<GeneralOrthographicResult::IrrationalCrossing>& crossings) {
  for (const auto& x : crossings) {
    std::vector<Vec3<Exact>> near;
    const Vec3<Exact> d(Exact(x.direction[0]), Exact(x.direction[1]), Exact(x.direction[2]));
    near.push_back(d);
    for (int k = 0; k < 3; ++k)
      for (int sg : {1, -1}) {
        Vec3<Exact> e = d;
        e[k] += Exact(sg, 1 << 24);
        near.push_back(e);
      }
    std::set<std::int64_t> seen_everywhere;
    bool first = true;
    for (const auto& e : near) {
      const auto ids = oracle_ids(s, e);
      if (first) seen_everywhere.insert(ids.begin(), ids.end());
      else
        for (auto it = seen_everywhere.begin(); it != seen_everywhere.end();)
          it = std::find(ids.begin(), ids.end(), *it) == ids.end() ? seen_everywhere.erase(it) : std::next(it);
      first = false;
    }
    for (std::int64_t id : x.aspect)
      EXPECT_TRUE(seen_everywhere.count(id)) << "triangle " << id << " of the crossing's aspect hidden nearby, at "
                                             << x.direction[0] << " " << x.direction[1] << " " << x.direction[2];
  }
}

// Terrains whose free EEE arcs cross inside faces of the circles (refused before session 11: "not certified
// apart"): the crossings are found exactly and cut the arcs (docs/theory.md 10.11, "EEE x EEE crossings"); every
// rational cell against the oracle, both sides of every segment, random directions, and each crossing's aspect
// against part (i). The 2 x 2 terrain of seed 7 (heights random.Random(7).randint(0, 3) / 2, i-major).
TEST(GeneralOrthographicAspectGraph, TerrainWithCrossingFreeEeeArcs) {
  const Scene s = terrain_grid({{1.0, 0.5, 1.5}, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.5}});
  const auto r = general(s);
  ASSERT_TRUE(r.ok) << r.problem;
  EXPECT_GT(r.eee_arcs, 0u);
  ASSERT_FALSE(r.eee_crossings.empty());
  std::printf("terrain seed 7: %zu regions, %zu EEE x EEE crossings\n", r.graph.regions.size(), r.eee_crossings.size());
  check_eee_graph(s, r, 22, 100);
  check_crossings(s, r.eee_crossings);
}

// The 2 x 2 terrains of seeds 40 and 41 (refused before session 11: two EEE arcs "not certified apart"), against
// the oracle as above.
TEST(GeneralOrthographicAspectGraph, TerrainsOfSeeds40And41) {
  for (const auto& h : std::vector<std::vector<std::vector<double>>>{{{1.5, 0.0, 0.5}, {1.0, 0.5, 0.5}, {1.0, 1.0, 1.5}},
                                                                    {{1.5, 1.0, 0.5}, {0.5, 1.5, 1.0}, {1.0, 1.5, 0.0}}}) {
    const Scene s = terrain_grid(h);
    const auto r = general(s);
    ASSERT_TRUE(r.ok) << r.problem;
    std::printf("terrain: %zu regions, %zu EEE x EEE crossings\n", r.graph.regions.size(), r.eee_crossings.size());
    check_eee_graph(s, r, 28, 100);
    check_crossings(s, r.eee_crossings);
  }
}

// The 2 x 2 terrain of seed 32 (refused before session 10): a free EEE arc touches a great circle of the
// partition (a double root of n . f, rational), now a cut point like a crossing (docs/theory.md 10.11 "Cuts").
// (Its two sub-arcs there do not end at one boundary point of one face: the session 9 order of such ends passes
// this test too, so the straight-angle case of the sweep order has no failing-able test yet.)
TEST(GeneralOrthographicAspectGraph, TerrainWithAnEeeArcTouchingACircle) {
  const Scene s = terrain_grid({{0, 0.5, 0.5}, {1, 0.5, 1.5}, {0, 0, 0}});
  const auto r = general(s);
  ASSERT_TRUE(r.ok) << r.problem;
  EXPECT_GT(r.eee_arcs, 0u);
  EXPECT_GT(eee_adjacencies(r.graph), 0u);
  check_eee_graph(s, r, 20, 100);
}

// The 3 x 3 terrains of docs/performance.md (heights of Python's random.Random(seed).randint(0, 3) / 2, i-major),
// refused before session 11 (EEE arcs crossing; seed 2 also two arcs leaving a common point with one tangent,
// ordered since by the side of one arc's cone the other leaves on): the full oracle check. Disabled in the suite
// (about 200 CPU s for seed 1); run by hand with --gtest_also_run_disabled_tests (docs/performance.md).
TEST(GeneralOrthographicAspectGraph, DISABLED_ThreeByThreeTerrainsWithCrossingFreeEeeArcs) {
  for (const auto& h : std::vector<std::vector<std::vector<double>>>{
           {{0.5, 0, 1, 0}, {1.5, 1.5, 1.5, 1.5}, {0.5, 0, 1.5, 0}, {1.5, 1.5, 0, 1.5}},
           {{0, 0, 0, 1}, {0.5, 1, 1, 0.5}, {0, 0.5, 1.5, 1.5}, {1, 1.5, 1, 0}}}) {
    const Scene s = terrain_grid(h);
    const auto r = general(s);
    ASSERT_TRUE(r.ok) << r.problem;
    EXPECT_GT(r.eee_arcs, 0u);
    check_eee_graph(s, r, 24, 100);
    check_crossings(s, r.eee_crossings);
  }
}

// Three disjoint tetrahedra, each with one of three pairwise skew edges met by the line x = y = 0 (along x at
// z = 0, along y at z = 1, along (1, 1, 0) at z = 2), each tetrahedron on one side of the plane of its edge and
// that line: a closed solid with a free EEE family. Faces (a,b,c), (a,d,b), (b,d,c), (a,c,d) of each.
Scene skew_tetrahedra() {
  std::vector<Point3> v{{-1, 0, 0}, {1, 0, 0}, {0, -3, 0}, {0, -1, -1}, {0, -1, 1}, {0, 1, 1}, {3, 0, 1}, {1, 0, 1.5},
                        {-1, -1, 2}, {1, 1, 2}, {2, -2, 2}, {1, -1, 3}};
  std::vector<std::array<int, 3>> t;
  for (int b : {0, 4, 8})
    for (const auto& f : {std::array<int, 3>{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}})
      t.push_back({b + f[0], b + f[1], b + f[2]});
  return make_scene(v, t);
}

// Refused before session 11 (two of its EEE arcs leave a common point with one tangent): now a graph (96 regions),
// against the oracle like the terrains. Disabled in the suite (about 150 CPU s); run by hand with
// --gtest_also_run_disabled_tests (docs/performance.md).
TEST(GeneralOrthographicAspectGraph, DISABLED_ClosedSolidWithCrossingFreeEeeArcs) {
  const Scene s = skew_tetrahedra();
  const ClosedSolidFronts f = closed_solid_fronts(s);
  EXPECT_FALSE(f.ok) << "in the class of 10.5";
  EXPECT_TRUE(f.outside_class) << f.problem;
  const auto r = general(s);
  ASSERT_TRUE(r.ok) << r.problem;
  EXPECT_GT(r.eee_arcs, 0u);
  std::printf("three tetrahedra: %zu regions, %zu EEE x EEE crossings\n", r.graph.regions.size(), r.eee_crossings.size());
  check_eee_graph(s, r, 26, 150);
  check_crossings(s, r.eee_crossings);
}

// The U-shaped slot: the section (0,0) (3,0) (3,2) (2,2) (2,1) (1,1) (1,2) (0,2) in the xz-plane extruded along
// y over [0, 2] (the slot [1,2] x [0,2] x [1,2] cut out of a box): outside the class of 10.5 (the front part
// of a slot wall holds both arms), no free EEE arc.
Scene u_slot() {
  const double sx[8] = {0, 3, 3, 2, 2, 1, 1, 0}, sz[8] = {0, 0, 2, 2, 1, 1, 2, 2};
  std::vector<Point3> v;
  for (int k = 0; k < 8; ++k) v.push_back({sx[k], 0, sz[k]});
  for (int k = 0; k < 8; ++k) v.push_back({sx[k], 2, sz[k]});
  std::vector<std::array<int, 3>> t;
  const int tri[6][3] = {{0, 1, 4}, {1, 2, 3}, {1, 3, 4}, {0, 4, 5}, {0, 5, 7}, {5, 6, 7}};
  for (const auto& q : tri) {
    t.push_back({q[0], q[1], q[2]});
    t.push_back({8 + q[0], 8 + q[2], 8 + q[1]});
  }
  for (int k = 0; k < 8; ++k) {
    const int a = k, b = (k + 1) % 8;
    t.push_back({a, 8 + a, 8 + b});
    t.push_back({a, 8 + b, b});
  }
  return make_scene(v, t);
}

TEST(GeneralOrthographicAspectGraph, UShapedSlotOutsideTheClass) {
  const Scene s = u_slot();
  const ClosedSolidFronts f = closed_solid_fronts(s);
  EXPECT_FALSE(f.ok);
  EXPECT_TRUE(f.outside_class) << f.problem;
  const auto r = general(s);
  // Hand count (docs/theory.md 10.10): the cube's 26 sign cells, the arcs (+-1, 0, +) and the octants
  // (+,-,+), (-,+,+) split by the floor's triangles, the octants (+,-,-), (-,+,-) by the walls' triangles.
  EXPECT_EQ(r.graph.regions.size(), 32u);
  EXPECT_EQ(per_dimension(r.graph), (std::array<int, 3>{6, 14, 12}));
  EXPECT_EQ(r.graph.adjacency.size(), 90u);  // the cube's 72, each half of the symmetry trading 15 for 24
  // One split, checked by its aspects: in the octant (+,-,+), floor triangle 20 is hidden iff d_x >= d_z and
  // |d_y| <= 2 d_x (21 seen); in (+,-,-), wall triangle 22 is hidden iff |d_y| <= 2 |d_z| (23 seen).
  const auto seen = [&](const Vec3<Exact>& d, std::int64_t id) {
    const auto ids = oracle_ids(s, d);
    return std::find(ids.begin(), ids.end(), id) != ids.end();
  };
  EXPECT_FALSE(seen({Exact(2), Exact(-1), Exact(1)}, 20));
  EXPECT_TRUE(seen({Exact(2), Exact(-1), Exact(1)}, 21));
  EXPECT_TRUE(seen({Exact(1), Exact(-3), Exact(1)}, 20));
  EXPECT_TRUE(seen({Exact(1), Exact(-1), Exact(2)}, 20));
  EXPECT_FALSE(seen({Exact(1), Exact(-1), Exact(-1)}, 22));
  EXPECT_TRUE(seen({Exact(1), Exact(-1), Exact(-1)}, 23));
  EXPECT_TRUE(seen({Exact(1), Exact(-3), Exact(-1)}, 22));
  check_against_oracle(s, r.graph, 21, 60);
}

}  // namespace
