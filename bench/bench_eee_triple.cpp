// Benchmark of one exact EEE computation (eee_event on a single edge triple) vs scene size: the per-triple
// cost that the EEE enumeration multiplies by its number of candidate triples. Triples are local: E1 random,
// E2 and E3 random edges of triangles meeting E1's bounding box grown by its largest side on each side.
// Prints a table (docs/performance.md, "bench_eee_triple").
//
// Usage: bench_eee_triple [--kinds random,town] [--sizes 100,1000,10000,100000] [--triples 1000] [--seed 1]
#include "bench/bench_util.hpp"
#include "events/eee_events.hpp"
#include "kernel/triangle_index.hpp"
#include "events/scene_adjacency.hpp"
#include "kernel/scene_generators.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace exactvis;

int main(int argc, char** argv) {
  std::vector<std::string> kinds{"random", "town"};
  std::vector<std::string> sizes{"100", "1000", "10000", "100000"};
  int triples = 1000;
  unsigned seed = 1;
  bench::require_option_pairs(argc, argv, 1, "bench_eee_triple");
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i], v = argv[i + 1];
    if (a == "--kinds") kinds = bench::split(v);
    else if (a == "--sizes") sizes = bench::split(v);
    else if (a == "--triples") triples = std::atoi(v.c_str());
    else if (a == "--seed") seed = static_cast<unsigned>(std::atoi(v.c_str()));
    else return bench::unknown_option("bench_eee_triple", a);
  }
  std::printf("%-8s %9s %8s %10s %10s %8s %10s %12s\n", "kind", "triangles", "triples", "base-valid", "events",
              "occl/tr", "us/triple", "us/event-tr");
  for (const auto& kind : kinds) {
    for (const auto& size : sizes) {
      const Scene scene = generate_scene(kind, std::atoll(size.c_str()), seed);
      const SceneAdjacency adj = build_scene_adjacency(scene);
      const TriangleIndex index(scene);
      std::mt19937 rng(seed);
      std::uniform_int_distribution<int> pick(0, static_cast<int>(adj.edges.size()) - 1);
      EeeStats stats;
      int events = 0;
      double seconds = 0, event_seconds = 0;
      for (int n = 0; n < triples; ++n) {
        const int e1 = pick(rng);
        const Point3 a = scene.vertices[adj.edges[e1].v[0]], b = scene.vertices[adj.edges[e1].v[1]];
        const double g = std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
        Box3 box{{std::min(a.x, b.x) - g, std::min(a.y, b.y) - g, std::min(a.z, b.z) - g},
                 {std::max(a.x, b.x) + g, std::max(a.y, b.y) + g, std::max(a.z, b.z) + g}};
        std::vector<int> near;
        for (int ti : index.triangles_meeting_box(box)) {
          const auto& t = scene.triangles[ti];
          for (int k = 0; k < 3; ++k) near.push_back(adj.edge_index(t.v[k], t.v[(k + 1) % 3]));
        }
        if (near.size() < 2) continue;
        std::uniform_int_distribution<std::size_t> pn(0, near.size() - 1);
        const int e2 = near[pn(rng)], e3 = near[pn(rng)];
        const auto t0 = std::chrono::steady_clock::now();
        const auto ev = eee_event(scene, adj, index, e1, e2, e3, &stats);
        const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        seconds += dt;
        if (ev) ++events, event_seconds += dt;
      }
      std::printf("%-8s %9zu %8d %10llu %10d %8.1f %10.1f %12.1f\n", kind.c_str(), scene.triangles.size(), triples,
                  static_cast<unsigned long long>(stats.tangent_triples), events,
                  stats.tangent_triples ? double(stats.occluder_tests) / double(stats.tangent_triples) : 0.0,
                  1e6 * seconds / triples, events ? 1e6 * event_seconds / events : 0.0);
      std::fflush(stdout);
    }
  }
  return 0;
}
