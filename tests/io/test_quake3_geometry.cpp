// The exact geometry of Quake 3 maps, on maps written by the tests' own writer:
// - leaf volumes: the doorway map's known volumes; on random trees, each leaf's vertex set equals the
//   brute-force oracle's for the half-spaces of its path (collected from the writer's tree), the volumes
//   sum exactly to the world box's, and every sample point lies in the interior of exactly the leaf that
//   an independent GMP descent of the writer's tree finds (and outside every other leaf);
// - brush polytopes: vertices satisfy every side plane exactly and equal the oracle's vertex set;
// - cluster regions, the two occluder sets (leaves: the cluster -1 leaves, including the never-solid
//   lintel; brushes: the solid brushes, including the detail pillar), outward triangles, OBJ output, drawn
//   triangles;
// - on Debian's openarena-data, when installed: one real map's leaves partition its world box.
#include "io/quake3_geometry.hpp"

#include "bsp_test_writer.hpp"
#include "io/load_scene.hpp"
#include "io_test_util.hpp"
#include "oracles/halfspace_oracle.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

using namespace exactvis;
using namespace exactvis::quake3;
using iotest::TempDir;
using iotest::write_file;

namespace {

mpq_class qn(const Exact& x) { return mpq_class(x.mpq()); }
oracle::QVec qv(const RationalPoint3& p) { return {qn(p.x), qn(p.y), qn(p.z)}; }
RationalPoint3 rp(const std::array<mpq_class, 3>& x) {
  return {Exact(x[0].get_mpq_t()), Exact(x[1].get_mpq_t()), Exact(x[2].get_mpq_t())};
}

BspMap read_written(const TempDir& dir, const bsptest::Bsp& b, const std::string& name = "map.bsp") {
  return read_bsp(write_file(dir.file(name), b.bytes()));
}

oracle::QHalfspace writer_halfspace(const bsptest::Plane& p, bool front) {
  const oracle::QVec n{mpq_class(double(p.n[0])), mpq_class(double(p.n[1])), mpq_class(double(p.n[2]))};
  const mpq_class d(double(p.d));
  if (front) return {n, d};
  return {{-n.x, -n.y, -n.z}, -d};
}

std::vector<oracle::QHalfspace> writer_box(const bsptest::Model& m) {
  return {{{1, 0, 0}, mpq_class(double(m.mins[0]))},  {{-1, 0, 0}, -mpq_class(double(m.maxs[0]))},
          {{0, 1, 0}, mpq_class(double(m.mins[1]))},  {{0, -1, 0}, -mpq_class(double(m.maxs[1]))},
          {{0, 0, 1}, mpq_class(double(m.mins[2]))},  {{0, 0, -1}, -mpq_class(double(m.maxs[2]))}};
}

// The closed half-spaces on the path to each leaf of the writer's tree (plus the world box), by leaf.
std::vector<std::vector<oracle::QHalfspace>> writer_leaf_paths(const bsptest::Bsp& b) {
  std::vector<std::vector<oracle::QHalfspace>> paths(b.leaves.size());
  std::vector<std::pair<int, std::vector<oracle::QHalfspace>>> stack{{0, writer_box(b.models[0])}};
  while (!stack.empty()) {
    auto [node, path] = stack.back();
    stack.pop_back();
    const bsptest::Node& n = b.nodes[node];
    for (int side = 0; side < 2; ++side) {
      std::vector<oracle::QHalfspace> p = path;
      p.push_back(writer_halfspace(b.planes[n.plane], side == 0));
      const int c = side == 0 ? n.front : n.back;
      if (c < 0) paths[-(c + 1)] = p;
      else stack.push_back({c, p});
    }
  }
  return paths;
}

// Our polyhedron against the oracle's vertex set for the half-spaces.
void expect_matches_oracle(const ConvexPolyhedron3& p, const std::vector<oracle::QHalfspace>& h) {
  const std::vector<oracle::QVec> want = oracle::halfspace_vertices(h);
  if (!oracle::spans_3d(want)) {
    EXPECT_TRUE(p.empty());
    return;
  }
  ASSERT_FALSE(p.empty());
  ASSERT_EQ(p.vertices.size(), want.size());
  for (const auto& v : p.vertices) {
    bool found = false;
    for (const auto& w : want) found = found || qv(v) == w;
    EXPECT_TRUE(found);
  }
}

mpq_class box_volume(const bsptest::Model& m) {
  mpq_class v(1);
  for (int k = 0; k < 3; ++k) v *= mpq_class(double(m.maxs[k])) - mpq_class(double(m.mins[k]));
  return v;
}

// A random point of the world box with coordinates lo + (hi - lo) * m / (3 * 2^10): almost never on a
// plane of float32 numbers (the descent oracle reports the rare ones, which are skipped).
std::array<mpq_class, 3> random_point(std::mt19937_64& rng, const bsptest::Model& m) {
  std::array<mpq_class, 3> x;
  for (int k = 0; k < 3; ++k) {
    const mpq_class u(static_cast<long>(1 + rng() % 3071), 3072);  // inside the box, not on its faces
    x[k] = mpq_class(double(m.mins[k])) + (mpq_class(double(m.maxs[k])) - mpq_class(double(m.mins[k]))) * u;
    x[k].canonicalize();
  }
  return x;
}

// Checks that the leaf volumes partition the world box: oracle vertex sets, the exact volume sum, and
// `samples` points each inside exactly the oracle's leaf.
void check_partition(const bsptest::Bsp& b, const BspMap& map, int samples, std::uint64_t seed) {
  const std::vector<ConvexPolyhedron3> volumes = leaf_volumes(map);
  ASSERT_EQ(volumes.size(), b.leaves.size());
  const auto paths = writer_leaf_paths(b);
  mpq_class sum(0);
  for (std::size_t i = 0; i < volumes.size(); ++i) {
    SCOPED_TRACE("leaf " + std::to_string(i));
    if (paths[i].empty()) EXPECT_TRUE(volumes[i].empty()) << "leaf outside the tree";
    else expect_matches_oracle(volumes[i], paths[i]);
    std::vector<std::array<oracle::QVec, 3>> tris;
    for (const auto& t : region::boundary_triangles(volumes[i])) tris.push_back({qv(t[0]), qv(t[1]), qv(t[2])});
    sum += oracle::enclosed_volume(tris);
  }
  EXPECT_EQ(sum, box_volume(b.models[0]));
  std::mt19937_64 rng(seed);
  int checked = 0;
  for (int s = 0; s < samples; ++s) {
    const auto x = random_point(rng, b.models[0]);
    const std::optional<int> want = bsptest::oracle_leaf_of(b, x);
    if (!want) continue;
    ++checked;
    const RationalPoint3 p = rp(x);
    EXPECT_EQ(leaf_containing(map, p), *want);
    for (std::size_t i = 0; i < volumes.size(); ++i)
      EXPECT_EQ(region::locate(volumes[i], p),
                static_cast<int>(i) == *want ? region::Containment::Interior : region::Containment::Outside)
          << "leaf " << i << " point " << x[0] << " " << x[1] << " " << x[2];
  }
  EXPECT_GT(checked, samples * 9 / 10);
}

// A random BSP tree over a world box: random planes (axis-aligned integer ones and slanted ones with
// non-dyadic float32 numbers), random depth, random clusters; no brushes or faces.
bsptest::Bsp random_tree_map(std::mt19937_64& rng) {
  bsptest::Bsp b;
  b.shaders = {{"textures/x", 0, 1}};
  b.models = {{{-64, -32, 0}, {64, 32, 48}, 0, 0, 0, 0}};
  b.leaves.push_back({});  // unused leaf 0, as q3map2 writes it
  auto coord = [&](int r) { return static_cast<float>(static_cast<long>(rng() % (2 * r + 1)) - r); };
  std::function<int(int)> build = [&](int depth) -> int {
    if (depth == 0 || rng() % 5 == 0) {
      bsptest::Leaf l;
      l.cluster = static_cast<int>(rng() % 4) - 1;
      b.leaves.push_back(l);
      return -static_cast<int>(b.leaves.size());  // -(index + 1)
    }
    int plane;
    switch (rng() % 3) {
      case 0: plane = b.add_plane(1, 0, 0, coord(60)); break;
      case 1: plane = b.add_plane(0, 0, -1, -coord(40)); break;
      default: plane = b.add_plane(coord(3) * 0.3f, coord(3) * 0.7f + 0.1f, coord(2) * 0.45f, coord(30) * 1.1f);
    }
    const int index = static_cast<int>(b.nodes.size());
    b.nodes.push_back({plane, 0, 0});
    const int front = build(depth - 1);
    const int back = build(depth - 1);
    b.nodes[index].front = front;
    b.nodes[index].back = back;
    return index;
  };
  b.nodes.reserve(64);
  if (build(6) < 0) {  // the root must be a node: wrap a lone leaf
    b.nodes.push_back({b.add_plane(1, 0, 0, 0), -2, -2});
    b.leaves.push_back({});
    b.nodes[0].back = -static_cast<int>(b.leaves.size());
  }
  b.has_vis = false;
  return b;
}

const char* kOpenArenaMap = "/usr/share/games/openarena/baseoa/pak1-maps.pk3:maps/oa_dm1.bsp";

}  // namespace

