// Benchmark of exact from-region visibility (cell-to-triangle queries) on generated towns and forests.
//
// Usage: bench_visibility [--sizes 1000,10000,100000] [--kinds town,forest] [--queries 40] [--seed 1]
// For each scene: a street-level view cell near one corner, `queries` target triangles drawn at random; each
// query timed alone on one thread. Prints per-query min/avg/max time for visible and hidden answers
// separately, average splits and effective occluders, and the least-squares exponent of
// time ~ (effective occluders)^k over the queries that used the exact CSG (see docs/performance.md).
#include "bench/bench_util.hpp"
#include "kernel/scene_generators.hpp"
#include "kernel/triangle_index.hpp"
#include "region/from_region_visibility.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using namespace exactvis;

namespace {

struct Summary {
  int n = 0;
  double min = 1e300, max = 0, sum = 0;
  void add(double v) {
    ++n;
    min = std::min(min, v);
    max = std::max(max, v);
    sum += v;
  }
  std::string str() const {
    if (n == 0) return "-";
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.2f / %.2f / %.2f", min, sum / n, max);
    return buf;
  }
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> sizes{"1000", "10000", "100000"}, kinds{"town", "forest"};
  int queries = 40;
  std::uint64_t seed = 1;
  bench::require_option_pairs(argc, argv, 1, "bench_visibility");
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--sizes")) sizes = bench::split(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--kinds")) kinds = bench::split(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--queries")) queries = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--seed")) seed = std::strtoull(argv[i + 1], nullptr, 10);
    else return bench::unknown_option("bench_visibility", std::string(argv[i]));
  }
  std::printf("| scene | triangles | queries | visible | visible ms min/avg/max | hidden ms min/avg/max | "
              "by sampling | avg occluders considered | avg effective occluders | avg splits | "
              "exponent k (time ~ eff^k) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& kind : kinds)
    for (const auto& size : sizes) {
      const Scene scene = generate_scene(kind, std::stoll(size), seed);
      const TriangleIndex index(scene);
      const region::CandidateFinder finder = [&index](const Box3& b) { return index.candidates_in_box(b); };
      const Box3 bb = bounding_box(scene);
      const Box3 cell{{bb.lo.x + 0.25, bb.lo.y + 0.25, 1}, {bb.lo.x + 1.5, bb.lo.y + 1.5, 2}};
      std::mt19937_64 rng(seed * 7919 + scene.triangles.size());
      Summary vis, hid;
      int n_vis = 0, sampled = 0;
      double occ_sum = 0, eff_sum = 0, split_sum = 0;
      std::vector<std::pair<double, double>> fit;  // (log eff, log ms)
      for (int q = 0; q < queries; ++q) {
        const std::int64_t t = static_cast<std::int64_t>(rng() % scene.triangles.size());
        const auto start = std::chrono::steady_clock::now();
        const region::VisibilityResult r = region::visible_from_box(scene, finder, cell, t);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        (r.visible ? vis : hid).add(ms);
        n_vis += r.visible;
        sampled += r.stats.accepted_by_sampling;
        occ_sum += r.stats.occluders_considered;
        eff_sum += r.stats.effective_occluders;
        split_sum += r.stats.splits;
        if (!r.stats.accepted_by_sampling && r.stats.effective_occluders > 0)
          fit.push_back({std::log(static_cast<double>(r.stats.effective_occluders)), std::log(ms)});
      }
      double k = NAN;
      if (fit.size() >= 3) {
        double mx = 0, my = 0;
        for (auto& [x, y] : fit) mx += x, my += y;
        mx /= fit.size();
        my /= fit.size();
        double sxy = 0, sxx = 0;
        for (auto& [x, y] : fit) sxy += (x - mx) * (y - my), sxx += (x - mx) * (x - mx);
        if (sxx > 0) k = sxy / sxx;
      }
      std::printf("| %s | %zu | %d | %d | %s | %s | %d | %.1f | %.1f | %.1f | %.2f (%zu queries) |\n", kind.c_str(),
                  scene.triangles.size(), queries, n_vis, vis.str().c_str(), hid.str().c_str(), sampled,
                  occ_sum / queries, eff_sum / queries, split_sum / queries, k, fit.size());
      std::fflush(stdout);
    }
  return 0;
}
