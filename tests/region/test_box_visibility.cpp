// The hidden-box test (region/box_visibility.hpp, docs/theory.md §5.8) on pinhole rooms and small towns, for
// BVH nodes apart from the cell with every triangle outside the node's subtree as an occluder:
// - its answer equals an independent decomposition: the box is reached iff some pair (face of the cell, face
//   of the box), over all 6 x 6 pairs and with each box face fanned into triangles, is visible by
//   region/polygon_pair_visibility (a free segment from the cell to the box has a free sub-segment from the
//   cell's boundary to the box's; the converse is immediate);
// - every "hidden" answer survives the oracle's exact-confirmed random segments from the open cell to each box
//   face (tests/oracles);
// - coplanar pairs (the 2-triangle panels of region/coplanar_panels.hpp) are disjoint, share two corners, are
//   coplanar and form a convex quadrilateral or a triangle (checked with the oracle's rational orientations),
//   and the town's walls have many; the test through the hierarchy answers the same with the pairs merged as
//   without;
// - with a split budget the test only ever gives up: a budgeted answer "hidden" is the unbudgeted answer, a
//   budgeted "may be visible" without giving up too, and small budgets do give up.
#include "kernel/scene_generators.hpp"
#include "kernel/triangle_index.hpp"
#include "oracles/visibility_oracle.hpp"
#include "region/box_visibility.hpp"
#include "region/coplanar_panels.hpp"
#include "region/hierarchy_candidates.hpp"
#include "region/polygon_pair_visibility.hpp"
#include "region/triangle_bvh.hpp"
#include "tests/region/oracle_input.hpp"
#include "tests/region/pvs_test_scenes.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

using region_test::qv;

struct Case {
  Scene scene;
  RationalBox3 cell;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (unsigned seed = 40; seed < 44; ++seed) {
    const int s = static_cast<int>(seed);
    // Seed 40: a closed room (no hole), so that the boxes inside are hidden.
    out.push_back({pvs_test::pinhole_room(seed == 40 ? 0.0 : 0.05 + 0.1 * (seed % 3), 24, seed),
                   exact_box({{-4.0 - s % 3, 1.0 + s % 5, 2}, {-3.0 - s % 3, 3.0 + s % 5, 7}})});
  }
  for (unsigned seed = 50; seed < 53; ++seed) {
    Scene scene = generate_scene("town", 120, seed);
    const Box3 b = bounding_box(scene);
    const double x = b.lo.x + 0.3 + 0.5 * (seed % 3), y = b.lo.y + 0.2 + 0.4 * (seed % 2);
    out.push_back({std::move(scene), exact_box({{x, y, 1}, {x + 1.25, y + 1.25, 2}})});
  }
  return out;
}

// The exact triangles outside the node's subtree (all of them: the decomposition needs no gathering).
std::vector<std::array<RationalPoint3, 3>> outside(const Scene& scene, const TriangleBvh& bvh, const BvhNode& node) {
  std::vector<std::array<RationalPoint3, 3>> out;
  for (std::size_t t = 0; t < scene.triangles.size(); ++t) {
    const int pos = bvh.position[t];
    if (pos < node.begin || pos >= node.end) out.push_back(triangle_points(scene, static_cast<std::int64_t>(t)));
  }
  return out;
}

bool reached_by_some_face_pair(const RationalBox3& cell, const Box3& box,
                               const std::vector<std::array<RationalPoint3, 3>>& occluders) {
  const RationalBox3 b = exact_box(box);
  for (int ca = 0; ca < 3; ++ca)
    for (bool chigh : {false, true})
      for (int ba = 0; ba < 3; ++ba)
        for (bool bhigh : {false, true}) {
          const Polygon3 target = box_face(b, ba, bhigh);
          if (is_degenerate(target)) continue;
          if (visible_between_polygons(box_face(cell, ca, chigh), target, occluders).visible) return true;
        }
  return false;
}

