// Single-occluder culling (region/single_occluder_culling.hpp), the wall and convex-solid proofs shared by
// methods `conservative` and `exact`: on randomized scenes where a tiny aperture in a wall is the only way
// to the triangles behind it, with closed boxes in front of and behind the wall, nothing it proves hidden is
// visible. The reference is the per-triangle line-space query with O(n) brute-force candidates (it shares
// no code with the wall/solid proofs), and every proved-hidden triangle is attacked by the independent
// oracle's exact-confirmed random segments (tests/oracles).
#include "oracles/visibility_oracle.hpp"
#include "region/exact_pvs.hpp"
#include "region/from_region_visibility.hpp"
#include "region/single_occluder_culling.hpp"
#include "tests/region/oracle_input.hpp"
#include "tests/region/region_scene_builder.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

RationalBox3 box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return exact_box({{x0, y0, z0}, {x1, y1, z1}});
}

// Ground z = 0; a wall x = 0 over y, z in [0, 10] tiled by four rectangles around a square hole of side
// `hole` (at a random place; two tilings); a back wall x = 10; random small triangles behind the wall (x in 1 .. 9);
// closed boxes behind the wall and between the cell (x in [-6, -5]) and the wall. Coordinates on a 1/64 grid.
Scene aperture_yard(double hole, unsigned seed) {
  std::mt19937 rng(seed);
  auto coord = [&](double lo, double hi) { return lo + (hi - lo) * static_cast<double>(rng() % 1024) / 1024.0; };
  region_test::SceneBuilder b;
  b.scene.objects[0].name = "wall";
  const double cy = coord(3, 7), cz = coord(3, 7);
  const double y0 = cy - hole / 2, y1 = cy + hole / 2, z0 = cz - hole / 2, z1 = cz + hole / 2;
  if (seed % 2 == 0) {  // full-height pieces left and right of the hole
    b.rect(0, 0, 0, y0, 0, 10);
    b.rect(0, 0, y1, 10, 0, 10);
    b.rect(0, 0, y0, y1, 0, z0);
    b.rect(0, 0, y0, y1, z1, 10);
  } else {  // full-width bands below and above it (their vertical umbrae decide)
    b.rect(0, 0, 0, 10, 0, z0);
    b.rect(0, 0, 0, 10, z1, 10);
    b.rect(0, 0, 0, y0, z0, z1);
    b.rect(0, 0, y1, 10, z0, z1);
  }
  b.rect(0, 10, 0, 10, 0, 10);
  b.object("ground");
  b.rect(2, 0, -8, 12, -2, 12);
  for (int k = 0; k < 4; ++k) {
    b.object("box" + std::to_string(k));
    const bool front = k < 2;
    const Point3 lo{front ? coord(-4, -2) : coord(1.5, 8), coord(1, 8), coord(1, 8)};
    b.box(lo, {lo.x + coord(0.3, 1), lo.y + coord(0.3, 1.5), lo.z + coord(0.3, 1.5)});
  }
  b.object("behind");
  for (int i = 0; i < 30; ++i) {
    const Point3 c{coord(1, 9), coord(1, 9), coord(1, 9)};
    b.triangle(c, {c.x + coord(-1, 1), c.y + coord(0.1, 1), c.z}, {c.x, c.y + coord(-1, 1), c.z + coord(0.1, 1)});
  }
  return b.scene;
}

TEST(SingleOccluderCulling, NeverHidesWhatATinyApertureShows) {
  std::int64_t proved = 0, nodes_proved = 0, seen_through = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const double hole = 0.03 + 0.1 * (seed % 3);
    const Scene scene = aperture_yard(hole, seed);
    const PvsContext context(scene);
    const int s = static_cast<int>(seed);
    const RationalBox3 cell = box(-6, 2 + s % 4, 2 + s % 3, -5, 4 + s % 4, 6 + s % 3);
    const CandidateFinder brute = brute_force_candidates(scene);
    const std::size_t n = scene.triangles.size();
    std::vector<char> visible(n, 0);
    for (std::size_t i = 0; i < n; ++i) visible[i] = visible_from_box(scene, brute, cell, static_cast<std::int64_t>(i)).visible;
    for (std::size_t i = 10; i < n; ++i) seen_through += visible[i] && scene.corner(scene.triangles[i], 0).x > 0;

    const SingleOccluderCulling proofs(context, cell);
    ASSERT_TRUE(proofs.any());
    const std::vector<oracle::Triangle> os = region_test::oracle_scene(scene);
    const oracle::Source src = region_test::oracle_box(cell.lo, cell.hi);
    for (std::size_t i = 0; i < n; ++i) {
      std::ptrdiff_t hint = -1;
      if (!proofs.hides_triangle(static_cast<std::int64_t>(i), hint)) continue;
      ++proved;
      EXPECT_FALSE(visible[i]) << "seed " << seed << ": visible triangle " << i << " proved hidden";
      EXPECT_FALSE(oracle::find_robust_free_segment(os, i, src, 40, 91 + i).has_value())
          << "seed " << seed << ": triangle " << i << " proved hidden, the oracle found a free segment";
    }
    const TriangleBvh& bvh = context.bvh();
    for (const BvhNode& node : bvh.nodes) {
      std::ptrdiff_t hint = -1;
      if (node.end - node.begin < 2 || !proofs.hides_node(node, hint)) continue;
      ++nodes_proved;
      for (int k = node.begin; k < node.end; ++k)
        EXPECT_FALSE(visible[static_cast<std::size_t>(bvh.order[k])])
            << "seed " << seed << ": visible triangle " << bvh.order[k] << " inside a node proved hidden";
    }

    // The exact method with the proofs equals the reference, and uses them.
    const CellPvs pvs = exact_cell_pvs(context, cell, {});
    std::vector<char> reported(n, 0);
    for (const auto& v : pvs.visible) reported[static_cast<std::size_t>(v.index)] = 1;
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(reported[i], visible[i]) << "seed " << seed << " triangle " << i;
    EXPECT_GT(pvs.stats.culled_by_occluders, 0) << "seed " << seed;
    EXPECT_EQ(pvs.stats.culled + pvs.stats.accepted_by_rays + pvs.stats.exact_queries, pvs.stats.triangles);
  }
  EXPECT_GT(proved, 20);
  EXPECT_GT(nodes_proved, 0);
  EXPECT_GT(seen_through, 0);  // the aperture does show something behind the wall
}

}  // namespace
