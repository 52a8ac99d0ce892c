// region/convex_occluder against the independent GMP oracle: segments that the code says meet a solid are
// compared with an explicit segment/triangle test plus an inside test; "blocked" box pairs are attacked by
// random exact segments, each of which must meet a closed triangle of the solid.
#include "region/convex_occluder.hpp"

#include "oracles/rational_geometry.hpp"
#include "tests/region/pvs_test_scenes.hpp"
#include "tests/exact_to_mpq.hpp"

#include <gtest/gtest.h>

#include <random>

namespace exactvis::region {
namespace {

using pvs_test::SceneBuilder;

using exact_to_mpq::q;
oracle::QVec to_q(const RationalPoint3& p) { return {q(p.x), q(p.y), q(p.z)}; }
oracle::QVec to_q(const Point3& p) { return oracle::qvec(p.x, p.y, p.z); }

// Oracle: the closed (or open) segment meets a closed face triangle of the solid.
bool oracle_meets_surface(const Scene& scene, const ConvexSolid& s, const oracle::QVec& a, const oracle::QVec& b,
                          bool open = false) {
  for (const std::int64_t ti : s.triangles) {
    const auto& t = scene.triangles[ti];
    const oracle::QVec t0 = to_q(scene.corner(t, 0)), t1 = to_q(scene.corner(t, 1)), t2 = to_q(scene.corner(t, 2));
    if (open ? oracle::oracle_open_segment_meets_closed_triangle(a, b, t0, t1, t2)
             : oracle::oracle_closed_segment_meets_closed_triangle(a, b, t0, t1, t2))
      return true;
  }
  return false;
}

// Oracle: the closed segment meets the closed solid iff an endpoint is inside (same side of every face
// plane as the corners' centroid, or on it) or the segment meets a face triangle.
bool oracle_meets(const Scene& scene, const ConvexSolid& s, const oracle::QVec& a, const oracle::QVec& b) {
  oracle::QVec centroid{0, 0, 0};
  for (const std::int64_t ti : s.triangles)
    for (int k = 0; k < 3; ++k) centroid = centroid + to_q(scene.corner(scene.triangles[ti], k));
  centroid = mpq_class(1, 3 * static_cast<long>(s.triangles.size())) * centroid;
  auto inside = [&](const oracle::QVec& p) {
    for (const std::int64_t ti : s.triangles) {
      const auto& t = scene.triangles[ti];
      const oracle::QVec t0 = to_q(scene.corner(t, 0)), t1 = to_q(scene.corner(t, 1)), t2 = to_q(scene.corner(t, 2));
      const int ref = oracle::orient3d(t0, t1, t2, centroid), here = oracle::orient3d(t0, t1, t2, p);
      if (here != 0 && here != ref) return false;
    }
    return true;
  };
  return inside(a) || inside(b) || oracle_meets_surface(scene, s, a, b);
}

void tetrahedron(SceneBuilder& b, const Point3& p0, const Point3& p1, const Point3& p2, const Point3& p3) {
  b.triangle(p0, p1, p2);
  b.triangle(p0, p1, p3);
  b.triangle(p0, p2, p3);
  b.triangle(p1, p2, p3);
}

TEST(ConvexSolids, FindsClosedConvexComponentsOnly) {
  SceneBuilder b;
  b.scene.objects[0].name = "cube";
  b.box({0, 0, 0}, {2, 2, 2});
  b.object("open_box");  // a closed box minus its top: not a solid
  for (int axis = 0; axis < 3; ++axis)
    for (double w : {10.0, 12.0})
      if (!(axis == 2 && w == 12.0)) b.rect(axis, w, 10, 12, 10, 12);
  b.object("two_boxes");  // two solids in one object (edge-connected components)
  b.box({20, 0, 0}, {21, 1, 1});
  b.box({23, 0, 0}, {24, 1, 1});
  b.object("tetra");
  tetrahedron(b, {30, 0, 0}, {32, 0, 0}, {30, 2, 0}, {30, 0, 2});
  b.object("stacked");  // two boxes sharing a face: edge-connected, closed, but the shared face is inside
  b.box({40, 0, 0}, {41, 1, 1});
  b.box({40, 0, 1}, {41, 1, 2});
  const std::vector<ConvexSolid> solids = convex_solids(b.scene);
  std::vector<std::string> names;
  for (const ConvexSolid& s : solids) names.push_back(b.scene.objects[s.object].name);
  EXPECT_EQ(names, (std::vector<std::string>{"cube", "two_boxes", "two_boxes", "tetra"}));
  ASSERT_EQ(solids.size(), 4u);
  EXPECT_EQ(solids[0].facets.size(), 6u);
  EXPECT_EQ(solids[0].triangles.size(), 12u);
  EXPECT_EQ(solids[3].facets.size(), 4u);
}

TEST(ConvexSolids, SegmentMeetsSolidAgreesWithOracle) {
  SceneBuilder b;
  tetrahedron(b, {0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4});
  b.object("box");
  b.box({6, 0, 0}, {8, 3, 2});
  const std::vector<ConvexSolid> solids = convex_solids(b.scene);
  ASSERT_EQ(solids.size(), 2u);
  std::mt19937 rng(11);
  // Coordinates on a grid of quarters so that touching, coplanar and through-vertex cases are frequent.
  auto coord = [&] { return Exact(static_cast<int>(rng() % 24) - 4) / 4; };
  int met = 0, missed = 0;
  for (int i = 0; i < 4000; ++i) {
    const ConvexSolid& s = solids[i % 2];
    const RationalPoint3 p{coord() + (i % 2) * 6, coord(), coord()}, q{coord() + (i % 2) * 6, coord(), coord()};
    const bool got = segment_meets_solid(s, p, q);
    ASSERT_EQ(got, oracle_meets(b.scene, s, to_q(p), to_q(q))) << "segment " << i;
    (got ? met : missed)++;
  }
  EXPECT_GT(met, 400);
  EXPECT_GT(missed, 400);
}

RationalPoint3 random_point_in(const RationalBox3& box, std::mt19937& rng) {
  auto t = [&](int k) {
    const int r = static_cast<int>(rng() % 10);  // faces and corners often
    const Exact f = r < 2 ? Exact(0) : r < 4 ? Exact(1) : Exact(static_cast<int>(rng() % 1000)) / 1000;
    return box.lo[k] + f * (box.hi[k] - box.lo[k]);
  };
  return {t(0), t(1), t(2)};
}

TEST(ConvexSolids, BlockedBoxPairsSurviveRandomSegments) {
  std::mt19937 rng(5);
  int blocked = 0, not_blocked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // A wall-like box or a tetrahedron between x = 4 and x = 6, random cell and target boxes on both sides.
    SceneBuilder b;
    auto r = [&](int lo, int hi) { return static_cast<double>(lo + static_cast<int>(rng() % (hi - lo + 1))); };
    if (trial % 3 == 0) {
      const Point3 p0{4, r(-6, 0), r(-6, 0)}, p1{6, r(0, 6), r(-6, 0)}, p2{5, r(-6, 6), r(0, 6)},
          p3{r(4, 6), r(-2, 2), r(-2, 2)};
      // Scenes never hold zero-area triangles (the loader drops them): skip flat tetrahedra.
      if (oracle::orient3d(to_q(p0), to_q(p1), to_q(p2), to_q(p3)) == 0) continue;
      tetrahedron(b, p0, p1, p2, p3);
    } else b.box({4, r(-8, 0), r(-8, 0)}, {r(5, 6), r(1, 8), r(1, 8)});
    const std::vector<ConvexSolid> solids = convex_solids(b.scene);
    if (solids.size() != 1) continue;
    auto box = [&](int x0, int x1) {
      const double lo[3] = {r(x0, x1 - 1), r(-3, 2), r(-3, 2)};
      RationalBox3 bx;
      for (int k = 0; k < 3; ++k) bx.lo[k] = Exact(lo[k]), bx.hi[k] = Exact(lo[k] + r(0, 2));
      return bx;
    };
    // Sometimes both boxes overlap the solid (cells inside geometry are allowed).
    const RationalBox3 cell = trial % 10 == 9 ? box(4, 6) : box(0, 4), target = trial % 10 == 9 ? box(4, 6) : box(6, 10);
    const bool got = solid_blocks_box_pair(solids[0], cell, target);
    if (!got) {
      ++not_blocked;
      continue;
    }
    ++blocked;
    for (int k = 0; k < 60; ++k) {
      const RationalPoint3 p = random_point_in(cell, rng), q = random_point_in(target, rng);
      ASSERT_TRUE(oracle_meets_surface(b.scene, solids[0], to_q(p), to_q(q), /*open=*/true)) << "trial " << trial;
    }
  }
  EXPECT_GT(blocked, 30);
  EXPECT_GT(not_blocked, 30);
}

TEST(ConvexSolids, BoxesTouchingTheSolidAreNotBlocked) {
  // Every segment between two boxes inside a big solid meets the solid but not its surface.
  SceneBuilder b;
  b.box({0, 0, 0}, {10, 10, 10});
  const std::vector<ConvexSolid> solids = convex_solids(b.scene);
  ASSERT_EQ(solids.size(), 1u);
  RationalBox3 cell{{1, 1, 1}, {2, 2, 2}}, target{{7, 7, 7}, {8, 8, 8}};
  EXPECT_TRUE(segment_meets_solid(solids[0], cell.lo, target.hi));
  EXPECT_FALSE(solid_blocks_box_pair(solids[0], cell, target));
  // A cell outside, the target inside: segments to points inside cross the surface, but the target box
  // (like a decal's) is not apart from the solid, so nothing is claimed.
  cell = {{-3, 4, 4}, {-2, 5, 5}};
  EXPECT_FALSE(solid_blocks_box_pair(solids[0], cell, target));
  // A decal flush on the far face x = 10 (seen from a cell beyond it, the segments meet the solid only at
  // their end point on the decal): the target box touches the solid, so nothing is claimed.
  const RationalBox3 decal{{10, 4, 4}, {10, 6, 6}};
  EXPECT_FALSE(solid_blocks_box_pair(solids[0], {{12, 4, 4}, {13, 5, 5}}, decal));
  EXPECT_FALSE(solid_blocks_box_pair(solids[0], cell, decal));
  // A cell flush against the near face x = 0: the segments start on the surface.
  const RationalBox3 flush{{-1, 4, 4}, {0, 5, 5}}, behind{{12, 4, 4}, {13, 5, 5}};
  EXPECT_FALSE(solid_blocks_box_pair(solids[0], flush, behind));
  // Apart on both sides: blocked.
  EXPECT_TRUE(solid_blocks_box_pair(solids[0], cell, behind));
  // Segments that only touch the solid at their end point are not blocked (the open-segment rule).
  const RationalBox3 on_face{{10, 4, 4}, {11, 5, 5}};
  EXPECT_FALSE(solid_blocks_box_pair(solids[0], cell, on_face));
}

}  // namespace
}  // namespace exactvis::region
