// Benchmark of exact exterior visibility (`exactvis exterior`) on real models, and the sampling pipeline of
// seed 003 at equal time.
//
// Usage: bench_exterior MODEL... [--threads N] [--rays 4096] [--slow SECONDS] [--no-sampled]
// For each model: triangles, kept, removed, how many triangles each stage decided (proposal / enclosure /
// query visible / query hidden), wall-clock time of the exact run (index and BVH included), then the sampler
// run with its default views and resolution and, when the exact run took longer, with views scaled up to about
// the same time; for each sampler run: kept, and its mistakes against the exact answer (removed but visible,
// kept but hidden). With --slow S the exact run goes triangle by triangle on one thread and lists every
// triangle that took longer than S seconds (its stage), to find where time goes.
#include "bench/bench_util.hpp"
#include "io/load_scene.hpp"
#include "kernel/float_ray_caster.hpp"
#include "kernel/triangle_index.hpp"
#include "region/exterior_sampled.hpp"
#include "region/exterior_visibility.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace exactvis;

namespace {

const char* stage_name(region::ExteriorStage s) {
  switch (s) {
    case region::ExteriorStage::Proposal: return "proposal";
    case region::ExteriorStage::Enclosure: return "enclosure";
    case region::ExteriorStage::QueryVisible: return "query-visible";
    case region::ExteriorStage::QueryHidden: return "query-hidden";
  }
  return "?";
}

struct SamplerRow {
  int views = 0, resolution = 0;
  double seconds = 0;
  std::int64_t kept = 0, missed = 0, wrongly_kept = 0;
};

SamplerRow run_sampler(const Scene& scene, const FloatRayCaster& caster, const std::vector<bool>& exact, int views,
                       int threads) {
  region::SampledExteriorOptions so;
  so.views = views;
  so.threads = threads;
  const double t0 = bench::now();
  const region::SampledExterior s = region::sampled_exterior_visibility(scene, caster, so);
  SamplerRow row{views, so.resolution, bench::now() - t0, s.kept_count, 0, 0};
  for (std::size_t i = 0; i < exact.size(); ++i) {
    row.missed += exact[i] && !s.kept[i] ? 1 : 0;
    row.wrongly_kept += !exact[i] && s.kept[i] ? 1 : 0;
  }
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> models;
  int threads = 0, rays = 4096;
  double slow = -1;
  bool sampled = true;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) threads = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--rays") && i + 1 < argc) rays = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--slow") && i + 1 < argc) slow = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--no-sampled")) sampled = false;
    else models.push_back(argv[i]);
  }
  std::printf("%-28s %9s %9s %8s %9s %9s %9s %9s %9s | %s\n", "model", "triangles", "kept", "removed", "proposal",
              "enclosure", "q-visible", "q-hidden", "exact s", "sampled: views kept missed wrongly-kept s");
  for (const std::string& path : models) {
    try {
      const double t0 = bench::now();
      const Scene scene = load_scenes({path});
      const TriangleIndex index(scene);
      const FloatRayCaster caster(scene);
      region::ExteriorOptions eo;
      eo.threads = threads;
      eo.rays = rays;
      std::vector<bool> kept(scene.triangles.size());
      region::ExteriorCounts c;
      if (slow >= 0) {
        const region::ExteriorClassifier classifier(scene, index, &caster, eo);
        for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
          const double ts = bench::now();
          const region::ExteriorTriangle r = classifier.classify(static_cast<std::int64_t>(i));
          const double dt = bench::now() - ts;
          if (dt > slow)
            std::fprintf(stderr, "  triangle id %lld: %.2f s, %s\n", static_cast<long long>(scene.triangles[i].id), dt,
                         stage_name(r.stage));
          kept[i] = r.visible;
          (r.visible ? c.visible : c.hidden) += 1;
          switch (r.stage) {
            case region::ExteriorStage::Proposal: ++c.by_proposal; break;
            case region::ExteriorStage::Enclosure: ++c.by_enclosure; break;
            case region::ExteriorStage::QueryVisible: ++c.by_query_visible; break;
            case region::ExteriorStage::QueryHidden: ++c.by_query_hidden; break;
          }
        }
      } else {
        const region::ExteriorVisibility ev = region::exterior_visibility(scene, index, &caster, eo);
        for (std::size_t i = 0; i < kept.size(); ++i) kept[i] = ev.triangles[i].visible;
        c = ev.counts;
      }
      const double exact_seconds = bench::now() - t0;
      const std::string name = path.substr(path.find_last_of('/') + 1);
      std::printf("%-28s %9zu %9lld %8lld %9lld %9lld %9lld %9lld %9.2f |", name.c_str(), scene.triangles.size(),
                  static_cast<long long>(c.visible), static_cast<long long>(c.hidden),
                  static_cast<long long>(c.by_proposal), static_cast<long long>(c.by_enclosure),
                  static_cast<long long>(c.by_query_visible), static_cast<long long>(c.by_query_hidden), exact_seconds);
      if (sampled) {
        std::vector<SamplerRow> rows{run_sampler(scene, caster, kept, 256, threads)};
        if (rows[0].seconds < 0.5 * exact_seconds) {
          const int views = static_cast<int>(std::min(65536.0, 256.0 * exact_seconds / std::max(rows[0].seconds, 1e-3)));
          rows.push_back(run_sampler(scene, caster, kept, views, threads));
        }
        for (const SamplerRow& r : rows)
          std::printf(" %d %lld %lld %lld %.2f;", r.views, static_cast<long long>(r.kept),
                      static_cast<long long>(r.missed), static_cast<long long>(r.wrongly_kept), r.seconds);
      }
      std::printf("\n");
      std::fflush(stdout);
    } catch (const std::exception& e) {
      std::printf("%s: error: %s\n", path.c_str(), e.what());
    }
  }
  return 0;
}
