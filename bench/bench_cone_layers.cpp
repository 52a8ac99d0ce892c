// bench_cone_layers: one street-level cell of `exactvis pvs` (method exact, the default options, 1 thread) on
// generated towns and forests, with the cone arithmetic counted by layer (region/cone_vector6, docs/theory.md
// §5.4): signs decided by the float filter / the fixed-width int64-__int128 layer / GMP, constructions (new
// rays, edge functionals) in the fixed layer / GMP. Process CPU seconds (the machine may be shared).
//
// Usage: bench_cone_layers [--kinds town,forest] [--sizes 1000,2000] [--threads 1]
// Compare builds by running this (or `exactvis pvs`) from both under /usr/bin/time in one session.
#include "bench/bench_util.hpp"
#include "bench/street_cell.hpp"
#include "kernel/scene_generators.hpp"
#include "kernel/predicate_counters.hpp"
#include "region/cone_vector6.hpp"
#include "region/exact_pvs.hpp"

#include <cstdio>
#include <ctime>
#include <string>

using namespace exactvis;

int main(int argc, char** argv) {
  std::vector<std::string> kinds{"town", "forest"}, sizes{"1000", "2000"};
  int threads = 1;
  bench::require_option_pairs(argc, argv, 1, "bench_cone_layers");
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--kinds") kinds = bench::split(argv[i + 1]);
    else if (a == "--sizes") sizes = bench::split(argv[i + 1]);
    else if (a == "--threads") threads = std::stoi(argv[i + 1]);
    else return bench::unknown_option("bench_cone_layers", a);
  }
  std::printf("%-7s %8s %8s %6s %8s %9s %10s %10s %8s %10s %8s\n", "scene", "tris", "cpu_s", "pvs", "splits",
              "sign_filt", "sign_fixed", "sign_gmp", "gmp_%", "cons_fixed", "cons_gmp");
  for (const auto& kind : kinds)
    for (const auto& size : sizes) {
      const Scene scene = generate_scene(kind, std::stol(size), 1);
      const region::RationalBox3 cell = bench::street_cell(scene);
      const region::PvsContext context(scene);
      region::PvsOptions po;
      po.threads = threads;
      reset_predicate_counters();
      const std::clock_t c0 = std::clock();
      const region::CellPvs pvs = region::exact_cell_pvs(context, cell, po);
      const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
      const auto& q = pvs.stats.query;
      const region::ConeLayerCounts c = region::cone_layer_counts();
      const double signs = static_cast<double>(c.signs[0] + c.signs[1] + c.signs[2]);
      std::printf("%-7s %8zu %8.2f %6lld %8lld %9lld %10lld %10lld %8.3f %10lld %8lld\n", kind.c_str(),
                  scene.triangles.size(), cpu, static_cast<long long>(pvs.stats.visible),
                  static_cast<long long>(q.splits), static_cast<long long>(c.signs[0]),
                  static_cast<long long>(c.signs[1]), static_cast<long long>(c.signs[2]),
                  signs > 0 ? 100.0 * static_cast<double>(c.signs[2]) / signs : 0.0,
                  static_cast<long long>(c.constructions[1]), static_cast<long long>(c.constructions[2]));
      std::fflush(stdout);
    }
  return 0;
}
