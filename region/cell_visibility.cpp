#include "region/cell_visibility.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <stdexcept>
#include <string>

namespace exactvis::region {

void check_thread_count(int threads) {
  if (threads < 0 || threads > kMaxThreads)
    throw std::invalid_argument("thread count " + std::to_string(threads) + " is outside 0 .. " +
                                std::to_string(kMaxThreads));
}

CellVisibility visibility_from_source(const Scene& scene, const TriangleIndex& index, const VisibilitySource& source,
                                      const std::vector<std::int64_t>& targets, const CellVisibilityOptions& options) {
  check_thread_count(options.threads);
  for (const std::int64_t t : targets)
    if (t < 0 || t >= static_cast<std::int64_t>(scene.triangles.size()))
      throw std::invalid_argument("target triangle index " + std::to_string(t) + " is out of range");
  const CandidateFinder finder = index_candidates(index);
  CellVisibility out;
  out.results.resize(targets.size());
  auto one = [&](std::size_t i) {
    out.results[i] = source.cell ? visible_from_box(scene, finder, *source.cell, targets[i], options.query)
                                 : visible_from_polygon(scene, finder, source.polygon, targets[i], options.query);
    if (options.on_target_done) options.on_target_done();
  };
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] { tbb::parallel_for(std::size_t(0), targets.size(), one); });
  for (const auto& r : out.results) {
    accumulate(out.stats, r.stats);
    out.visible += r.visible ? 1 : 0;
    out.accepted_by_sampling += r.stats.accepted_by_sampling ? 1 : 0;
  }
  return out;
}

}  // namespace exactvis::region
