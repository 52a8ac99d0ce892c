// EEE enumeration (events/eee_enumeration.hpp): the candidate restriction never loses an event. Compared with
// a plain loop over all triples of edges calling eee_event (same events, same intervals), with and without a
// light; the edge-rule prefilter is checked against exact sampling with GMP rationals (no shared code).
#include "events/eee_enumeration.hpp"
#include "events/eee_prefilter.hpp"
#include "kernel/triangle_index.hpp"
#include "kernel/predicates.hpp"
#include "kernel/scene_generators.hpp"
#include "tests/events/event_test_scenes.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <string>

namespace exactvis {
namespace {

using namespace event_test;


std::string describe(const EeeEvent& ev) {
  std::string s;
  for (const auto& e : ev.edges) s += "[" + std::to_string(e[0]) + "," + std::to_string(e[1]) + "]";
  s += ":";
  for (const auto& iv : ev.intervals) s += " [" + root_number_to_string(iv.t0) + "," + root_number_to_string(iv.t1) + "]";
  return s;
}

// All triples (with a light edge when `light` is non-empty) through eee_event, no restriction at all.
std::vector<std::string> all_triples(const Scene& s, const std::vector<int>& light) {
  const SceneAdjacency adj = build_scene_adjacency(s);
  const TriangleIndex index(s);
  std::set<int> light_edges;
  for (int ti : light)
    for (int k = 0; k < 3; ++k)
      light_edges.insert(adj.edge_index(s.triangles[ti].v[k], s.triangles[ti].v[(k + 1) % 3]));
  std::vector<std::string> out;
  const int m = static_cast<int>(adj.edges.size());
  for (int a = 0; a < m; ++a)
    for (int b = a + 1; b < m; ++b)
      for (int c = b + 1; c < m; ++c) {
        if (!light.empty() && !light_edges.count(a) && !light_edges.count(b) && !light_edges.count(c)) continue;
        if (auto ev = eee_event(s, adj, index, a, b, c)) out.push_back(describe(*ev));
      }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> enumerated(const Scene& s, const std::vector<int>& light, bool parallel = true) {
  EeeOptions o;
  o.light_triangles = light;
  o.parallel = parallel;
  std::vector<std::string> out;
  for (const auto& ev : enumerate_eee_events(s, o).events) out.push_back(describe(ev));
  std::sort(out.begin(), out.end());
  return out;
}

TEST(EeeEnumeration, SameEventsAsAllTriplesOnRandomSoups) {
  std::size_t total = 0;  // ~800 triples per scene
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const Scene s = random_soup(seed, 6, 6);
    const auto want = all_triples(s, {});
    EXPECT_EQ(enumerated(s, {}), want) << "seed " << seed;
    total += want.size();
  }
  EXPECT_GT(total, 20u);  // the comparison saw real events
}

TEST(EeeEnumeration, SameEventsAsAllTriplesWithSharedVertices) {
  std::size_t total = 0;
  for (unsigned seed = 1; seed <= 25; ++seed) {
    const Scene s = shared_vertex_scene(300 + seed, 9, 6, 8, 300);
    const auto want = all_triples(s, {});
    EXPECT_EQ(enumerated(s, {}, seed % 2 == 0), want) << "seed " << seed;
    total += want.size();
  }
  EXPECT_GT(total, 5u);
}

// Light restriction: the light edge as an outer edge and as the middle edge (the shadow-box query).
TEST(EeeEnumeration, LightRestrictedSameAsAllTriplesWithALightEdge) {
  std::size_t total = 0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const Scene s = random_soup(700 + seed, 7, 8);
    const std::vector<int> light{static_cast<int>(seed % 7)};
    const auto want = all_triples(s, light);
    EXPECT_EQ(enumerated(s, light), want) << "seed " << seed;
    total += want.size();
  }
  EXPECT_GT(total, 10u);
}

TEST(EeeEnumeration, SameEventsAsAllTriplesOnGeneratedScenes) {
  std::size_t total = 0;
  // Closed meshes (trunks, crowns, buildings): silhouette-only events, many coplanar edge pairs.
  for (const char* kind : {"town", "forest", "room"}) {
    const Scene s = generate_scene(kind, 16, 3);
    const auto want = all_triples(s, {});
    EXPECT_EQ(enumerated(s, {}), want) << kind;
    total += want.size();
  }
  EXPECT_GT(total, 0u);
}

// Independent check of the prefilter: whenever exact sampling finds a point X of the open segment (c, d)
// satisfying the edge rule of e, edge_rule_possible must say true.
TEST(EeePrefilter, EdgeRulePossibleNeverRejectsASampledTangentPoint) {
  int positives = 0, checked = 0;
  for (unsigned seed = 1; seed <= 60; ++seed) {
    const Scene s = shared_vertex_scene(900 + seed, 9, 6, 8, 300);
    const SceneAdjacency adj = build_scene_adjacency(s);
    auto q = [&](int v) {
      const auto& p = s.vertices[v];
      return std::array<mpq_class, 3>{mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)};
    };
    for (const auto& e : adj.edges)
      for (const auto& f : adj.edges) {
        const auto A = q(e.v[0]), B = q(e.v[1]), C = q(f.v[0]), D = q(f.v[1]);
        bool found = false;
        for (int k = 1; k < 32 && !found; ++k) {
          const mpq_class u(k, 32);
          std::array<mpq_class, 3> X;
          for (int i = 0; i < 3; ++i) X[i] = C[i] + u * (D[i] - C[i]);
          int sign = 0;
          bool ok = true;
          for (int ti : e.triangles) {
            int w = -1;
            for (int vv : s.triangles[ti].v)
              if (vv != e.v[0] && vv != e.v[1]) w = vv;
            const auto W = q(w);
            std::array<mpq_class, 3> u1, u2, u3;
            for (int i = 0; i < 3; ++i) u1[i] = B[i] - A[i], u2[i] = X[i] - A[i], u3[i] = W[i] - A[i];
            const mpq_class det = u1[0] * (u2[1] * u3[2] - u2[2] * u3[1]) - u1[1] * (u2[0] * u3[2] - u2[2] * u3[0]) +
                                  u1[2] * (u2[0] * u3[1] - u2[1] * u3[0]);
            const int sg = sgn(det);
            if (sg == 0 || (sign != 0 && sg != sign)) ok = false;
            sign = sg;
          }
          found = ok;
        }
        ++checked;
        if (found) {
          ++positives;
          EXPECT_TRUE(edge_rule_possible(s, e, s.vertices[f.v[0]], s.vertices[f.v[1]])) << "seed " << seed;
        }
      }
  }
  EXPECT_GT(positives, 100);
  EXPECT_GT(checked, positives);
}

}  // namespace
}  // namespace exactvis
