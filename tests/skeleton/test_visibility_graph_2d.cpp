// Bitangents and maximal free segments against the O(n^3) exact brute force of tests/oracles.
#include "tests/planar/scene2d_test_util.hpp"
#include "skeleton/visibility_graph_2d.hpp"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

using namespace exactvis;
using namespace exactvis::test2d;

namespace {

// A bitangent in the oracle's normal form: endpoints in lexicographic order, kind for that direction.
oracle2d::Bitangent normal_form(const Scene2D& s, const Bitangent2D& b) {
  oracle2d::Bitangent o;
  o.a = to_pt(s.points[b.a]);
  o.b = to_pt(s.points[b.b]);
  o.object_a = b.object_a;
  o.object_b = b.object_b;
  o.kind = b.kind();
  auto end_pt = [&](const SegmentEnd2D& e, bool* inf) {
    *inf = e.kind == SegmentEnd2D::Infinity;
    return *inf ? oracle2d::Pt{} : to_pt(e.point);
  };
  o.end_a = end_pt(b.end_a, &o.end_a_infinite);
  o.end_b = end_pt(b.end_b, &o.end_b_infinite);
  if (o.b < o.a) {  // reverse: swap ends, and sides flip
    auto flip = [](char c) { return c == 'L' ? 'R' : 'L'; };
    o.kind = {flip(o.kind[1]), flip(o.kind[0])};
    std::swap(o.a, o.b);
    std::swap(o.object_a, o.object_b);
    std::swap(o.end_a, o.end_b);
    std::swap(o.end_a_infinite, o.end_b_infinite);
  }
  return o;
}

std::string describe(const oracle2d::Bitangent& b) {
  return "(" + b.a.x.get_str() + "," + b.a.y.get_str() + ")-(" + b.b.x.get_str() + "," + b.b.y.get_str() + ") " +
         b.kind + " objects " + std::to_string(b.object_a) + "," + std::to_string(b.object_b) + " ends " +
         (b.end_a_infinite ? "inf" : "(" + b.end_a.x.get_str() + "," + b.end_a.y.get_str() + ")") + " " +
         (b.end_b_infinite ? "inf" : "(" + b.end_b.x.get_str() + "," + b.end_b.y.get_str() + ")");
}

std::set<std::string> as_set(const std::vector<oracle2d::Bitangent>& v) {
  std::set<std::string> s;
  for (const auto& b : v) s.insert(describe(b));
  return s;
}

void expect_same_bitangents(const std::vector<oracle2d::Polygon>& polys, const Scene2D& s) {
  const auto g = visibility_graph(s);
  std::vector<oracle2d::Bitangent> mine;
  for (const auto& b : g.bitangents) mine.push_back(normal_form(s, b));
  const auto expected = as_set(oracle2d::brute_force_bitangents(polys));
  const auto got = as_set(mine);
  ASSERT_EQ(got.size(), mine.size()) << "duplicate bitangents";
  for (const auto& e : expected) EXPECT_TRUE(got.count(e)) << "missing bitangent " << e;
  for (const auto& e : got) EXPECT_TRUE(expected.count(e)) << "extra bitangent " << e;
}

oracle2d::Ring box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

}  // namespace

TEST(Bitangents2D, TwoSquaresHaveFourBitangentsOfAllKinds) {
  const std::vector<oracle2d::Polygon> polys{{{box(0, 0, 1, 1)}}, {{box(3, 0.5, 4, 2)}}};
  const Scene2D s = make_scene2d(to_input(polys));
  const auto g = visibility_graph(s);
  ASSERT_EQ(g.bitangents.size(), 4u);
  std::multiset<std::string> kinds;
  for (const auto& b : g.bitangents) kinds.insert(b.kind());
  EXPECT_EQ(kinds.count("LL") + kinds.count("RR"), 2u);  // outer common tangents
  EXPECT_EQ(kinds.count("LR") + kinds.count("RL"), 2u);  // separating tangents
  expect_same_bitangents(polys, s);
}

TEST(Bitangents2D, CollinearSquaresSplitTheLineAtEveryTangentVertex) {
  // y = 0 and y = 1 carry edges of three objects: bitangents join neighbours only, never across a vertex.
  const std::vector<oracle2d::Polygon> polys{{{box(0, 0, 1, 1)}}, {{box(2, 0, 3, 1)}}, {{box(4, 0, 5, 1)}}};
  const Scene2D s = make_scene2d(to_input(polys));
  expect_same_bitangents(polys, s);
  for (const auto& b : visibility_graph(s).bitangents)
    EXPECT_LE(std::abs(b.object_a - b.object_b), 1) << "bitangent across a tangent vertex";
}

TEST(Bitangents2D, ThreeBitangentsThroughOnePoint) {
  // Bitangent lines y = x, y = -x and y = 2x all pass through the origin.
  const std::vector<oracle2d::Polygon> polys{{{box(2, 1, 3, 2)}},      {{box(-3, -2, -2, -1)}},
                                             {{box(-2, 2, -1, 3)}},    {{box(1, -3, 2, -2)}},
                                             {{box(0.5, 2, 1, 3)}},   {{box(-1, -3, -0.5, -2)}}};
  const Scene2D s = make_scene2d(to_input(polys));
  expect_same_bitangents(polys, s);
  int through_origin = 0;
  for (const auto& b : visibility_graph(s).bitangents)
    if (orientation2(s.points[b.a], s.points[b.b], Point2(0.0, 0.0)) == Sign::Zero) ++through_origin;
  EXPECT_GE(through_origin, 3);
}

TEST(Bitangents2D, NonConvexPolygonHasBitangentsAcrossItsConcavity) {
  // A U shape: the segment closing the U's mouth is a bitangent of the polygon with itself.
  const std::vector<oracle2d::Polygon> polys{{{{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}}}};
  const Scene2D s = make_scene2d(to_input(polys));
  const auto g = visibility_graph(s);
  bool mouth = false;
  for (const auto& b : g.bitangents)
    if (b.object_a == 0 && b.object_b == 0 && s.points[b.a].y == 3 && s.points[b.b].y == 3) mouth = true;
  EXPECT_TRUE(mouth);
  expect_same_bitangents(polys, s);
}

TEST(Bitangents2D, RandomGridScenesMatchBruteForce) {
  int tested = 0;
  std::size_t total = 0;
  for (std::uint64_t seed = 1; tested < 40 && seed < 400; ++seed) {
    const auto polys = oracle2d::random_grid_scene(seed, seed % 3 == 0 ? 3 : 2);
    const auto s = try_scene(polys);
    if (!s || s->num_vertices() > 70) continue;
    ++tested;
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_bitangents(polys, *s);
    total += visibility_graph(*s).bitangents.size();
  }
  EXPECT_GE(tested, 30);
  EXPECT_GE(total, 400u);  // the comparison is not vacuous
}

TEST(VisibilityGraph2D, StrictPairsAreSymmetricAndContainBitangents) {
  std::optional<Scene2D> s;
  for (std::uint64_t seed = 7; !s; ++seed) s = try_scene(oracle2d::random_grid_scene(seed, 3));
  const auto g = visibility_graph(*s);
  std::set<std::pair<int, int>> pairs(g.strict_pairs.begin(), g.strict_pairs.end());
  EXPECT_EQ(pairs.size(), g.strict_pairs.size());
  for (const auto& b : g.bitangents) EXPECT_TRUE(pairs.count({b.a, b.b}));
  EXPECT_EQ(static_cast<int>(g.ring_edges.size()), s->num_vertices());
}
