// The interval layer of eee_event's occluder analysis (events/eee_occluder_pattern.hpp) against the exact
// analysis it stands in front of: every EEE event of random, integer-grid, degenerate and nearly degenerate
// scenes and of generated towns and rooms is computed with the filters on and off (set_filter_enabled(false):
// exact path only), and the two must agree in every field (ends, causes, features, keys, sample lines). The
// exact path itself is checked against the brute-force oracle in test_eee_events.cpp. The counters must show
// that the pattern layer decided occluders, including occluders that block something (exact ends built from
// the pattern), so the comparison exercises it.
#include "events/eee_events.hpp"
#include "events/eee_enumeration.hpp"
#include "events/eee_occluder_pattern.hpp"
#include "kernel/filtered_predicate.hpp"
#include "kernel/predicate_counters.hpp"
#include "kernel/predicates.hpp"
#include "kernel/scene_generators.hpp"
#include "kernel/triangle_index.hpp"
#include "tests/events/event_test_scenes.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace exactvis {
namespace {

using namespace event_test;

std::string describe_end(const CriticalEnd& e) {
  std::string s = std::string(cause_name(e.cause)) + " g" + std::to_string(e.generator) + " v" +
                  std::to_string(e.vertex) + " T" + std::to_string(e.triangle) + " f" +
                  std::to_string(static_cast<int>(e.feature.kind)) + "{";
  for (int id : e.feature.ids) s += std::to_string(id) + ",";
  return s + "} " + to_string(e.line);
}

std::string describe(const EeeEvent& ev) {
  std::string s;
  for (const auto& e : ev.edges) s += "[" + std::to_string(e[0]) + "," + std::to_string(e[1]) + "]";
  for (const auto& iv : ev.intervals)
    s += " [" + root_number_to_string(iv.t0) + " (" + describe_end(iv.end0) + "), " + root_number_to_string(iv.t1) +
         " (" + describe_end(iv.end1) + ") sample " + to_rational_string(iv.sample_t) + "]";
  return s;
}

// Every triple of edges of `s` through eee_event, described.
std::vector<std::string> all_events(const Scene& s) {
  const SceneAdjacency adj = build_scene_adjacency(s);
  const TriangleIndex index(s);
  std::vector<std::string> out;
  const int m = static_cast<int>(adj.edges.size());
  for (int a = 0; a < m; ++a)
    for (int b = a + 1; b < m; ++b)
      for (int c = b + 1; c < m; ++c)
        if (auto ev = eee_event(s, adj, index, a, b, c)) out.push_back(describe(*ev));
  return out;
}

std::vector<std::string> enumerated_events(const Scene& s) {
  EeeOptions o;
  o.parallel = false;
  o.segment_ends = false;
  std::vector<std::string> out;
  for (const auto& ev : enumerate_eee_events(s, o).events) out.push_back(describe(ev));
  return out;
}

struct LayerCounts {
  std::uint64_t certified = 0, exact = 0;  // patterns certified / left to the exact analysis
  std::uint64_t checked = 0, refuted = 0;  // certified patterns whose tie assumptions held / failed
};
LayerCounts pattern_counts() {
  LayerCounts c;
  for (const auto& p : predicate_counters()) {
    if (p.name == "eee_occluder_pattern") c.certified = p.interval, c.exact = p.exact;
    if (p.name == "eee_occluder_pattern_check") c.checked = p.interval, c.refuted = p.exact;
  }
  return c;
}

// Compares filter on / off on one scene; returns the number of events.
std::size_t compare(const Scene& s, const std::string& what, bool enumerate) {
  set_filter_enabled(true);
  const std::vector<std::string> on = enumerate ? enumerated_events(s) : all_events(s);
  set_filter_enabled(false);
  const std::vector<std::string> off = enumerate ? enumerated_events(s) : all_events(s);
  set_filter_enabled(true);
  EXPECT_EQ(on.size(), off.size()) << what;
  for (std::size_t i = 0; i < std::min(on.size(), off.size()); ++i) {
    EXPECT_EQ(on[i], off[i]) << what << ", event " << i;
    if (on[i] != off[i]) break;
  }
  return on.size();
}

Scene soup(std::mt19937& rng, int n, int kind) {
  std::uniform_real_distribution<double> real(-4, 4), off(-1.5, 1.5), tiny(-1e-12, 1e-12);
  std::uniform_int_distribution<int> grid(-3, 3), small(-1, 1);
  std::vector<Point3> v;
  std::vector<std::array<int, 3>> t;
  while (static_cast<int>(t.size()) < n) {
    const int b = static_cast<int>(v.size());
    const Point3 c{real(rng), real(rng), real(rng)};
    for (int q = 0; q < 3; ++q) {
      switch (kind) {
        case 0: v.push_back({c.x + off(rng), c.y + off(rng), c.z + off(rng)}); break;           // doubles
        case 1: v.push_back({double(grid(rng)), double(grid(rng)), double(grid(rng))}); break;  // integer grid
        case 2: v.push_back({0.5 * small(rng), 0.5 * small(rng), 0.5 * (small(rng) + 1)}); break;  // tiny grid
        default:  // a grid perturbed by ~1e-12: breakpoints ulps apart
          v.push_back({small(rng) + tiny(rng), small(rng) + tiny(rng), small(rng) + 1 + tiny(rng)});
      }
    }
    if (collinear(v[b], v[b + 1], v[b + 2])) {
      v.resize(b);
      continue;
    }
    t.push_back({b, b + 1, b + 2});
  }
  return make_scene(v, t);
}

TEST(EeeOccluderPattern, SameEventsAsTheExactAnalysisOnRandomScenes) {
  std::mt19937 rng(20261204);
  reset_predicate_counters();
  std::size_t events[4] = {};
  for (int scene = 0; scene < 12; ++scene) {
    const int kind = scene % 4;
    const Scene s = soup(rng, kind == 0 ? 9 : 7, kind);
    events[kind] += compare(s, "kind " + std::to_string(kind) + " scene " + std::to_string(scene), false);
    if (::testing::Test::HasFailure()) break;
  }
  const LayerCounts c = pattern_counts();
  std::printf("pattern layer: %llu certified, %llu exact, %llu ties checked, %llu refuted; events by kind %zu %zu "
              "%zu %zu\n", (unsigned long long)c.certified, (unsigned long long)c.exact,
              (unsigned long long)c.checked, (unsigned long long)c.refuted, events[0], events[1], events[2], events[3]);
  for (std::size_t e : events) EXPECT_GT(e, 0u);
  EXPECT_GT(c.certified, 100u);  // the layer decides most occluders (the filter-off runs count as exact)
}

TEST(EeeOccluderPattern, SameEventsAsTheExactAnalysisOnGeneratedScenes) {
  // Closed meshes with shared edges, axis-parallel walls and coplanar faces (the towns and rooms of the
  // benchmarks), through the enumeration.
  std::size_t events = 0;
  reset_predicate_counters();
  for (const auto& [kind, n] : std::vector<std::pair<std::string, int>>{{"town", 40}, {"room", 40}, {"forest", 30},
                                                                         {"random", 12}})
    events += compare(generate_scene(kind, n, 3), kind, true);
  const LayerCounts c = pattern_counts();
  std::printf("pattern layer: %llu certified, %llu exact, %llu ties checked, %llu refuted; %zu events\n",
              (unsigned long long)c.certified, (unsigned long long)c.exact, (unsigned long long)c.checked,
              (unsigned long long)c.refuted, events);
  EXPECT_GT(events, 0u);
  EXPECT_GT(c.certified, 0u);
  EXPECT_GT(c.checked, 0u);  // shared edge lines: ties with the range ends, checked exactly
}

}  // namespace
}  // namespace exactvis
