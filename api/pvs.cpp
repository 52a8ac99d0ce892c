#include "api/pvs.hpp"

#include "io/pvs_json.hpp"
#include "region/view_cell_grid.hpp"

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>

namespace exactvis::api {

std::vector<region::RationalBox3> grid_view_cells(const Scene& scene, const std::array<long, 3>& n,
                                                  const std::optional<region::RationalBox3>& box) {
  if (box) return region::grid_cells(*box, n);
  if (scene.triangles.empty()) throw std::invalid_argument("--grid: the scene is empty; give --box");
  const region::RationalBox3 b = region::exact_box(bounding_box(scene));
  for (int k = 0; k < 3; ++k)
    if (!(b.lo[k] < b.hi[k]))
      throw std::invalid_argument(std::string("--grid: the scene's bounding box is flat in ") + "xyz"[k] +
                                  "; give --box");
  return region::grid_cells(b, n);
}

PvsAnswer pvs(const Scene& scene, const PvsRequest& request) {
  const region::PvsOptions& o = request.options;
  if (o.query.samples < 0) throw std::invalid_argument("--samples must be >= 0");
  if (o.rays < 0 || o.cell_rays < 0) throw std::invalid_argument("--rays must be >= 0");
  if (o.threads < 0 || o.threads > region::kMaxThreads)
    throw std::invalid_argument("--threads: " + std::to_string(o.threads) +
                                " is not a thread count (0 = all cores, or 1 .. " +
                                std::to_string(region::kMaxThreads) + ")");
  for (const auto& cell : request.cells) region::check_view_cell(cell);
  const region::PvsContext context(scene);
  const auto n = static_cast<std::int64_t>(scene.triangles.size());
  const auto total = n * static_cast<std::int64_t>(request.cells.size());
  std::mutex progress_mutex;
  std::int64_t reported = 0;  // the workers' counts can arrive out of order: only increases are passed on
  PvsAnswer answer;
  answer.cells.reserve(request.cells.size());
  for (std::size_t c = 0; c < request.cells.size(); ++c) {
    region::PvsOptions options = o;
    const std::int64_t before = n * static_cast<std::int64_t>(c);
    if (request.progress)
      options.on_progress = [&](std::int64_t decided) {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        if (before + decided <= reported) return;
        reported = before + decided;
        request.progress(reported, total);
      };
    answer.cells.push_back(region::compute_cell_pvs(request.method, context, request.cells[c], options));
    if (request.progress && before + n > reported) request.progress(reported = before + n, total);
  }
  return answer;
}

nlohmann::ordered_json pvs_json(const Scene& scene, const PvsAnswer& answer, const nlohmann::ordered_json& scene_label,
                                bool witnesses) {
  std::vector<OrderedJson> cells;
  cells.reserve(answer.cells.size());
  for (std::size_t c = 0; c < answer.cells.size(); ++c)
    cells.push_back(pvs_cell_json(scene, static_cast<std::int64_t>(c), answer.cells[c], witnesses));
  return pvs_document(scene_label, static_cast<std::int64_t>(scene.triangles.size()), std::move(cells));
}

}  // namespace exactvis::api