// The oracle's refutation: random segments from the open cell to each face of the box (as two triangles),
// every triangle outside the subtree an occluder; a free one (exactly confirmed, robust) refutes "hidden".
bool oracle_finds_a_free_segment(const Scene& scene, const TriangleBvh& bvh, const BvhNode& node,
                                 const RationalBox3& cell, unsigned seed) {
  std::vector<oracle::Triangle> os;
  for (const auto& t : outside(scene, bvh, node)) os.push_back({qv(t[0]), qv(t[1]), qv(t[2])});
  const std::size_t first_face = os.size();
  const RationalBox3 b = exact_box(node.box);
  for (int axis = 0; axis < 3; ++axis)
    for (bool high : {false, true}) {
      const Polygon3 f = box_face(b, axis, high);
      os.push_back({qv(f[0]), qv(f[1]), qv(f[2])});
      os.push_back({qv(f[0]), qv(f[2]), qv(f[3])});
    }
  // The face triangles other than the target are occluders too: a segment from outside the box to a point
  // of one face meets the others only on a null set of lines, so they do not hide a robust free segment.
  const oracle::Source src = region_test::oracle_box(cell.lo, cell.hi);
  for (std::size_t f = first_face; f < os.size(); ++f)
    if (oracle::find_robust_free_segment(os, f, src, 40, seed + f)) return true;
  return false;
}

}  // namespace

TEST(BoxVisibility, QuadFacesAgreeWithAllFacePairsAndTheOracle) {
  int hidden = 0, reached = 0;
  unsigned seed = 1;
  for (const Case& c : cases()) {
    const TriangleIndex index(c.scene);
    const TriangleBvh bvh = build_triangle_bvh(c.scene);
    int tested = 0;
    for (std::size_t i = 1; i < bvh.nodes.size() && tested < 12; i += 3) {
      const BvhNode& node = bvh.nodes[i];
      if (boxes_meet(c.cell, node.box)) continue;
      ++tested;
      const std::vector<std::array<RationalPoint3, 3>> occluders = outside(c.scene, bvh, node);
      std::vector<std::int64_t> ids;
      for (std::size_t t = 0; t < c.scene.triangles.size(); ++t) {
        const int pos = bvh.position[t];
        if (pos < node.begin || pos >= node.end) ids.push_back(static_cast<std::int64_t>(t));
      }
      VisibilityStats stats;
      const BoxReach reach = box_may_be_visible(c.scene, ids, c.cell, node.box, {}, stats);
      const bool may = reach.may_be_visible;
      EXPECT_FALSE(reach.gave_up);
      EXPECT_EQ(may, reached_by_some_face_pair(c.cell, node.box, occluders)) << "node " << i;
      if (!may) {
        EXPECT_FALSE(oracle_finds_a_free_segment(c.scene, bvh, node, c.cell, ++seed)) << "node " << i;
        ++hidden;
      } else {
        ++reached;
      }
    }
  }
  EXPECT_GT(hidden, 3);
  EXPECT_GT(reached, 3);
}

TEST(BoxVisibility, SplitBudgetOnlyEverGivesUp) {
  int given_up = 0, hidden_within_budget = 0;
  for (const Case& c : cases()) {
    const TriangleBvh bvh = build_triangle_bvh(c.scene);
    for (std::size_t i = 1; i < bvh.nodes.size(); i += 2) {
      const BvhNode& node = bvh.nodes[i];
      if (boxes_meet(c.cell, node.box)) continue;
      std::vector<std::int64_t> ids;
      for (std::size_t t = 0; t < c.scene.triangles.size(); ++t) {
        const int pos = bvh.position[t];
        if (pos < node.begin || pos >= node.end) ids.push_back(static_cast<std::int64_t>(t));
      }
      VisibilityStats full_stats;
      const bool full = box_may_be_visible(c.scene, ids, c.cell, node.box, {}, full_stats).may_be_visible;
      for (const std::int64_t budget : {1, 7, 40, 300}) {
        VisibilityOptions o;
        o.split_budget = budget;
        VisibilityStats stats;
        const BoxReach reach = box_may_be_visible(c.scene, ids, c.cell, node.box, o, stats);
        const bool may = reach.may_be_visible;
        if (reach.gave_up) {
          EXPECT_TRUE(may) << "a test that gave up must not claim hidden, node " << i;
          ++given_up;
          continue;
        }
        EXPECT_EQ(may, full) << "node " << i << " budget " << budget;
        if (!may) ++hidden_within_budget;
      }
    }
  }
  EXPECT_GT(given_up, 3);
  EXPECT_GT(hidden_within_budget, 3);
}

namespace {

// Rational orientation of (b - a) x (c - a) . n for the oracle's exact vectors.
int orient_in_plane(const oracle::QVec& a, const oracle::QVec& b, const oracle::QVec& c, const oracle::QVec& n) {
  const oracle::QVec u = (b - a), v = (c - a);
  const mpq_class s = oracle::dot(oracle::cross(u, v), n);
  return oracle::sign(s);
}

}  // namespace

