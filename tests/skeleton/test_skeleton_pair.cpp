// The lazy build of one pair equals that pair's slice of the full skeleton; blockers between two objects.
#include "skeleton/skeleton_pair.hpp"

#include "kernel/predicate_counters.hpp"
#include "kernel/scene_generators.hpp"
#include "tests/skeleton/skeleton3d_test_scenes.hpp"

#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>

namespace exactvis {
namespace {

std::string ends_text(const std::array<std::int64_t, 2>& e) { return std::to_string(e[0]) + "," + std::to_string(e[1]); }

// Nodes and arcs of a selection as comparable text (keys, exact parameters, end objects, end node keys).
std::multiset<std::string> describe(const Skeleton3D& sk, const std::vector<int>& nodes, const std::vector<int>& arcs) {
  std::multiset<std::string> out;
  for (int n : nodes) {
    const auto& node = sk.nodes[n];
    std::ostringstream os;
    os << "node " << to_string(node.key) << " ends " << ends_text(node.ends) << " valid " << node.valid << " from "
       << CGAL::to_double(node.from.x) << " to " << CGAL::to_double(node.to.x);
    out.insert(os.str());
  }
  for (int a : arcs) {
    const auto& arc = sk.arcs[a];
    std::ostringstream os;
    os << "arc " << arc_kind_name(arc.kind) << " v " << arc.vertex;
    for (const auto& e : arc.edges) os << " [" << e[0] << "," << e[1] << "]";
    os << " t " << CGAL::to_double(arc.t0) << " " << CGAL::to_double(arc.t1) << " ends " << ends_text(arc.ends)
       << " nodes " << to_string(sk.nodes[arc.nodes[0]].key) << " " << to_string(sk.nodes[arc.nodes[1]].key);
    out.insert(os.str());
    EXPECT_TRUE(arc.t0 < arc.t1);
  }
  return out;
}

TEST(SkeletonPair, LazyBuildEqualsTheSliceOfTheFullSkeleton) {
  Scene s = skeleton_test::random_soup(11, 5, 30);
  const Skeleton3D full = build_skeleton_3d(s);
  std::size_t total = 0, compared = 0;
  // The first three pairs with a non-empty slice, and one with an empty slice (each lazy build is a full
  // build of a sub-scene: kept few for the test time).
  bool empty_done = false;
  for (int a = 0; a < static_cast<int>(s.objects.size()) && compared < 3; ++a)
    for (int b = a + 1; b < static_cast<int>(s.objects.size()) && compared < 3; ++b) {
      const SkeletonPairSide A{a, -1}, B{b, -1};
      const SkeletonPairSlice slice = pair_slice(s, full, A, B);
      const bool empty = slice.arcs.empty() && slice.nodes.empty();
      if (empty && empty_done) continue;
      empty_done = empty_done || empty;
      compared += empty ? 0 : 1;
      std::set<int> nodes(slice.nodes.begin(), slice.nodes.end());
      for (int ai : slice.arcs) nodes.insert(full.arcs[ai].nodes.begin(), full.arcs[ai].nodes.end());
      const auto want = describe(full, {nodes.begin(), nodes.end()}, slice.arcs);
      const Skeleton3D lazy = build_pair_skeleton(s, A, B);
      std::vector<int> all_nodes, all_arcs;
      for (std::size_t i = 0; i < lazy.nodes.size(); ++i) all_nodes.push_back(static_cast<int>(i));
      for (std::size_t i = 0; i < lazy.arcs.size(); ++i) all_arcs.push_back(static_cast<int>(i));
      EXPECT_EQ(describe(lazy, all_nodes, all_arcs), want) << "pair " << a << "," << b;
      for (std::size_t i = 0; i < lazy.arcs.size(); ++i)
        for (int n : lazy.arcs[i].nodes) {
          const auto& l = lazy.nodes[n].arcs;
          EXPECT_NE(std::find(l.begin(), l.end(), static_cast<int>(i)), l.end());
        }
      total += slice.arcs.size() + slice.nodes.size();
    }
  EXPECT_EQ(compared, 3u);  // the comparison saw non-empty slices
  EXPECT_GT(total, 0u);
}

// A town (closed buildings, shared edges, coplanar walls and ground): most EV pencils of the pair's sub-scene
// cannot reach both buildings, so the pencil-range filter and the node-line filter act; the lazy build must
// still equal the full skeleton's slice (and the filter must have proved something, or the test is vacuous).
TEST(SkeletonPair, LazyTownPairEqualsTheSliceOfTheFullSkeleton) {
  const Scene s = generate_scene("town", 200, 1);  // two buildings, ground, curb
  const Skeleton3D full = build_skeleton_3d(s);
  reset_predicate_counters();
  std::size_t compared = 0;
  const int objects = static_cast<int>(s.objects.size());
  for (int p = 0; p < objects * objects; ++p) {
    const int a = p / objects, b = p % objects;
    // The ground's box holds the whole town (its lazy build is the full one): pairs of the others only.
    if (b <= a || s.objects[a].name == "ground" || s.objects[b].name == "ground") continue;
    const SkeletonPairSide A{a, -1}, B{b, -1};
    const SkeletonPairSlice slice = pair_slice(s, full, A, B);
    std::set<int> nodes(slice.nodes.begin(), slice.nodes.end());
    for (int ai : slice.arcs) nodes.insert(full.arcs[ai].nodes.begin(), full.arcs[ai].nodes.end());
    const Skeleton3D lazy = build_pair_skeleton(s, A, B);
    std::vector<int> all_nodes, all_arcs;
    for (std::size_t i = 0; i < lazy.nodes.size(); ++i) all_nodes.push_back(static_cast<int>(i));
    for (std::size_t i = 0; i < lazy.arcs.size(); ++i) all_arcs.push_back(static_cast<int>(i));
    EXPECT_EQ(describe(lazy, all_nodes, all_arcs), describe(full, {nodes.begin(), nodes.end()}, slice.arcs))
        << "pair " << a << "," << b;
    compared += slice.arcs.size();
  }
  EXPECT_GT(compared, 0u);
  std::uint64_t proved = 0;
  for (const auto& c : predicate_counters())
    if (c.name == "ev_pencil_misses") proved = c.interval;
  EXPECT_GT(proved, 0u);
}

TEST(SkeletonPair, TrianglePairSidesMatchBySide) {
  Scene s = skeleton_test::random_soup(12, 5, 30);
  const Skeleton3D full = build_skeleton_3d(s);
  const SkeletonPairSide A{-1, 0}, B{-1, 3};
  const SkeletonPairSlice slice = pair_slice(s, full, A, B);
  for (int n : slice.nodes) {
    const auto& e = full.nodes[n].ends;
    EXPECT_TRUE((e[0] == 0 && e[1] == 3) || (e[0] == 3 && e[1] == 0));
  }
  const Skeleton3D lazy = build_pair_skeleton(s, A, B);
  std::size_t matching = 0;
  for (const auto& n : lazy.nodes)
    if ((n.ends[0] == 0 && n.ends[1] == 3) || (n.ends[0] == 3 && n.ends[1] == 0)) ++matching;
  EXPECT_EQ(matching, slice.nodes.size());
}

TEST(SkeletonPair, BlockersAreTheOccludersBetweenThePair) {
  // Floor A (z = 0) and ceiling C (z = 10), two small triangles B1, B2 between them, and a box D far off to
  // the side (outside the hull of A and C).
  Scene s;
  auto add_triangle = [&](Point3 p, Point3 q, Point3 r, const std::string& name) {
    const int b = static_cast<int>(s.vertices.size());
    s.vertices.insert(s.vertices.end(), {p, q, r});
    s.objects.push_back({name});
    s.triangles.push_back({s.faces_read++, {b, b + 1, b + 2}, static_cast<int>(s.objects.size()) - 1});
  };
  add_triangle({-20, -20, 0}, {20, -19, 0.5}, {0, 21, -0.25}, "A");
  add_triangle({-20, -20, 10}, {0, 21, 10.5}, {20, -19, 9.75}, "C");
  add_triangle({-2, -1, 4}, {2, -1.5, 4.5}, {0, 2, 3.75}, "B1");
  add_triangle({1, 0, 6}, {4, 0.5, 6.25}, {2.5, 3, 5.5}, "B2");
  skeleton_test::add_box(s, {100, 100, 0}, {101, 101, 1}, "D");
  const SkeletonPairSide A{0, -1}, C{1, -1};
  const Skeleton3D lazy = build_pair_skeleton(s, A, C);
  ASSERT_FALSE(lazy.arcs.empty());
  const SkeletonPairSlice all = pair_slice(s, lazy, A, C);
  EXPECT_EQ(pair_blockers(s, lazy, all, A, C), (std::vector<int>{2, 3}));
  // The same from the full skeleton.
  const Skeleton3D full = build_skeleton_3d(s);
  EXPECT_EQ(pair_blockers(s, full, pair_slice(s, full, A, C), A, C), (std::vector<int>{2, 3}));
}

}  // namespace
}  // namespace exactvis
