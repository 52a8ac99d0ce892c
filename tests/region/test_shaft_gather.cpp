// Shaft occluders gathered through the hierarchy (region/hierarchy_candidates.hpp,
// region/occluder_shaft.hpp): on random scenes of small triangles (so that whole BVH nodes lie outside a shaft
// plane), for cell faces and random targets, the pruned gathering gives exactly the occluders of the full scan
// of the query box's candidates (same triangles, same order, same functionals), and every candidate the
// pruning skipped is proved unable to meet the open shaft by an independent exact test: its three corners
// on the closed outer side of one of the shaft planes, checked with the generic rational plane_side. The
// pruned query with a test that never prunes equals both the index's candidates_in_box and a brute-force
// scan, on random boxes (also with excluded triangles). End to end: the from-region query and the hidden-box
// test give the same answers, witnesses and counters through the hierarchy as through the plain index, and
// the exact segment re-check (with and without the hierarchy) equals a brute force with the rational test.
#include "kernel/predicates.hpp"
#include "kernel/scene_generators.hpp"
#include "kernel/segment_triangle_intersection.hpp"
#include "kernel/triangle_index.hpp"
#include "region/box_visibility.hpp"
#include "region/from_region_visibility.hpp"
#include "region/hierarchy_candidates.hpp"
#include "region/occluder_shaft.hpp"
#include "region/stabbing_pair.hpp"
#include "region/triangle_bvh.hpp"
#include "region/witness.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

// n small triangles (corners within 1/2 of a centre in [-8, 8]^3, on the 1/64 grid when `grid`), grouped
// into objects of 6 so the hierarchy has object levels too.
Scene small_triangles(std::mt19937_64& rng, bool grid, int n) {
  Scene scene;
  std::uniform_real_distribution<double> centre(-8, 8), off(-0.5, 0.5);
  auto snap = [&](double x) { return grid ? std::round(x * 64) / 64 : x; };
  while (static_cast<int>(scene.triangles.size()) < n) {
    const Point3 c{centre(rng), centre(rng), centre(rng)};
    Point3 p[3];
    for (auto& q : p) q = {snap(c.x + off(rng)), snap(c.y + off(rng)), snap(c.z + off(rng))};
    if (collinear(p[0], p[1], p[2])) continue;
    const int v0 = static_cast<int>(scene.vertices.size());
    scene.vertices.insert(scene.vertices.end(), {p[0], p[1], p[2]});
    SceneTriangle t;
    t.id = static_cast<std::int64_t>(scene.triangles.size());
    t.v = {v0, v0 + 1, v0 + 2};
    t.object = static_cast<int>(scene.triangles.size() / 6);
    if (t.object >= static_cast<int>(scene.objects.size())) scene.objects.push_back({"o" + std::to_string(t.object)});
    scene.triangles.push_back(t);
  }
  return scene;
}

bool on_outer_side_of_a_plane(const std::vector<Plane3>& planes, const std::array<RationalPoint3, 3>& t) {
  for (const Plane3& pl : planes)
    if (plane_side(pl, t[0]) != Sign::Positive && plane_side(pl, t[1]) != Sign::Positive &&
        plane_side(pl, t[2]) != Sign::Positive)
      return true;
  return false;
}

}  // namespace