TEST(Quake3Geometry, DoorwayLeafVolumes) {
  TempDir dir;
  const bsptest::Bsp b = bsptest::doorway_map().bsp;
  const BspMap map = read_written(dir, b);
  const std::vector<ConvexPolyhedron3> v = leaf_volumes(map);
  ASSERT_EQ(v.size(), 9u);
  EXPECT_TRUE(v[0].empty());
  EXPECT_TRUE(v[8].empty());
  EXPECT_EQ(region::volume(v[1]), Exact(120 * 128 * 128));
  EXPECT_EQ(region::volume(v[2]), Exact(16 * 48 * 128));
  EXPECT_EQ(region::volume(v[3]), Exact(16 * 48 * 128));
  EXPECT_EQ(region::volume(v[4]), Exact(16 * 32 * 32));
  EXPECT_EQ(region::volume(v[5]), Exact(16 * 32 * 96));
  EXPECT_GT(region::volume(v[6]), Exact(0));
  EXPECT_GT(region::volume(v[7]), Exact(0));
  EXPECT_EQ(region::volume(v[6]) + region::volume(v[7]), Exact(120 * 128 * 128));
  // The slanted plane's float32 numbers are taken exactly: some corners of room B are not doubles.
  bool non_double = false;
  for (const auto& p : v[6].vertices) {
    double d;
    non_double |= !exact_double(p.y, &d);
  }
  EXPECT_TRUE(non_double);
  check_partition(b, map, 1500, 1);
}