TEST(BoxVisibility, CoplanarPairsAreConvexAndMergingKeepsTheAnswers) {
  std::int64_t pairs = 0, boxes = 0, hidden = 0;
  for (unsigned seed = 60; seed < 64; ++seed) {
    // Towns, and a closed room (walls of two triangles each: partners; the boxes inside hidden).
    const Scene scene = seed == 63 ? pvs_test::pinhole_room(0.0, 24, seed) : generate_scene("town", 600, seed);
    const CoplanarPanels panels = coplanar_panels(scene);
    ASSERT_EQ(panels.pair_of.size(), scene.triangles.size());
    const std::vector<oracle::Triangle> os = region_test::oracle_scene(scene);
    for (std::size_t k = 0; k < panels.pairs.size(); ++k) {
      const CoplanarPanel& pr = panels.pairs[k];
      ASSERT_EQ(pr.triangles.size(), 2u);
      const auto t = static_cast<std::size_t>(pr.triangles[0]), o = static_cast<std::size_t>(pr.triangles[1]);
      ASSERT_LT(t, o);
      ASSERT_EQ(panels.pair_of[t], static_cast<std::int32_t>(k));
      ASSERT_EQ(panels.pair_of[o], static_cast<std::int32_t>(k));
      ++pairs;
      const oracle::Triangle &A = os[t], &B = os[o];
      // Shared corners and the other two.
      std::vector<oracle::QVec> shared, other;
      for (const auto& p : A) (std::find(B.begin(), B.end(), p) != B.end() ? shared : other).push_back(p);
      for (const auto& p : B)
        if (std::find(A.begin(), A.end(), p) == A.end()) other.push_back(p);
      ASSERT_EQ(shared.size(), 2u) << t;
      ASSERT_EQ(other.size(), 2u) << t;
      const oracle::QVec n = oracle::cross((A[1] - A[0]), (A[2] - A[0]));
      EXPECT_EQ(oracle::sign(oracle::dot(n, (other[1] - A[0]))), 0) << "not coplanar " << t;
      // Convex union: the others strictly on opposite sides of the shared edge, the shared corners on opposite
      // closed sides of the others' diagonal, at most one on it (then the union is a triangle).
      EXPECT_EQ(orient_in_plane(shared[0], shared[1], other[0], n) * orient_in_plane(shared[0], shared[1], other[1], n), -1);
      const int s0 = orient_in_plane(other[0], other[1], shared[0], n), s1 = orient_in_plane(other[0], other[1], shared[1], n);
      EXPECT_LE(s0 * s1, 0) << t;
      EXPECT_TRUE(s0 != 0 || s1 != 0) << t;
    }
    const TriangleIndex index(scene);
    const TriangleBvh bvh = build_triangle_bvh(scene);
    const Box3 bb = bounding_box(scene);
    const RationalBox3 cell =
        seed == 63 ? exact_box({{-4, 2, 2}, {-3, 4, 7}})
                   : exact_box({{bb.lo.x + 0.3, bb.lo.y + 0.2, 1}, {bb.lo.x + 1.55, bb.lo.y + 1.45, 2}});
    for (std::size_t i = 1, tested = 0; i < bvh.nodes.size() && tested < 30; ++i) {
      const BvhNode& node = bvh.nodes[i];
      if (boxes_meet(cell, node.box) || node.end - node.begin < 4) continue;
      ++boxes;
      ++tested;
      auto inside = [&](std::int64_t t) {
        const int pos = bvh.position[static_cast<std::size_t>(t)];
        return pos >= node.begin && pos < node.end;
      };
      const Box3 query = enclosing_box({cell.lo, cell.hi, to_rational(node.box.lo), to_rational(node.box.hi)});
      VisibilityStats sa, sb;
      const bool a =
          box_may_be_visible(scene, HierarchyCandidates{index, &scene, &bvh, inside}, query, cell, node.box, {}, sa)
              .may_be_visible;
      const bool b = box_may_be_visible(scene, HierarchyCandidates{index, &scene, &bvh, inside, &panels, false}, query, cell,
                                        node.box, {}, sb)
                         .may_be_visible;
      EXPECT_EQ(a, b) << "seed " << seed << " node " << i;
      hidden += a ? 0 : 1;
    }
  }
  EXPECT_GT(pairs, 100);
  EXPECT_GT(hidden, 2);
  EXPECT_GT(boxes - hidden, 2);
}
