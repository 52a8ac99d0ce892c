// The sampled PVS (region/sampled_pvs.hpp): it never lists a hidden triangle. Every listed triangle's witness
// is re-checked by the independent oracle and the triangle must be in the exact PVS; adversarial scenes
// where Embree's float32 hits are wrong (a hidden triangle 1e-7 behind a wall, coplanar in float32; a wall of
// two quads sharing an edge) must not leak; results do not depend on the thread count.
#include "region/sampled_pvs.hpp"

#include "kernel/scene_generators.hpp"
#include "oracles/visibility_oracle.hpp"
#include "region/exact_pvs.hpp"
#include "tests/region/oracle_input.hpp"

#include <gtest/gtest.h>

using namespace exactvis;
using namespace exactvis::region;

namespace {

using region_test::qv;

Scene scene_of(const std::vector<std::array<Point3, 3>>& tris) {
  Scene s;
  for (const auto& t : tris) {
    SceneTriangle st;
    st.id = static_cast<std::int64_t>(s.triangles.size());
    for (int k = 0; k < 3; ++k) {
      st.v[k] = static_cast<int>(s.vertices.size());
      s.vertices.push_back(t[static_cast<std::size_t>(k)]);
    }
    s.triangles.push_back(st);
  }
  s.faces_read = static_cast<std::int64_t>(s.triangles.size());
  s.objects.push_back({"all"});
  return s;
}

// Every listed triangle: witness valid for the oracle, and in the exact PVS.
void expect_only_visible(const Scene& scene, const RationalBox3& cell, const CellPvs& sampled) {
  const auto os = region_test::oracle_scene(scene);
  const oracle::Source src = region_test::oracle_box(cell.lo, cell.hi);
  const CellPvs exact = exact_cell_pvs(PvsContext(scene), cell, {});
  std::vector<bool> visible(scene.triangles.size(), false);
  for (const auto& v : exact.visible) visible[static_cast<std::size_t>(v.index)] = true;
  for (const auto& v : sampled.visible) {
    EXPECT_TRUE(visible[static_cast<std::size_t>(v.index)]) << "sampled lists hidden triangle " << v.index;
    ASSERT_TRUE(v.witness.has_value());
    std::string why;
    EXPECT_TRUE(oracle::witness_is_valid(os, static_cast<std::size_t>(v.index), src, qv(v.witness->p), qv(v.witness->q), &why))
        << v.index << ": " << why;
  }
}

}  // namespace

TEST(SampledPvs, NeverListsAHiddenTriangleOnATown) {
  const Scene scene = generate_scene("town", 200, 7);
  const RationalBox3 cell{{Exact(1, 3), Exact(1, 3), Exact(1, 2)}, {Exact(7, 3), Exact(5, 3), Exact(3, 2)}};
  PvsOptions options;
  options.cell_rays = 20000;
  const CellPvs sampled = sampled_cell_pvs(PvsContext(scene), cell, options);
  EXPECT_GT(sampled.stats.visible, 0);
  EXPECT_EQ(sampled.stats.rays_cast, 20000);
  expect_only_visible(scene, cell, sampled);
}

TEST(SampledPvs, FloatCoplanarHiddenTriangleDoesNotLeak) {
  // Wall at x = 10; the target 1e-7 behind it (x = 10 + 1e-7: the same float32 as 10), smaller than the wall.
  const double x = 10 + 1e-7;
  const Scene scene = scene_of({{Point3{10, -5, -5}, Point3{10, 5, -5}, Point3{10, 5, 5}},
                                {Point3{10, -5, -5}, Point3{10, 5, 5}, Point3{10, -5, 5}},
                                {Point3{x, -1, -1}, Point3{x, 1, -1}, Point3{x, 0, 1}}});
  const RationalBox3 cell = exact_box({{0, -0.5, -0.5}, {1, 0.5, 0.5}});
  PvsOptions options;
  options.cell_rays = 40000;
  const CellPvs sampled = sampled_cell_pvs(PvsContext(scene), cell, options);
  for (const auto& v : sampled.visible) EXPECT_NE(v.index, 2) << "the hidden target was listed";
  EXPECT_GT(sampled.stats.visible, 0);  // the wall is seen
  expect_only_visible(scene, cell, sampled);
}

TEST(SampledPvs, SharedEdgeWallDoesNotLeakAndThreadsDoNotMatter) {
  // A wall of two quads meeting along y = 0 exactly (a zero-width slit), the target right behind the seam.
  const Scene scene = scene_of({{Point3{5, -10, -10}, Point3{5, 0, -10}, Point3{5, 0, 10}},
                                {Point3{5, -10, -10}, Point3{5, 0, 10}, Point3{5, -10, 10}},
                                {Point3{5, 0, -10}, Point3{5, 10, -10}, Point3{5, 10, 10}},
                                {Point3{5, 0, -10}, Point3{5, 10, 10}, Point3{5, 0, 10}},
                                {Point3{10, -1, -1}, Point3{10, 1, -1}, Point3{10, 0, 1}}});
  const RationalBox3 cell = exact_box({{-1, -1, -1}, {0, 1, 1}});
  PvsOptions options;
  options.cell_rays = 30000;
  options.threads = 1;
  const CellPvs one = sampled_cell_pvs(PvsContext(scene), cell, options);
  options.threads = 2;
  const CellPvs two = sampled_cell_pvs(PvsContext(scene), cell, options);
  ASSERT_EQ(one.visible.size(), two.visible.size());
  for (std::size_t i = 0; i < one.visible.size(); ++i) {
    EXPECT_EQ(one.visible[i].index, two.visible[i].index);
    EXPECT_TRUE(one.visible[i].witness->p == two.visible[i].witness->p && one.visible[i].witness->q == two.visible[i].witness->q);
  }
  for (const auto& v : one.visible) EXPECT_NE(v.index, 4);
  expect_only_visible(scene, cell, one);
  EXPECT_THROW(sampled_cell_pvs(PvsContext(scene), RationalBox3{cell.hi, cell.lo}, options), std::invalid_argument);
}