TEST(Quake3Geometry, RandomTreesPartitionTheWorldBox) {
  TempDir dir;
  std::mt19937_64 rng(77);
  int leaves = 0, empty = 0;
  for (int trial = 0; trial < 25; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const bsptest::Bsp b = random_tree_map(rng);
    const BspMap map = read_written(dir, b, "tree" + std::to_string(trial) + ".bsp");
    check_partition(b, map, 150, trial);
    for (const auto& v : leaf_volumes(map)) ++leaves, empty += v.empty();
  }
  EXPECT_GT(leaves, 300);
  EXPECT_GT(empty, 20);  // random planes leave some cells outside the box
}

TEST(Quake3Geometry, ClusterRegions) {
  TempDir dir;
  const BspMap map = read_written(dir, bsptest::doorway_map().bsp);
  const std::vector<ClusterRegion> regions = cluster_regions(map);
  ASSERT_EQ(regions.size(), 4u);
  // Leaves 0 and 8 also say cluster 0 but are outside the world tree.
  EXPECT_EQ(regions[0].leaves, std::vector<std::int32_t>{1});
  EXPECT_EQ(regions[1].leaves, std::vector<std::int32_t>{6});
  EXPECT_EQ(regions[2].leaves, std::vector<std::int32_t>{5});
  EXPECT_EQ(regions[3].leaves, std::vector<std::int32_t>{7});
  for (const auto& r : regions) {
    ASSERT_EQ(r.volumes.size(), 1u);
    EXPECT_FALSE(r.volumes[0].empty());
  }
  EXPECT_EQ(region::volume(regions[2].volumes[0]), Exact(16 * 32 * 96));
}

