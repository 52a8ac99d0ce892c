// bench_pvs: per-cell time of `exactvis pvs` (method exact) on generated towns and forests, with and without
// the hierarchy, side by side in the same run with the per-triangle loop of `exactvis visible --triangles all`
// (region::visibility_from_source), and the PVS size. Wall-clock and process CPU seconds (the machine may be
// shared: CPU seconds are the fairer figure).
//
// Usage: bench_pvs [--kinds town,forest] [--sizes 1000,10000] [--threads 1,2] [--baseline-max N]
//                  [--methods pvs-flat,pvs-box,pvs-novirt,pvs] [--cap N]
//   --baseline-max: run the per-triangle loop only for scenes of at most N triangles (default 10000).
//   --methods: which PVS rows to run (default all): pvs-flat = rays + one exact query per triangle (no
//   hierarchy, no single-occluder proofs); pvs-box = with the hierarchy's exact hidden-box tests only;
//   pvs-novirt = hierarchy with single wall / convex solid proofs first, then box tests, rays, queries, but
//   no virtual occluders (the traversal before issue #11's front-to-back step); pvs = the default of
//   `exactvis pvs`: the same front to back with boxes proved hidden as virtual occluders (at most --cap,
//   default 32). Columns: culled = triangles proved hidden without their own query; by_occl = of those by
//   one wall / solid; by_virt = by a virtual occluder; boxes = exact hidden-box tests run.
#include "bench/bench_util.hpp"
#include "bench/street_cell.hpp"
#include "kernel/scene_generators.hpp"
#include "region/cell_visibility.hpp"
#include "region/exact_pvs.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>

using namespace exactvis;

int main(int argc, char** argv) {
  std::vector<std::string> kinds{"town", "forest"}, sizes{"1000", "10000"}, threads{"1", "2"},
      methods{"pvs-flat", "pvs-box", "pvs-novirt", "pvs"};
  long baseline_max = 10000;
  int cap = 32;
  bench::require_option_pairs(argc, argv, 1, "bench_pvs");
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--kinds") kinds = bench::split(argv[i + 1]);
    else if (a == "--sizes") sizes = bench::split(argv[i + 1]);
    else if (a == "--threads") threads = bench::split(argv[i + 1]);
    else if (a == "--baseline-max") baseline_max = std::stol(argv[i + 1]);
    else if (a == "--methods") methods = bench::split(argv[i + 1]);
    else if (a == "--cap") cap = std::stoi(argv[i + 1]);
    else return bench::unknown_option("bench_pvs", a);
  }
  std::printf("%-7s %8s %3s %-14s %8s %8s %8s %10s %8s %8s %8s %8s %8s %8s\n", "scene", "tris", "thr", "method",
              "wall_s", "cpu_s", "pvs", "tris/cpu_s", "culled", "by_occl", "by_virt", "boxes", "queries", "ratio");
  for (const auto& kind : kinds)
    for (const auto& size : sizes) {
      const Scene scene = generate_scene(kind, std::stol(size), 1);
      const region::RationalBox3 cell = bench::street_cell(scene);
      const region::PvsContext context(scene);
      const auto n = static_cast<double>(scene.triangles.size());
      for (const auto& th : threads) {
        const int t = std::stoi(th);
        double baseline_cpu = 0;
        if (static_cast<long>(scene.triangles.size()) <= baseline_max) {
          std::vector<std::int64_t> all(scene.triangles.size());
          for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::int64_t>(i);
          region::CellVisibilityOptions co;
          co.threads = t;
          region::CellVisibility cv;
          const bench::Timing tm =
              bench::timed([&] { cv = region::visibility_from_source(scene, context.index(), {cell, {}}, all, co); });
          baseline_cpu = tm.cpu;
          std::printf("%-7s %8.0f %3d %-14s %8.2f %8.2f %8lld %10.1f %8s %8s %8s %8s %8.0f %8s\n", kind.c_str(), n, t,
                      "per-triangle", tm.wall, tm.cpu, static_cast<long long>(cv.visible), n / tm.cpu, "-", "-", "-", "-",
                      n, "1.00");
        }
        for (const std::string method : {"pvs-flat", "pvs-box", "pvs-novirt", "pvs"}) {
          if (std::find(methods.begin(), methods.end(), method) == methods.end()) continue;
          region::PvsOptions po;
          po.threads = t;
          po.hierarchy = method != "pvs-flat";
          po.occluder_proofs = method == "pvs" || method == "pvs-novirt";
          po.virtual_occluders = method == "pvs" ? cap : 0;
          region::CellPvs pvs;
          const bench::Timing tm = bench::timed([&] { pvs = region::exact_cell_pvs(context, cell, po); });
          char ratio[32] = "-";
          if (baseline_cpu > 0) std::snprintf(ratio, sizeof ratio, "%.2f", baseline_cpu / tm.cpu);
          std::printf("%-7s %8.0f %3d %-14s %8.2f %8.2f %8lld %10.1f %8lld %8lld %8lld %8lld %8lld %8s\n", kind.c_str(),
                      n, t, method.c_str(), tm.wall, tm.cpu, static_cast<long long>(pvs.stats.visible), n / tm.cpu,
                      static_cast<long long>(pvs.stats.culled), static_cast<long long>(pvs.stats.culled_by_occluders),
                      static_cast<long long>(pvs.stats.culled_by_virtual), static_cast<long long>(pvs.stats.boxes_tested),
                      static_cast<long long>(pvs.stats.exact_queries), ratio);
          std::fflush(stdout);
          if (baseline_cpu == 0) baseline_cpu = tm.cpu;  // no per-triangle row: ratios to the first PVS row
        }
      }
    }
  return 0;
}