TEST(ShaftGather, HierarchyGivesTheFullScansOccluders) {
  std::mt19937_64 rng(911);
  int pairs = 0, occluders = 0;
  std::int64_t scanned = 0, gathered = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const Scene scene = small_triangles(rng, trial % 3 != 2, 600);
    const TriangleIndex index(scene);
    const TriangleBvh bvh = build_triangle_bvh(scene);
    const HierarchyCandidates finder{index, &scene, &bvh, {}};
    ASSERT_NE(hierarchy_of(hierarchy_candidates(index, scene, bvh)), nullptr);
    // Source: a face of a unit cell near the middle; targets: random scene triangles.
    const Exact lo(static_cast<long>(rng() % 5) - 2);
    const int axis = static_cast<int>(rng() % 3);
    Polygon3 source;
    for (int i = 0; i < 4; ++i) {
      RationalPoint3 p{lo, lo, lo};
      p[(axis + 1) % 3] = lo + Exact((i == 1 || i == 2) ? 1 : 0);
      p[(axis + 2) % 3] = lo + Exact(i >= 2 ? 1 : 0);
      source.push_back(p);
    }
    for (int k = 0; k < 6; ++k) {
      const auto target = static_cast<std::int64_t>(rng() % scene.triangles.size());
      const auto tri = triangle_points(scene, target);
      std::vector<RationalPoint3> pts = source;
      pts.insert(pts.end(), tri.begin(), tri.end());
      const Box3 box = enclosing_box(pts);
      const std::vector<std::int64_t> all = index.candidates_in_box(box);
      for (const auto& pair : stabbing_pairs(source, tri)) {
        ++pairs;
        const auto full = shaft_occluders(scene, all, target, pair);
        const auto fast = shaft_occluders(scene, finder, box, target, pair);
        ASSERT_EQ(fast.size(), full.size()) << "trial " << trial;
        for (std::size_t i = 0; i < fast.size(); ++i) {
          ++occluders;
          ASSERT_EQ(fast[i].triangle, full[i].triangle);
          ASSERT_EQ(fast[i].edges.size(), full[i].edges.size());
          for (std::size_t e = 0; e < fast[i].edges.size(); ++e) EXPECT_EQ(fast[i].edges[e], full[i].edges[e]);
        }
        const BoxPrune never = [](const Box3&) { return false; };
        ASSERT_EQ(finder.pruned(box, never), all);
        // The pruning rebuilt here from its definition, in rationals (a box whose corner of largest value is
        // strictly outside a shaft plane); every candidate it skips is proved unable to meet the open shaft
        // by the independent per-corner test.
        const std::vector<Plane3> planes = shaft_planes(pair);
        const BoxPrune outside = [&](const Box3& b) {
          for (const Plane3& p : planes) {
            const RationalPoint3 x{Exact(CGAL::sign(p.normal.x) > 0 ? b.hi.x : b.lo.x),
                                   Exact(CGAL::sign(p.normal.y) > 0 ? b.hi.y : b.lo.y),
                                   Exact(CGAL::sign(p.normal.z) > 0 ? b.hi.z : b.lo.z)};
            if (plane_side(p, x) == Sign::Negative) return true;
          }
          return false;
        };
        const std::vector<std::int64_t> listed = finder.pruned(box, outside);
        scanned += static_cast<std::int64_t>(all.size());
        gathered += static_cast<std::int64_t>(listed.size());
        for (const std::int64_t t : all)
          if (!std::binary_search(listed.begin(), listed.end(), t))
            ASSERT_TRUE(on_outer_side_of_a_plane(planes, triangle_points(scene, t))) << "trial " << trial;
      }
    }
  }
  EXPECT_GT(pairs, 100);
  EXPECT_GT(occluders, 100);
  EXPECT_LT(gathered * 4, scanned);  // the pruning does prune
}

TEST(ShaftGather, UnprunedQueryEqualsTheIndexAndBruteForce) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 10; ++trial) {
    const Scene scene = small_triangles(rng, trial % 2 == 0, 300);
    const TriangleIndex index(scene);
    const TriangleBvh bvh = build_triangle_bvh(scene, 1 + trial % 8);
    const HierarchyCandidates finder{index, &scene, &bvh, {}};
    const CandidateFinder brute = brute_force_candidates(scene);
    std::uniform_real_distribution<double> u(-9, 9), w(0, 6);
    const BoxPrune never = [](const Box3&) { return false; };
    for (int k = 0; k < 40; ++k) {
      Box3 b;
      for (int a = 0; a < 3; ++a) {
        b.lo[a] = std::round(u(rng) * 64) / 64;
        b.hi[a] = b.lo[a] + (k % 10 == 0 ? 0.0 : std::round(w(rng) * 64) / 64);  // also flat boxes
      }
      const auto got = finder.pruned(b, never);
      EXPECT_EQ(got, index.candidates_in_box(b));
      EXPECT_EQ(got, brute(b));
      EXPECT_EQ(finder(b), got);
    }
    const Box3 empty{{1, 1, 1}, {0, 2, 2}};
    EXPECT_TRUE(finder.pruned(empty, never).empty());
    // Excluded triangles (every third) are missing from both queries and only they.
    const HierarchyCandidates some{index, &scene, &bvh, [](std::int64_t t) { return t % 3 == 0; }};
    const Box3 b{{-4, -4, -4}, {4, 4, 4}};
    std::vector<std::int64_t> expected;
    for (const std::int64_t t : brute(b))
      if (t % 3 != 0) expected.push_back(t);
    EXPECT_EQ(some(b), expected);
    EXPECT_EQ(some.pruned(b, never), expected);
  }
}

