// Benchmark of EV and EEE event enumeration: time vs scene size (full enumeration and light-restricted) and vs
// output size. Prints tables (docs/performance.md "bench_events" has the figures and the command).
//
// Usage: bench_events [--kinds town,forest,random,room] [--full 100,300,1000,3000] [--light 1000,10000,100000]
//                     [--eee-full 100,300] [--eee-light 1000,10000] [--split 1|0] [--seed 1]
// An empty list ("--full ''") skips that table. --split 0 turns off the EV end-object splitting.
#include "bench/bench_util.hpp"
#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"
#include "events/light_source.hpp"
#include "events/scene_adjacency.hpp"
#include "kernel/predicate_counters.hpp"
#include "kernel/scene_generators.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace exactvis;

namespace {

struct Row {
  double seconds = 0;
  std::size_t events = 0, intervals = 0;
  EvStats stats;
};

Row run(const Scene& scene, const EvOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  const EvResult r = enumerate_ev_events(scene, opt);
  Row row;
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  row.events = r.events.size();
  for (const auto& e : r.events) row.intervals += e.intervals.size();
  row.stats = r.stats;
  return row;
}

// A square light of side 1/10 of the scene's diagonal extent, just above the scene's top, centred.
std::vector<Point3> light_polygon(const Scene& s) {
  const Box3 b = bounding_box(s);
  const double cx = std::round((b.lo.x + b.hi.x) / 2), cy = std::round((b.lo.y + b.hi.y) / 2);
  const double h = std::max(1.0, std::round((b.hi.x - b.lo.x) / 20));
  const double z = b.hi.z + h;
  return {{cx - h, cy - h, z}, {cx + h, cy - h, z}, {cx + h, cy + h, z}, {cx - h, cy + h, z}};
}

struct EeeRow {
  double seconds = 0;
  std::size_t events = 0, intervals = 0;
  EeeEnumerationStats stats;
};

EeeRow run_eee(const Scene& scene, const EeeOptions& opt) {
  reset_predicate_counters();
  const auto t0 = std::chrono::steady_clock::now();
  const EeeResult r = enumerate_eee_events(scene, opt);
  EeeRow row;
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  row.events = r.events.size();
  for (const auto& e : r.events) row.intervals += e.intervals.size();
  row.stats = r.stats;
  return row;
}

void eee_header(const char* title) {
  std::printf("\n%s\n%-7s %8s %8s %12s %10s %10s %12s %8s %9s %9s %7s\n", title, "kind", "tris", "edges", "outer.pairs",
              "kept", "triples", "occl.tests", "events", "intervals", "seconds", "growth");
}

void eee_print(const std::string& kind, const Scene& s, const EeeRow& r, double growth) {
  const std::size_t edges = build_scene_adjacency(s).edges.size();
  std::printf("%-7s %8zu %8zu %12llu %10llu %10llu %12llu %8zu %9zu %9.3f ", kind.c_str(), s.triangles.size(), edges,
              (unsigned long long)r.stats.outer_pairs, (unsigned long long)r.stats.outer_pairs_kept,
              (unsigned long long)r.stats.candidate_triples, (unsigned long long)r.stats.eee.occluder_tests, r.events,
              r.intervals, r.seconds);
  if (std::isnan(growth)) std::printf("%7s\n", "-");
  else std::printf("%7.2f\n", growth);
  // The occluder layers of eee_event (docs/theory.md section 9, "Scale"): interval-decided / exact.
  std::printf("        occluder layers (interval / exact):");
  for (const auto& c : predicate_counters())
    if (c.name.rfind("eee_", 0) == 0)
      std::printf(" %s %llu / %llu", c.name.c_str(), (unsigned long long)c.interval, (unsigned long long)c.exact);
  std::printf("\n");
  std::fflush(stdout);
}

void header(const char* title) {
  std::printf("\n%s\n%-7s %8s %8s %8s %11s %11s %12s %8s %9s %9s %7s\n", title, "kind", "tris", "verts", "edges",
              "pairs", "tangent", "occl.tests", "events", "intervals", "seconds", "growth");
}

void print(const std::string& kind, const Scene& s, const Row& r, double growth) {
  const std::size_t edges = build_scene_adjacency(s).edges.size();
  std::printf("%-7s %8zu %8zu %8zu %11llu %11llu %12llu %8zu %9zu %9.3f ", kind.c_str(), s.triangles.size(),
              s.vertices.size(), edges, (unsigned long long)r.stats.pairs, (unsigned long long)r.stats.tangent_pairs,
              (unsigned long long)r.stats.occluder_tests, r.events, r.intervals, r.seconds);
  if (std::isnan(growth)) std::printf("%7s\n", "-");
  else std::printf("%7.2f\n", growth);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> kinds{"town", "forest", "random"};
  std::vector<std::string> full{"100", "300", "1000", "3000"};
  std::vector<std::string> light{"1000", "10000", "100000"};
  std::vector<std::string> eee_full{"100", "300"};
  std::vector<std::string> eee_light{"1000", "10000"};
  bool split_ev = true;
  std::uint64_t seed = 1;
  bench::require_option_pairs(argc, argv, 1, "bench_events");
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i], v = argv[i + 1];
    if (a == "--kinds") kinds = bench::split(v);
    else if (a == "--full") full = bench::split(v);
    else if (a == "--light") light = bench::split(v);
    else if (a == "--eee-full") eee_full = bench::split(v);
    else if (a == "--eee-light") eee_light = bench::split(v);
    else if (a == "--split") split_ev = v != "0";
    else if (a == "--seed") seed = std::stoull(v);
    else return bench::unknown_option("bench_events", a);
  }
  std::printf("EV and EEE events, both cores (oneTBB); growth = log(time ratio) / log(triangle ratio) vs previous "
              "row; EV intervals %s at end-object changes\n", split_ev ? "split" : "not split");
  EvOptions base;
  base.split_at_end_objects = split_ev;
  if (!full.empty()) header("EV: full enumeration (all vertex-edge pairs)");
  for (const auto& kind : kinds) {
    double prev_t = NAN, prev_n = NAN;
    for (const auto& n : full) {
      const Scene s = generate_scene(kind, std::stoll(n), seed);
      const Row r = run(s, base);
      const double nn = static_cast<double>(s.triangles.size());
      print(kind, s, r, std::log(r.seconds / prev_t) / std::log(nn / prev_n));
      prev_t = r.seconds;
      prev_n = nn;
    }
  }
  if (!light.empty()) header("EV: light-restricted (a square light above the scene's centre, appended to the scene)");
  for (const auto& kind : kinds) {
    double prev_t = NAN, prev_n = NAN;
    for (const auto& n : light) {
      Scene s = generate_scene(kind, std::stoll(n), seed);
      EvOptions opt = base;
      opt.light_triangles = append_light_polygon(s, light_polygon(s)).triangles;
      const Row r = run(s, opt);
      const double nn = static_cast<double>(s.triangles.size());
      print(kind, s, r, std::log(r.seconds / prev_t) / std::log(nn / prev_n));
      prev_t = r.seconds;
      prev_n = nn;
    }
  }
  if (!eee_full.empty()) eee_header("EEE: full enumeration (all outer edge pairs)");
  for (const auto& kind : kinds) {
    double prev_t = NAN, prev_n = NAN;
    for (const auto& n : eee_full) {
      const Scene s = generate_scene(kind, std::stoll(n), seed);
      const EeeRow r = run_eee(s, {});
      const double nn = static_cast<double>(s.triangles.size());
      eee_print(kind, s, r, std::log(r.seconds / prev_t) / std::log(nn / prev_n));
      prev_t = r.seconds;
      prev_n = nn;
    }
  }
  if (!eee_light.empty()) eee_header("EEE: light-restricted (same light)");
  for (const auto& kind : kinds) {
    double prev_t = NAN, prev_n = NAN;
    for (const auto& n : eee_light) {
      Scene s = generate_scene(kind, std::stoll(n), seed);
      EeeOptions opt;
      opt.light_triangles = append_light_polygon(s, light_polygon(s)).triangles;
      const EeeRow r = run_eee(s, opt);
      const double nn = static_cast<double>(s.triangles.size());
      eee_print(kind, s, r, std::log(r.seconds / prev_t) / std::log(nn / prev_n));
      prev_t = r.seconds;
      prev_n = nn;
    }
  }
  return 0;
}
