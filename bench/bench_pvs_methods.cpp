// bench_pvs_methods: the three PVS methods of `exactvis pvs --method` side by side on generated towns and
// forests, per cell (issue #12): time and PVS size of exact / sampled / conservative; sampled's false
// invisible (exact - sampled: the sampler never lists a hidden triangle) at equal time to exact (its ray
// count set from a short calibration run so that it takes about exact's CPU time); conservative's overestimate
// (listed / exact) and its misses (must be 0). Ratios are to exact, measured in the same run. Wall-clock and
// process CPU seconds (the machine may be shared: CPU seconds are the fairer figure).
//
// Usage: bench_pvs_methods [--kinds town,forest] [--sizes 2000,10000] [--threads 2] [--exact-max N]
//                          [--rays R] [--scan-max M] [--conservative-max C]
//   --exact-max: run exact (and sampled at equal time) only up to N triangles (default 10000); above it, only
//   conservative and sampled with --rays (default 10^6) are timed; --rays 0: no sampled rows at all.
//   --scan-max: also time conservative with the scan over all occluders (OccluderSearch::scan, the reference
//   of the 2D footprint grid) up to M triangles (default 0: not run); its PVS must equal the grid's.
//   --conservative-max: run conservative only up to C triangles (default: always), e.g. for a sampled-only
//   row of a scene too large to wait for.
#include "bench/bench_util.hpp"
#include "bench/street_cell.hpp"
#include "kernel/scene_generators.hpp"
#include "region/conservative_pvs.hpp"
#include "region/exact_pvs.hpp"
#include "region/sampled_pvs.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>

using namespace exactvis;

namespace {

std::vector<char> membership(std::size_t n, const region::CellPvs& pvs) {
  std::vector<char> in(n, 0);
  for (const auto& v : pvs.visible) in[static_cast<std::size_t>(v.index)] = 1;
  return in;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> kinds{"town", "forest"}, sizes{"2000", "10000"};
  int threads = 2;
  long exact_max = 10000;
  std::int64_t rays = 1000000;
  long scan_max = 0;
  long conservative_max = -1;  // -1: no limit
  bench::require_option_pairs(argc, argv, 1, "bench_pvs_methods");
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--kinds") kinds = bench::split(argv[i + 1]);
    else if (a == "--sizes") sizes = bench::split(argv[i + 1]);
    else if (a == "--threads") threads = std::stoi(argv[i + 1]);
    else if (a == "--exact-max") exact_max = std::stol(argv[i + 1]);
    else if (a == "--rays") rays = std::stoll(argv[i + 1]);
    else if (a == "--scan-max") scan_max = std::stol(argv[i + 1]);
    else if (a == "--conservative-max") conservative_max = std::stol(argv[i + 1]);
    else return bench::unknown_option("bench_pvs_methods", a);
  }
  std::printf("%-7s %8s %-13s %9s %9s %7s %9s %10s %9s\n", "scene", "tris", "method", "wall_s", "cpu_s", "pvs",
              "vs_exact", "rays", "errors");
  for (const auto& kind : kinds)
    for (const auto& size : sizes) {
      const Scene scene = generate_scene(kind, std::stol(size), 1);
      const region::RationalBox3 cell = bench::street_cell(scene);
      const region::PvsContext context(scene);
      const std::size_t n = scene.triangles.size();
      region::PvsOptions po;
      po.threads = threads;
      const bool with_exact = static_cast<long>(n) <= exact_max;
      auto row = [&](const char* method, const bench::Timing& tm, std::int64_t pvs, const std::string& vs, std::int64_t r,
                     const std::string& errors) {
        std::printf("%-7s %8zu %-13s %9.3f %9.3f %7lld %9s %10lld %9s\n", kind.c_str(), n, method, tm.wall, tm.cpu,
                    static_cast<long long>(pvs), vs.c_str(), static_cast<long long>(r), errors.c_str());
        std::fflush(stdout);
      };
      (void)context.extruded();  // detection and solids outside the timings (built once per scene)
      (void)context.solids();
      region::CellPvs exact, cons;
      bench::Timing t_exact;
      if (with_exact) {
        t_exact = bench::timed([&] { exact = region::exact_cell_pvs(context, cell, po); });
        row("exact", t_exact, exact.stats.visible, "1.00", 0, "-");
      }
      const bool with_cons = conservative_max < 0 || static_cast<long>(n) <= conservative_max;
      bench::Timing t_cons;
      if (with_cons) t_cons = bench::timed([&] { cons = region::conservative_cell_pvs(context, cell, po); });
      std::string vs = "-", errors = "-";
      if (with_cons && with_exact) {
        const auto in = membership(n, cons);
        std::int64_t misses = 0;
        for (const auto& v : exact.visible) misses += in[static_cast<std::size_t>(v.index)] ? 0 : 1;
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.2fx", static_cast<double>(cons.stats.visible) / static_cast<double>(std::max<std::int64_t>(1, exact.stats.visible)));
        vs = buf;
        errors = std::to_string(misses) + " miss";
      }
      if (with_cons) row("conservative", t_cons, cons.stats.visible, vs, 0, errors);
      if (with_cons && static_cast<long>(n) <= scan_max) {
        region::CellPvs scan;
        const bench::Timing t_scan = bench::timed(
            [&] { scan = region::conservative_cell_pvs(context, cell, po, region::OccluderSearch::scan); });
        bool same = scan.visible.size() == cons.visible.size();
        for (std::size_t i = 0; same && i < scan.visible.size(); ++i) same = scan.visible[i].index == cons.visible[i].index;
        char buf[48];
        std::snprintf(buf, sizeof buf, "grid %.1fx", t_scan.cpu / std::max(1e-6, t_cons.cpu));
        row("cons.scan", t_scan, scan.stats.visible, buf, 0, same ? "same" : "DIFFERENT!");
      }
      if (rays == 0) continue;  // no sampled rows
      // Sampled: calibrate the ray rate, then (with exact) as many rays as exact's time allows.
      region::PvsOptions so = po;
      so.cell_rays = 100000;
      region::CellPvs sampled;
      const bench::Timing t_cal = bench::timed([&] { sampled = region::sampled_cell_pvs(context, cell, so); });
      std::int64_t r = rays;
      // By CPU seconds, not wall: the machine may be shared, and CPU time is what equal cost means.
      if (with_exact) r = std::clamp<std::int64_t>(static_cast<std::int64_t>(100000 * t_exact.cpu / std::max(1e-3, t_cal.cpu)), 100000, 200000000);
      so.cell_rays = r;
      const bench::Timing t_s = bench::timed([&] { sampled = region::sampled_cell_pvs(context, cell, so); });
      vs = "-", errors = "-";
      if (with_exact) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.2fx", static_cast<double>(sampled.stats.visible) / static_cast<double>(std::max<std::int64_t>(1, exact.stats.visible)));
        vs = buf;
        const auto in = membership(n, exact);
        std::int64_t wrong = 0;
        for (const auto& v : sampled.visible) wrong += in[static_cast<std::size_t>(v.index)] ? 0 : 1;
        errors = std::to_string(exact.stats.visible - sampled.stats.visible + wrong) + " f.inv";
        if (wrong > 0) errors += " " + std::to_string(wrong) + " f.vis!";
      }
      row("sampled", t_s, sampled.stats.visible, vs, r, errors);
    }
  return 0;
}