TEST(Quake3Geometry, BrushPolytopes) {
  TempDir dir;
  bsptest::Bsp b = bsptest::doorway_map().bsp;
  // Random convex brushes: a box cut by slanted sides with float32 numbers (fixed seed).
  std::mt19937_64 rng(5);
  auto f = [&](int r) { return static_cast<float>(static_cast<long>(rng() % (2 * r + 1)) - r); };
  for (int k = 0; k < 30; ++k) {
    const int first = static_cast<int>(b.sides.size());
    const float cx = 128 + f(60), cy = 64 + f(30), cz = 64 + f(30);
    int n = 0;
    for (int axis = 0; axis < 3; ++axis)
      for (int s = -1; s <= 1; s += 2) {
        float nv[3] = {0, 0, 0};
        nv[axis] = float(s);
        const float c[3] = {cx, cy, cz};
        b.sides.push_back({b.add_plane(nv[0], nv[1], nv[2], s * c[axis] + 20), 0});
        ++n;
      }
    for (int extra = 0; extra < 3; ++extra, ++n) {
      const float nx = f(4) * 0.3f, ny = f(4) * 0.7f, nz = f(4) * 0.11f + 0.05f;
      b.sides.push_back({b.add_plane(nx, ny, nz, nx * cx + ny * cy + nz * cz + f(10) * 0.9f + 1.5f), 0});
    }
    b.brushes.push_back({first, n, 0});
  }
  b.models[0].n_brushes = static_cast<int>(b.brushes.size());
  b.models[1] = {{0, 0, 0}, {1, 1, 1}, 4, 0, 0, 0};
  const BspMap map = read_written(dir, b);
  const std::vector<oracle::QHalfspace> box = writer_box(b.models[0]);
  int nonempty = 0;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(b.brushes.size()); ++i) {
    SCOPED_TRACE("brush " + std::to_string(i));
    const ConvexPolyhedron3 p = brush_polyhedron(map, i);
    std::vector<oracle::QHalfspace> h = box;
    for (int s = 0; s < b.brushes[i].n_sides; ++s)
      h.push_back(writer_halfspace(b.planes[b.sides[b.brushes[i].first_side + s].plane], false));
    // Every vertex satisfies every side (n . v <= d) exactly, and lies on at least three of the planes.
    for (const auto& v : p.vertices) {
      int on = 0;
      for (const auto& hs : h) {
        const mpq_class val = oracle::dot(hs.n, qv(v)) - hs.d;
        EXPECT_GE(val, 0);
        on += val == 0;
      }
      EXPECT_GE(on, 3);
    }
    expect_matches_oracle(p, h);
    nonempty += !p.empty();
  }
  EXPECT_GT(nonempty, 25);
  // The first wall brush exactly.
  const ConvexPolyhedron3 wall = brush_polyhedron(map, 0);
  EXPECT_EQ(wall.vertices.size(), 8u);
  EXPECT_EQ(region::volume(wall), Exact(16 * 48 * 128));
}

TEST(Quake3Geometry, OccluderSets) {
  TempDir dir;
  const BspMap map = read_written(dir, bsptest::doorway_map().bsp);
  EXPECT_EQ(solid_world_brushes(map), (std::vector<std::int32_t>{0, 1, 3}));  // not the lintel, not model 1's door
  EXPECT_FALSE(is_solid_brush(map, 2));
  std::vector<std::int32_t> leaves, brushes;
  for (const auto& s : opaque_solids(map, Occluders::Leaves)) leaves.push_back(s.index);
  for (const auto& s : opaque_solids(map, Occluders::Brushes)) brushes.push_back(s.index);
  EXPECT_EQ(leaves, (std::vector<std::int32_t>{2, 3, 4}));   // the lintel leaf blocks vis although never solid
  EXPECT_EQ(brushes, (std::vector<std::int32_t>{0, 1, 3}));  // the detail pillar is solid to the eye
  EXPECT_STREQ(occluders_name(Occluders::Leaves), "leaves");
  EXPECT_STREQ(occluders_name(Occluders::Brushes), "brushes");
  for (Occluders occ : {Occluders::Leaves, Occluders::Brushes}) {
    const std::vector<OpaqueTriangle> tris = opaque_triangles(map, occ);
    EXPECT_EQ(tris.size(), 36u);  // three boxes, 12 triangles each
    // Outward: the solid's other corners are on the inner side of each triangle, some strictly.
    for (const auto& t : tris) {
      const oracle::QVec a = qv(t.corners[0]), n = oracle::cross(qv(t.corners[1]) - a, qv(t.corners[2]) - a);
      EXPECT_NE(oracle::sign(oracle::dot(n, n)), 0);
      int behind = 0;
      for (const auto& u : tris) {
        if (u.solid != t.solid) continue;
        for (const auto& c : u.corners) {
          const int s = oracle::sign(oracle::dot(n, qv(c) - a));
          EXPECT_LE(s, 0);
          behind += s < 0;
        }
      }
      EXPECT_GT(behind, 0);
    }
  }
}

