#include "api/visible.hpp"

#include "kernel/triangle_index.hpp"

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>

namespace exactvis::api {

region::RationalBox3 cell_box(const Exact& x0, const Exact& y0, const Exact& z0, const Exact& x1, const Exact& y1,
                              const Exact& z1) {
  region::RationalBox3 b;
  b.lo = RationalPoint3{x0, y0, z0};
  b.hi = RationalPoint3{x1, y1, z1};
  for (int k = 0; k < 3; ++k)
    if (!(b.lo[k] < b.hi[k])) throw std::invalid_argument("--cell: need X0 < X1, Y0 < Y1 and Z0 < Z1");
  return b;
}

std::vector<std::int64_t> triangle_indices(const Scene& scene, const std::optional<std::vector<std::int64_t>>& ids) {
  std::vector<std::int64_t> out;
  if (!ids) {
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) out.push_back(static_cast<std::int64_t>(i));
    return out;
  }
  for (const std::int64_t id : *ids) {
    const std::int64_t index = scene.index_of_id(id);
    if (index < 0)
      throw std::invalid_argument("--triangles: triangle id " + std::to_string(id) +
                                  " is not in the scene (out of range, or dropped as degenerate)");
    out.push_back(index);
  }
  return out;
}

VisibleAnswer visible(const Scene& scene, const VisibleRequest& request) {
  if (request.samples < 0) throw std::invalid_argument("--samples must be >= 0");
  if (request.threads < 0 || request.threads > region::kMaxThreads)
    throw std::invalid_argument("--threads: " + std::to_string(request.threads) +
                                " is not a thread count (0 = all cores, or 1 .. " +
                                std::to_string(region::kMaxThreads) + ")");
  if (!request.source.cell) {
    try {
      region::validate_source_polygon(request.source.polygon);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--source-polygon: ") + e.what());
    }
  }
  const std::vector<std::int64_t> targets = triangle_indices(scene, request.triangle_ids);
  region::CellVisibilityOptions options;
  options.query.samples = request.samples;
  options.query.seed = request.seed;
  options.threads = request.threads;
  std::int64_t done = 0;  // counted under the lock, so that the calls see 1, 2, ..., total in order
  std::mutex progress_mutex;
  const auto total = static_cast<std::int64_t>(targets.size());
  if (request.progress)
    options.on_target_done = [&] {
      const std::lock_guard<std::mutex> lock(progress_mutex);
      request.progress(++done, total);
    };
  const region::CellVisibility cv =
      region::visibility_from_source(scene, TriangleIndex(scene), request.source, targets, options);
  VisibleAnswer answer;
  answer.visible = cv.visible;
  answer.accepted_by_sampling = cv.accepted_by_sampling;
  answer.stats = cv.stats;
  answer.triangles.reserve(cv.results.size());
  for (const auto& r : cv.results)
    answer.triangles.push_back({scene.triangles[r.triangle_index].id, r.visible, r.witness});
  return answer;
}

}  // namespace exactvis::api
