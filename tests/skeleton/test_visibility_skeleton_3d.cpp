// The 3D visibility skeleton against the independent brute-force oracle (tests/oracles/skeleton_oracle):
// node sets of kinds VV, VEE, EEEE equal to the oracle's valid lines, every node re-checked exactly, graph
// consistency, and Durand's table equal to the pair slices of the full skeleton.
#include "skeleton/skeleton_validation.hpp"
#include "skeleton/visibility_skeleton_3d.hpp"
#include "tests/skeleton/skeleton3d_test_scenes.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <sstream>

namespace exactvis {
namespace {

using skeleton_oracle::QS;

QS to_qs(const RootNumber& x, mpq_class* root) {
  if (!x.is_extended()) return {mpq_class(x.a0().mpq()), 0};
  *root = mpq_class(x.root().mpq());
  return {mpq_class(x.a0().mpq()), mpq_class(x.a1().mpq())};
}

skeleton_oracle::Line oracle_line(const SkeletonNode& n) {
  skeleton_oracle::Line l;
  mpq_class r = 0;
  for (int k = 0; k < 3; ++k) {
    l.p[k] = to_qs(n.from[k], &r);
    const QS b = to_qs(n.to[k], &r);
    l.d[k] = {b.a - l.p[k].a, b.b - l.p[k].b};
  }
  l.r = r;
  return l;
}

skeleton_oracle::Generators oracle_generators(const ExtremalLineKey& k) {
  skeleton_oracle::Generators g;
  for (int i = 0; i < k.vertex_count(); ++i) g.vertices.push_back(k.vertices[i]);
  const int edges = k.kind == ExtremalLineKind::EEP ? 2 : k.edge_count();
  for (int i = 0; i < edges; ++i) g.edges.push_back(k.edges[i]);
  return g;
}

std::string oracle_key(const ExtremalLineKey& k) {
  std::ostringstream os;
  os << kind_name(k.kind);
  for (int i = 0; i < k.vertex_count(); ++i) os << " " << k.vertices[i];
  for (int i = 0; i < k.edge_count(); ++i) os << " " << k.edges[i][0] << " " << k.edges[i][1];
  return os.str();
}

// Node multiset of kinds VV, VEE, EEEE in the oracle's key form.
std::map<std::string, int> main_kind_nodes(const Skeleton3D& sk, bool with_eeee) {
  std::map<std::string, int> out;
  for (const auto& n : sk.nodes) {
    const auto k = n.key.kind;
    if (!n.valid) continue;
    if (k == ExtremalLineKind::VV || k == ExtremalLineKind::VEE || (with_eeee && k == ExtremalLineKind::EEEE))
      ++out[oracle_key(n.key)];
  }
  return out;
}

std::string diff(const std::map<std::string, int>& got, const std::map<std::string, int>& want) {
  std::ostringstream os;
  for (const auto& [k, c] : want)
    if (!got.count(k) || got.at(k) != c) os << "  missing " << k << " (oracle " << c << ")\n";
  for (const auto& [k, c] : got)
    if (!want.count(k) || want.at(k) != c) os << "  extra " << k << " (skeleton " << c << ")\n";
  return os.str();
}

// Every node re-checked by the oracle: VV/VEE/EEEE: the oracle's validity equals the node's flag; valid
// face kinds: the line lies in the face's plane, passes its vertices, meets its edges' relative interiors,
// and its spanned segment is free; every node's line passes through its vertex generators.
void expect_nodes_recheck(const Scene& s, const Skeleton3D& sk) {
  const auto m = skeleton_test::to_oracle(s);
  for (const auto& n : sk.nodes) {
    const auto l = oracle_line(n);
    auto g = oracle_generators(n.key);
    std::string why;
    switch (n.key.kind) {
      case ExtremalLineKind::VV:
      case ExtremalLineKind::VEE:
      case ExtremalLineKind::EEEE:
        EXPECT_EQ(skeleton_oracle::valid_line(m, g, l, &why), n.valid) << to_string(n.key) << ": " << why;
        break;
      case ExtremalLineKind::FVE:
      case ExtremalLineKind::FEE: {
        for (int v : g.vertices) EXPECT_TRUE(skeleton_oracle::passes_through(l, m.v[v])) << to_string(n.key);
        if (!n.valid) break;
        g.faces.push_back(static_cast<int>(s.index_of_id(n.key.faces[0])));
        EXPECT_TRUE(skeleton_oracle::lies_in_plane(m, l, static_cast<int>(s.index_of_id(n.key.faces[0]))))
            << to_string(n.key);
        for (const auto& e : g.edges) EXPECT_TRUE(skeleton_oracle::meets_edge_interior(m, l, e)) << to_string(n.key);
        EXPECT_TRUE(skeleton_oracle::segment_free(m, g, l, &why)) << to_string(n.key) << ": " << why;
        break;
      }
      default:
        for (int v : g.vertices) EXPECT_TRUE(skeleton_oracle::passes_through(l, m.v[v])) << to_string(n.key);
        break;
    }
  }
}

// Graph consistency: arcs have two valid end nodes and are listed at both; node lists hold only arcs ending
// there; Durand's table holds every node and arc once, under the objects of its ends.
void expect_graph_consistent(const Scene& s, const Skeleton3D& sk) {
  std::map<int, std::multiset<int>> expected;
  for (std::size_t i = 0; i < sk.arcs.size(); ++i) {
    const auto& a = sk.arcs[i];
    ASSERT_GE(a.nodes[0], 0);
    ASSERT_GE(a.nodes[1], 0);
    ASSERT_LT(a.nodes[0], static_cast<int>(sk.nodes.size()));
    ASSERT_LT(a.nodes[1], static_cast<int>(sk.nodes.size()));
    EXPECT_TRUE(a.t0 < a.t1);
    EXPECT_TRUE(a.t0 < RootNumber(a.sample_t) && RootNumber(a.sample_t) < a.t1);
    for (int n : a.nodes) expected[n].insert(static_cast<int>(i));
  }
  for (std::size_t n = 0; n < sk.nodes.size(); ++n) {
    const std::multiset<int> got(sk.nodes[n].arcs.begin(), sk.nodes[n].arcs.end());
    EXPECT_EQ(got, expected[static_cast<int>(n)]) << to_string(sk.nodes[n].key);
    EXPECT_FALSE(sk.nodes[n].arcs.empty()) << to_string(sk.nodes[n].key);
  }
  std::size_t nodes = 0, arcs = 0;
  for (const auto& [objs, slice] : sk.by_objects) {
    for (int n : slice.nodes) {
      std::array<int, 2> k{object_of_triangle(s, sk.nodes[n].ends[0]), object_of_triangle(s, sk.nodes[n].ends[1])};
      if (k[1] < k[0]) std::swap(k[0], k[1]);
      EXPECT_EQ(k, objs);
    }
    for (int a : slice.arcs) {
      std::array<int, 2> k{object_of_triangle(s, sk.arcs[a].ends[0]), object_of_triangle(s, sk.arcs[a].ends[1])};
      if (k[1] < k[0]) std::swap(k[0], k[1]);
      EXPECT_EQ(k, objs);
    }
    nodes += slice.nodes.size(), arcs += slice.arcs.size();
    const auto again = skeleton_pair(sk, objs[1], objs[0]);
    EXPECT_EQ(again.nodes, slice.nodes);
    EXPECT_EQ(again.arcs, slice.arcs);
  }
  EXPECT_EQ(nodes, sk.nodes.size());
  EXPECT_EQ(arcs, sk.arcs.size());
}

void check_scene(const Scene& s, bool with_eeee, int min_nodes, bool generic) {
  SkeletonOptions opt;
  opt.parallel = false;
  const Skeleton3D sk = build_skeleton_3d(s, opt);
  EXPECT_GE(static_cast<int>(sk.nodes.size()), min_nodes);
  const auto oracle = skeleton_oracle::valid_nodes(skeleton_test::to_oracle(s), true, true, with_eeee);
  const auto got = main_kind_nodes(sk, with_eeee);
  EXPECT_EQ(got, oracle.nodes) << diff(got, oracle.nodes);
  expect_nodes_recheck(s, sk);
  expect_graph_consistent(s, sk);
  if (generic) {
    const SkeletonCheck check = validate_skeleton(s, sk);
    EXPECT_GT(check.nodes_checked, 0u);
    std::string all;
    for (const auto& p : check.problems) all += "  " + p + "\n";
    EXPECT_TRUE(check.problems.empty()) << check.problems.size() << " problems:\n" << all;
  }
}

TEST(VisibilitySkeleton3D, RandomSoupsMatchBruteForce) {
  for (unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    check_scene(skeleton_test::random_soup(seed, 5, 24), true, 10, true);
  }
}

TEST(VisibilitySkeleton3D, TetrahedraWithSharedEdgesMatchBruteForce) {
  for (unsigned seed : {4u, 5u}) {
    SCOPED_TRACE(seed);
    check_scene(skeleton_test::random_tetrahedra(seed, 2, 30), true, 4, true);
  }
}

TEST(VisibilitySkeleton3D, CubeHasNoFreeExtremalLines) {
  Scene s;
  skeleton_test::add_box(s, {0, 0, 0}, {1, 1, 1}, "cube");
  const Skeleton3D sk = build_skeleton_3d(s);
  EXPECT_TRUE(sk.nodes.empty());
  EXPECT_TRUE(sk.arcs.empty());
  EXPECT_TRUE(skeleton_oracle::valid_nodes(skeleton_test::to_oracle(s), true, true, true).nodes.empty());
}

TEST(VisibilitySkeleton3D, TwoBoxesMatchBruteForce) {
  Scene s;
  skeleton_test::add_box(s, {0, 0, 0}, {1, 1, 1}, "A");
  skeleton_test::add_box(s, {2.125, 0.25, 0.375}, {3.5, 1.5, 1.75}, "B");
  check_scene(s, false, 20, true);
}

TEST(VisibilitySkeleton3D, CoplanarFacesMatchBruteForce) {
  // Boxes sharing the planes z = 0, z = 1 and y = 0: coplanar faces, lines in common face planes.
  Scene s;
  skeleton_test::add_box(s, {0, 0, 0}, {1, 1, 1}, "A");
  skeleton_test::add_box(s, {2, 0, 0}, {3, 2, 1}, "B");
  check_scene(s, false, 1, false);
}

TEST(VisibilitySkeleton3D, PairSliceIsTheTableEntry) {
  const Scene s = skeleton_test::random_soup(7, 6, 24);
  const Skeleton3D sk = build_skeleton_3d(s);
  ASSERT_FALSE(sk.by_objects.empty());
  for (const auto& [objs, slice] : sk.by_objects) {
    const auto got = skeleton_pair(sk, objs[0], objs[1]);
    std::vector<int> nodes, arcs;
    for (std::size_t i = 0; i < sk.nodes.size(); ++i) {
      std::set<int> o{object_of_triangle(s, sk.nodes[i].ends[0]), object_of_triangle(s, sk.nodes[i].ends[1])};
      if (o == std::set<int>{objs[0], objs[1]}) nodes.push_back(static_cast<int>(i));
    }
    for (std::size_t i = 0; i < sk.arcs.size(); ++i) {
      std::set<int> o{object_of_triangle(s, sk.arcs[i].ends[0]), object_of_triangle(s, sk.arcs[i].ends[1])};
      if (o == std::set<int>{objs[0], objs[1]}) arcs.push_back(static_cast<int>(i));
    }
    EXPECT_EQ(got.nodes, nodes);
    EXPECT_EQ(got.arcs, arcs);
  }
}

}  // namespace
}  // namespace exactvis