// The exact segment re-check (segment_is_free: bounding boxes, semi-static layer, double and rational exact
// paths) over every candidate and through the hierarchy, against a brute force with the rational segment test
// alone, on random segments across towns: endpoints rational (not doubles), doubles exactly, and segments
// ending inside a scene triangle (skipped), whose endpoint lies in the plane of coplanar neighbours (the
// semi-static layer cannot certify those signs).
TEST(ShaftGather, SegmentCheckEqualsTheRationalBruteForce) {
  std::mt19937_64 rng(8);
  int free = 0, blocked = 0, doubles_blocked = 0;
  for (int trial = 0; trial < 3; ++trial) {
    const Scene scene = generate_scene("town", 400, static_cast<std::uint64_t>(trial + 3));
    const TriangleIndex index(scene);
    const TriangleBvh bvh = build_triangle_bvh(scene);
    const HierarchyCandidates finder{index, &scene, &bvh, {}};
    const Box3 bb = bounding_box(scene);
    std::uniform_real_distribution<double> u(0, 1);
    auto point = [&](bool dyadic) {
      RationalPoint3 x{Exact(bb.lo.x + u(rng) * (bb.hi.x - bb.lo.x)), Exact(bb.lo.y + u(rng) * (bb.hi.y - bb.lo.y)),
                       Exact(bb.lo.z + u(rng) * (bb.hi.z - bb.lo.z))};
      if (!dyadic) x = x + Exact(1, 3 * 1024) * RationalPoint3{Exact(1), Exact(-1), Exact(1)};
      return x;
    };
    const std::vector<std::int64_t> all = index.candidates_in_box(bb);
    for (int k = 0; k < 300; ++k) {
      auto skip = static_cast<std::int64_t>(rng() % scene.triangles.size());
      const RationalPoint3 p = point(k % 2 == 0);
      RationalPoint3 q;
      if (k % 3 == 0) {  // inside triangle `skip` (weights 1/3 + small: in the relative interior)
        const auto t = triangle_points(scene, skip);
        const Exact w0 = Exact(1, 3) + Exact(static_cast<int>(rng() % 64), 1024), w1 = Exact(1, 3);
        q = t[0] + w0 * (t[1] - t[0]) + w1 * (t[2] - t[0]);
      } else {
        q = k % 3 == 1 ? p + Exact(1, 8) * (point(true) - p) : point(k % 2 == 0);
      }
      bool expected = true;
      for (std::size_t i = 0; i < scene.triangles.size() && expected; ++i) {
        if (static_cast<std::int64_t>(i) == skip) continue;
        const auto t = triangle_points(scene, static_cast<std::int64_t>(i));
        expected = !open_segment_meets_closed_triangle(p, q, t[0], t[1], t[2]);
      }
      ASSERT_EQ(segment_is_free(scene, all, p, q, skip), expected) << "trial " << trial << " segment " << k;
      ASSERT_EQ(segment_is_free(scene, finder, bb, p, q, skip), expected) << "trial " << trial << " segment " << k;
      (expected ? free : blocked) += 1;
      const bool doubles = k % 6 == 2;  // both endpoints doubles exactly
      if (doubles && !expected) ++doubles_blocked;
    }
  }
  EXPECT_GT(free, 50);
  EXPECT_GT(blocked, 100);
  EXPECT_GT(doubles_blocked, 10);
}

