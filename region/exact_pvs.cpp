#include "region/exact_pvs.hpp"

#include "region/cell_visibility.hpp"
#include "region/from_region_visibility.hpp"
#include "region/ray_witness.hpp"
#include "util/for_each_index.hpp"

#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>

namespace exactvis::region {
namespace {

std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ull * (index + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

Box3 approximate_box(const RationalBox3& b) {
  return {{CGAL::to_double(b.lo.x), CGAL::to_double(b.lo.y), CGAL::to_double(b.lo.z)},
          {CGAL::to_double(b.hi.x), CGAL::to_double(b.hi.y), CGAL::to_double(b.hi.z)}};
}

struct TriangleAnswer {
  bool visible = false;
  bool by_rays = false;
  std::optional<Witness> witness;
  VisibilityStats stats;
};

}  // namespace

CellPvs exact_cell_pvs(const PvsContext& context, const RationalBox3& cell, const PvsOptions& options) {
  check_view_cell(cell);
  if (options.threads < 0 || options.threads > kMaxThreads)
    throw std::invalid_argument("thread count " + std::to_string(options.threads) + " is outside 0 .. " +
                                std::to_string(kMaxThreads));
  const auto start = std::chrono::steady_clock::now();
  const Scene& scene = context.scene();
  const std::size_t n = scene.triangles.size();
  const CandidateFinder finder = index_candidates(context.index());
  const Box3 approx = approximate_box(cell);
  std::vector<TriangleAnswer> answers(n);
  std::atomic<std::int64_t> decided{0};

  auto decide = [&](std::size_t i) {
    const auto t = static_cast<std::int64_t>(i);
    TriangleAnswer& a = answers[i];
    std::mt19937_64 rng(mix_seed(options.query.seed, i));
    if (auto w = ray_witness(context, cell, approx, t, options.rays, rng)) {
      a.visible = a.by_rays = true;
      a.witness = std::move(w);
    } else {
      VisibilityResult r = visible_from_box(scene, finder, cell, t, options.query);
      a.visible = r.visible;
      a.witness = std::move(r.witness);
      a.stats = r.stats;
      a.stats.exact_evaluations = 0;  // a process-wide counter: not deterministic under threads
    }
    const std::int64_t d = decided.fetch_add(1) + 1;
    if (options.on_progress) options.on_progress(d);
  };
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] { for_each_index(n, options.threads != 1, 4, decide); });

  CellPvs out;
  out.cell = cell;
  out.stats.triangles = static_cast<std::int64_t>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const TriangleAnswer& a = answers[i];
    if (a.by_rays) ++out.stats.accepted_by_rays;
    else {
      ++out.stats.exact_queries;
      accumulate(out.stats.query, a.stats);
    }
    if (a.visible) out.visible.push_back({static_cast<std::int64_t>(i), a.witness});
  }
  out.stats.visible = static_cast<std::int64_t>(out.visible.size());
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace exactvis::region
