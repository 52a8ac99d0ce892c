// The interval rejection before the convex-solid proof (region/solid_miss_filter.hpp): whenever it claims
// that a corner-to-corner segment misses a solid, the exact test (solid_blocks_box_pair, exact rational
// clipping, and segment_meets_solid on every corner pair) agrees; and it rejects most of the failing tests
// (what it is for), on generated forests (crowns and trunks are the closed convex solids) from street cells.
#include "kernel/scene_generators.hpp"
#include "region/convex_occluder.hpp"
#include "region/solid_miss_filter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

std::array<RationalPoint3, 8> corners(const RationalBox3& b) {
  std::array<RationalPoint3, 8> c;
  for (int k = 0; k < 8; ++k) c[k] = {(k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z};
  return c;
}

// Does the segment p q pass through the box (slab test in doubles; only chooses the cases to test)?
bool passes(const Point3& p, const Point3& q, const Box3& box) {
  double t0 = 0, t1 = 1;
  for (int k = 0; k < 3; ++k) {
    const double d = q[k] - p[k];
    if (d == 0) {
      if (p[k] < box.lo[k] || p[k] > box.hi[k]) return false;
      continue;
    }
    double a = (box.lo[k] - p[k]) / d, b = (box.hi[k] - p[k]) / d;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a), t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

Point3 centre(const Box3& b) { return {(b.lo.x + b.hi.x) / 2, (b.lo.y + b.hi.y) / 2, (b.lo.z + b.hi.z) / 2}; }

}  // namespace

TEST(SolidMissFilter, ClaimsOnlyMissesTheExactTestConfirms) {
  std::int64_t claims = 0, failing = 0, blocking = 0;
  for (unsigned seed = 1; seed <= 2; ++seed) {
    const Scene scene = generate_scene("forest", 1000, seed);
    const std::vector<ConvexSolid> solids = convex_solids(scene);
    ASSERT_GT(solids.size(), 10u);
    const Box3 bb = bounding_box(scene);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    for (int c = 0; c < 6; ++c) {
      const double x = bb.lo.x + (bb.hi.x - bb.lo.x) * u(rng), y = bb.lo.y + (bb.hi.y - bb.lo.y) * u(rng);
      // A non-dyadic side (1/3) so the cell's corners are not doubles: the filter's enclosures are exercised.
      const RationalBox3 cell{{Exact(x), Exact(y), Exact(1)}, {Exact(x) + Exact(4, 3), Exact(y) + Exact(4, 3), Exact(2)}};
      std::vector<std::size_t> listed(solids.size());
      for (std::size_t k = 0; k < solids.size(); ++k) listed[k] = k;
      const SolidMissFilter filter(solids, listed, cell);
      const Box3 cell_d = approximate_box(cell);
      for (std::size_t t = 0; t < scene.triangles.size(); t += 2) {
        const Box3 target = triangle_box(scene, scene.triangles[t]);
        const RationalBox3 exact_target = exact_box(target);
        // The solids conservative tries: near the segment between the box centres (single_occluder_culling).
        for (std::size_t k = 0; k < solids.size(); ++k) {
          if (!passes(centre(cell_d), centre(target), solids[k].box)) continue;
          if (!box_disjoint_from_solid(solids[k], cell) || !box_disjoint_from_solid(solids[k], exact_target)) continue;
          const bool claim = filter.proves_miss(k, target);
          const bool blocks = solid_blocks_box_pair(solids[k], cell, exact_target);
          blocking += blocks;
          failing += !blocks;
          if (!claim) continue;
          ++claims;
          ASSERT_FALSE(blocks) << "seed " << seed << " triangle " << t << " solid " << k;
          // And some corner pair really misses the solid (exact clipping).
          bool some_miss = false;
          for (const auto& a : corners(cell))
            for (const auto& b : corners(exact_target)) some_miss = some_miss || !segment_meets_solid(solids[k], a, b);
          ASSERT_TRUE(some_miss);
        }
      }
    }
  }
  std::cout << claims << " rejections of " << failing << " failing exact tests (" << blocking << " blocking)\n";
  EXPECT_GT(blocking, 40) << "few blocking pairs: the cases are too easy";
  EXPECT_GT(claims, failing / 2) << "the filter rejects too little to be worth its cost";
}

TEST(SolidMissFilter, AnUnlistedSolidIsNeverRejected) {
  const Scene scene = generate_scene("forest", 500, 4);
  const std::vector<ConvexSolid> solids = convex_solids(scene);
  ASSERT_FALSE(solids.empty());
  const RationalBox3 cell = exact_box({{-1000, -1000, 1}, {-999, -999, 2}});
  const SolidMissFilter none(solids, {}, cell);
  EXPECT_FALSE(none.proves_miss(0, solids[0].box));
  EXPECT_FALSE(SolidMissFilter().proves_miss(0, solids[0].box));
}