namespace {

void expect_same_stats(const VisibilityStats& a, const VisibilityStats& b) {
  EXPECT_EQ(a.stabbing_pairs, b.stabbing_pairs);
  EXPECT_EQ(a.occluders_considered, b.occluders_considered);
  EXPECT_EQ(a.effective_occluders, b.effective_occluders);
  EXPECT_EQ(a.samples_cast, b.samples_cast);
  EXPECT_EQ(a.splits, b.splits);
  EXPECT_EQ(a.cones_created, b.cones_created);
  EXPECT_EQ(a.real_line_tests, b.real_line_tests);
  EXPECT_EQ(a.accepted_by_sampling, b.accepted_by_sampling);
}

}  // namespace

TEST(ShaftGather, QueriesThroughTheHierarchyEqualThePlainIndex) {
  std::mt19937_64 rng(42);
  int visible = 0, hidden = 0, boxes = 0;
  for (int trial = 0; trial < 4; ++trial) {
    // Generated towns and forests (hidden triangles and hidden boxes), a street-level cell near a corner.
    const Scene scene = generate_scene(trial % 2 == 0 ? "town" : "forest", 300, static_cast<std::uint64_t>(trial + 1));
    const TriangleIndex index(scene);
    const TriangleBvh bvh = build_triangle_bvh(scene);
    const CandidateFinder plain = index_candidates(index);
    const CandidateFinder gathered = hierarchy_candidates(index, scene, bvh);
    const Box3 bb = bounding_box(scene);
    const RationalBox3 cell = exact_box({{bb.lo.x + 0.25, bb.lo.y + 0.25, 1}, {bb.lo.x + 1.5, bb.lo.y + 1.5, 2}});
    for (int k = 0; k < 10; ++k) {
      const auto t = static_cast<std::int64_t>(rng() % scene.triangles.size());
      const VisibilityResult a = visible_from_box(scene, plain, cell, t);
      const VisibilityResult b = visible_from_box(scene, gathered, cell, t);
      ASSERT_EQ(a.visible, b.visible) << "trial " << trial << " triangle " << t;
      (a.visible ? visible : hidden) += 1;
      ASSERT_EQ(a.witness.has_value(), b.witness.has_value());
      if (a.witness) {
        EXPECT_TRUE(a.witness->p == b.witness->p);
        EXPECT_TRUE(a.witness->q == b.witness->q);
      }
      expect_same_stats(a.stats, b.stats);
    }
    // Hidden-box tests: the nodes of the hierarchy apart from the cell, occluders = everything outside.
    for (std::size_t i = 1; i < bvh.nodes.size() && boxes < 6 * (trial + 1); i += 5) {
      const BvhNode& node = bvh.nodes[i];
      if (boxes_meet(cell, node.box)) continue;
      ++boxes;
      auto inside = [&](std::int64_t t) {
        const int pos = bvh.position[static_cast<std::size_t>(t)];
        return pos >= node.begin && pos < node.end;
      };
      const Box3 query = enclosing_box({cell.lo, cell.hi, to_rational(node.box.lo), to_rational(node.box.hi)});
      std::vector<std::int64_t> occluders;
      for (const std::int64_t t : index.candidates_in_box(query))
        if (!inside(t)) occluders.push_back(t);
      VisibilityStats sa, sb;
      const bool a = box_may_be_visible(scene, occluders, cell, node.box, {}, sa).may_be_visible;
      const bool b = box_may_be_visible(scene, HierarchyCandidates{index, &scene, &bvh, inside}, query, cell,
                                        node.box, {}, sb)
                         .may_be_visible;
      ASSERT_EQ(a, b) << "trial " << trial << " node " << i;
      expect_same_stats(sa, sb);
    }
  }
  EXPECT_GT(visible, 3);
  EXPECT_GT(hidden, 3);
  EXPECT_GT(boxes, 10);
}
