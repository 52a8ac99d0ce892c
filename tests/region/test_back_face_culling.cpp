// Back faces of closed convex solids (region/back_face_culling.hpp): everything it proves hidden is hidden by
// the per-triangle line-space query with O(n) brute-force candidates (no code shared with the proof) and
// survives the independent oracle's exact-confirmed random segments (tests/oracles), on generated forests
// (octahedral crowns, box trunks) and on boxes with cells touching their face planes; the exact PVS with the
// proof equals the one without.
#include "kernel/scene_generators.hpp"
#include "oracles/visibility_oracle.hpp"
#include "region/back_face_culling.hpp"
#include "region/exact_pvs.hpp"
#include "region/from_region_visibility.hpp"
#include "tests/region/oracle_input.hpp"
#include "tests/region/region_scene_builder.hpp"

#include <gtest/gtest.h>

using namespace exactvis;
using namespace exactvis::region;

namespace {

RationalBox3 box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return exact_box({{x0, y0, z0}, {x1, y1, z1}});
}

// Every proved triangle is hidden (brute-force query and oracle refutation); returns how many were proved.
std::int64_t check_proofs(const Scene& scene, const RationalBox3& cell, const std::string& what) {
  const PvsContext context(scene);
  const BackFaceCulling culling(context, cell);
  const CandidateFinder brute = brute_force_candidates(scene);
  const std::vector<oracle::Triangle> os = region_test::oracle_scene(scene);
  const oracle::Source src = region_test::oracle_box(cell.lo, cell.hi);
  std::int64_t proved = 0;
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    if (!culling.hides_triangle(static_cast<std::int64_t>(i))) continue;
    ++proved;
    EXPECT_FALSE(visible_from_box(scene, brute, cell, static_cast<std::int64_t>(i)).visible)
        << what << ": visible triangle " << i << " proved hidden";
    EXPECT_FALSE(oracle::find_robust_free_segment(os, i, src, 30, 57 + i).has_value())
        << what << ": triangle " << i << " proved hidden, the oracle found a free segment";
  }
  return proved;
}

TEST(BackFaceCulling, ProvesOnlyHiddenTrianglesInForests) {
  std::int64_t proved = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const Scene scene = generate_scene("forest", 160, seed);
    const Box3 b = bounding_box(scene);
    const double w = b.hi.x - b.lo.x, d = b.hi.y - b.lo.y;
    // A cell at crown height near a corner and one in the middle (it may touch crowns: those are skipped).
    proved += check_proofs(scene, box(b.lo.x + 0.1 * w, b.lo.y + 0.1 * d, 1, b.lo.x + 0.3 * w, b.lo.y + 0.25 * d, 2),
                           "forest seed " + std::to_string(seed) + " corner");
    proved += check_proofs(scene, box(b.lo.x + 0.45 * w, b.lo.y + 0.4 * d, 0.5, b.lo.x + 0.55 * w, b.lo.y + 0.5 * d, 3),
                           "forest seed " + std::to_string(seed) + " middle");
  }
  EXPECT_GT(proved, 50);
}

// Boxes around a cell whose faces lie in the planes of box faces (orientation 0 at four cell corners): the
// proof accepts the plane itself, and a box face with the cell partly in front is never proved.
TEST(BackFaceCulling, CellsOnFacePlanesAndTouchingSolids) {
  region_test::SceneBuilder b;
  b.object("a");
  b.box({2, 0, 0}, {3, 1, 1});  // x from 2: the cell's face x = 1 is not in any of its planes
  b.object("b");
  b.box({-1, 0, 1}, {1, 1, 2});  // on top of the cell: touches it (z = 1), never usable
  b.object("c");
  b.box({0, 2, 0}, {1, 3, 1});   // the cell's planes x = 0, x = 1, z = 0, z = 1 are its face planes
  b.object("d");
  b.box({-3, -3, 0.5}, {-2, -2, 0.75});
  const RationalBox3 cell = box(0, 0, 0, 1, 1, 1);
  const std::int64_t proved = check_proofs(b.scene, cell, "boxes");
  const PvsContext context(b.scene);
  const BackFaceCulling culling(context, cell);
  for (int t = 12; t < 24; ++t) EXPECT_FALSE(culling.hides_triangle(t)) << "touching box, triangle " << t;
  // Box c (triangles 24..35, faces x = hi, x = lo, y = hi, y = lo, z = hi, z = lo): the cell is on the inner
  // side of x = 1, x = 0, y = 3 (closed: on the plane for x and z), in front of y = 2, and on the planes z = 1 /
  // z = 0 from inside: every face but y = lo is a back face.
  for (int t = 24; t < 36; ++t) EXPECT_EQ(culling.hides_triangle(t), t < 30 || t >= 32) << "box c, triangle " << t;
  EXPECT_EQ(proved, 10 + 10 + 4);  // a: all but x = lo; c: all but y = lo; d: x = lo, y = lo
}

TEST(BackFaceCulling, ExactPvsUnchanged) {
  const Scene scene = generate_scene("forest", 400, 5);
  const PvsContext context(scene);
  const Box3 b = bounding_box(scene);
  const RationalBox3 cell = box(b.lo.x + 0.5, b.lo.y + 0.5, 1, b.lo.x + 1.5, b.lo.y + 1.25, 2);
  PvsOptions off;
  off.back_faces = false;
  const CellPvs with = exact_cell_pvs(context, cell, {}), without = exact_cell_pvs(context, cell, off);
  ASSERT_EQ(with.visible.size(), without.visible.size());
  for (std::size_t k = 0; k < with.visible.size(); ++k) EXPECT_EQ(with.visible[k].index, without.visible[k].index);
  EXPECT_GT(with.stats.culled_by_back_faces, 0);
  EXPECT_EQ(without.stats.culled_by_back_faces, 0);
  EXPECT_LT(with.stats.exact_queries, without.stats.exact_queries);
  EXPECT_EQ(with.stats.culled + with.stats.accepted_by_rays + with.stats.exact_queries, with.stats.triangles);
}

}  // namespace
