#pragma once
// Job façade: exact from-region visibility ("which triangles can be seen from this view cell or polygon?").
// What `exactvis visible` computes (docs/cli.md "visible", definitions in docs/theory.md section 5), as one
// call for programs that link exactvis::api (C++) or import exactvis (Python, python/).
//
//   #include <exactvis/api/visible.hpp>
//   exactvis::Scene scene = exactvis::load_scene("town.obj");
//   exactvis::api::VisibleRequest req;
//   req.source.cell = exactvis::api::cell_box(0, 0, 1, 1, 1, 2);
//   exactvis::api::VisibleAnswer a = exactvis::api::visible(scene, req);
//
// Conventions: a triangle is visible when some segment from the source to its relative interior has an open
// part free of every other triangle (positive-measure definition); "visible" carries an exact witness
// segment (p on the source, q in the triangle), "hidden" is proved by the exact line-space CSG.
#include "kernel/scene.hpp"
#include "region/cell_visibility.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace exactvis::api {

struct VisibleRequest {
  // The source: a view cell (source.cell) or a convex planar polygon (source.polygon).
  region::VisibilitySource source;
  // Stable scene triangle ids to query (Scene::triangles[i].id), or std::nullopt for every triangle.
  std::optional<std::vector<std::int64_t>> triangle_ids;
  int samples = 48;        // random segments per source/target pair before the exact query (>= 0)
  std::uint64_t seed = 1;  // of the sampling; answers do not depend on it, witnesses may
  int threads = 0;         // 0 = all cores, else 1 .. region::kMaxThreads
  // Called after each finished triangle with (done, total), from worker threads, never concurrently.
  std::function<void(std::int64_t done, std::int64_t total)> progress;
};

struct VisibleTriangle {
  std::int64_t id = 0;                // stable scene triangle id
  bool visible = false;
  std::optional<region::Witness> witness;  // set iff visible: p on the source, q in the triangle (exact)
};

struct VisibleAnswer {
  std::vector<VisibleTriangle> triangles;  // one per queried id, in the order asked (all: id order)
  std::int64_t visible = 0;                // how many are visible
  std::int64_t accepted_by_sampling = 0;   // witnesses found by the sampling step (then re-checked exactly)
  region::VisibilityStats stats;           // summed over the queries
};

// The box X0,Y0,Z0,X1,Y1,Z1 with the given exact corners. Throws std::invalid_argument("--cell: need X0 < X1,
// Y0 < Y1 and Z0 < Z1") unless lo < hi in every coordinate.
region::RationalBox3 cell_box(const Exact& x0, const Exact& y0, const Exact& z0, const Exact& x1, const Exact& y1,
                              const Exact& z1);

// Indices into scene.triangles of the stable ids `ids` (std::nullopt: all triangles, in order). Throws
// std::invalid_argument("--triangles: triangle id N is not in the scene (out of range, or dropped as
// degenerate)"), the message of `exactvis visible --triangles`.
std::vector<std::int64_t> triangle_indices(const Scene& scene, const std::optional<std::vector<std::int64_t>>& ids);

// Input: a scene and a request. Output: VisibleAnswer (exact; independent of threads and seed except for
// which witness is reported). Throws std::invalid_argument with the CLI's message for a bad source, an id
// not in the scene, samples < 0 or a bad thread count. Cost: one exact from-region query per triangle
// (region/cell_visibility.hpp), spread over the threads.
VisibleAnswer visible(const Scene& scene, const VisibleRequest& request);

}  // namespace exactvis::api