TEST(Quake3Geometry, OpaqueObjRoundTrip) {
  TempDir dir;
  const BspMap map = read_written(dir, bsptest::doorway_map().bsp);
  const std::string obj = dir.file("opaque.obj");
  write_opaque_obj(obj, map, Occluders::Leaves);
  const Scene s = load_scene(obj);
  ASSERT_EQ(s.triangles.size(), 36u);
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.objects[0].name, "leaf_2");
  EXPECT_EQ(s.objects[2].name, "leaf_4");
  const Box3 box = bounding_box(s);
  EXPECT_EQ(box.lo.x, 120);
  EXPECT_EQ(box.hi.x, 136);
  EXPECT_EQ(box.hi.z, 128);
  const Scene brushes = opaque_scene(map, Occluders::Brushes);
  EXPECT_EQ(brushes.objects[2].name, "brush_3");
  EXPECT_EQ(brushes.degenerate_dropped, 0);
  // An unwritable destination: OutputError, no file.
  EXPECT_ANY_THROW(write_opaque_obj(dir.file("no/such/dir/x.obj"), map, Occluders::Leaves));
}

TEST(Quake3Geometry, DrawnTriangles) {
  TempDir dir;
  const BspMap map = read_written(dir, bsptest::doorway_map().bsp);
  const Scene s = drawn_scene(map);
  ASSERT_EQ(s.triangles.size(), 3u);  // the quad's two and the mesh's one; patch and billboard skipped
  EXPECT_EQ(s.triangles[0].v, (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(s.triangles[1].v, (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(s.triangles[2].v, (std::array<int, 3>{4, 5, 6}));
  EXPECT_EQ(s.objects[s.triangles[2].object].name, "face_1");
  EXPECT_EQ(s.vertices[6].z, 10.5);
}

TEST(Quake3Geometry, OpenArenaMapPartitionsItsWorldBox) {
  std::error_code ec;
  if (!std::filesystem::exists("/usr/share/games/openarena/baseoa/pak1-maps.pk3", ec))
    GTEST_SKIP() << "openarena-data is not installed";
  const BspMap map = read_bsp(kOpenArenaMap);
  const std::vector<ConvexPolyhedron3> volumes = leaf_volumes(map);
  const WorldBox box = world_box(map);
  Exact sum(0);
  for (std::size_t i = 0; i < volumes.size(); ++i) {
    if (!map.world_leaf[i]) {
      EXPECT_TRUE(volumes[i].empty());
    }
    sum += region::volume(volumes[i]);
  }
  EXPECT_EQ(sum, (box.hi.x - box.lo.x) * (box.hi.y - box.lo.y) * (box.hi.z - box.lo.z));
  // Sample points: inside the leaf the descent finds, and in no other leaf whose bounds could hold it.
  std::mt19937_64 rng(9);
  for (int s = 0; s < 200; ++s) {
    RationalPoint3 p;
    for (int k = 0; k < 3; ++k) p[k] = box.lo[k] + (box.hi[k] - box.lo[k]) * Exact(static_cast<int>(1 + rng() % 3071), 3072);
    const std::int32_t leaf = leaf_containing(map, p);
    const region::Containment c = region::locate(volumes[leaf], p);
    EXPECT_NE(c, region::Containment::Outside);
    if (c != region::Containment::Interior) continue;
    for (std::size_t i = 0; i < volumes.size(); ++i)
      if (static_cast<std::int32_t>(i) != leaf) {
        EXPECT_EQ(region::locate(volumes[i], p), region::Containment::Outside);
      }
  }
  // Cluster -1 leaves and solid brushes both give closed outward surfaces.
  EXPECT_GT(opaque_triangles(map, Occluders::Leaves).size(), 1000u);
  EXPECT_GT(opaque_triangles(map, Occluders::Brushes).size(), 1000u);
}
