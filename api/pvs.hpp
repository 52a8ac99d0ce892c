#pragma once
// Job façade: exact potentially visible sets (PVS) of view cells, what `exactvis pvs` computes (docs/cli.md
// "pvs", definitions in docs/theory.md section 5): for every cell, the triangles visible from the closed
// cell, each with an exactly checked witness segment, and the objects they belong to.
//
//   #include <exactvis/api/pvs.hpp>
//   exactvis::Scene scene = exactvis::load_scene("town.obj");
//   exactvis::api::PvsRequest req;
//   req.cells = exactvis::api::grid_view_cells(scene, {4, 4, 1});   // or explicit boxes
//   exactvis::api::PvsAnswer a = exactvis::api::pvs(scene, req);
//   nlohmann::ordered_json j = exactvis::api::pvs_json(scene, a, "town.obj");   // `pvs --json`
//
// Conventions: a cell is a closed box with exact corners (lo < hi in every coordinate); a triangle is in the
// cell's PVS when some segment from the cell to its relative interior has an open part free of every other
// triangle (positive-measure definition; touching blocks). Answers are exact and do not depend on threads,
// seed, samples or rays (method exact); witnesses depend only on seed, rays and samples.
#include "kernel/scene.hpp"
#include "region/cell_pvs.hpp"
#include "region/cell_visibility.hpp"
#include "region/pvs_method.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace exactvis::api {

struct PvsRequest {
  std::vector<region::RationalBox3> cells;          // the view cells, numbered in this order
  region::PvsMethod method = region::PvsMethod::exact;
  // The method's options (region/cell_pvs.hpp): query.samples and query.seed (as --samples, --seed), rays
  // (exact: Embree proposals per triangle, --rays), cell_rays (sampled: rays per cell), threads, hierarchy.
  region::PvsOptions options;
  // Called as progress(decided, total) while the cells run: total = cells x scene triangles, decided the
  // triangles decided so far (finished cells count whole), increasing from call to call; from worker
  // threads, never concurrently.
  std::function<void(std::int64_t decided, std::int64_t total)> progress;
};

struct PvsAnswer {
  std::vector<region::CellPvs> cells;  // one per requested cell, in request order
};

// The cells of `exactvis pvs --grid NX,NY,NZ [--box B]`: n[0] x n[1] x n[2] cells (x fastest) dividing `box`,
// or the scene's bounding box when `box` is empty. Throws std::invalid_argument("--grid: the scene is empty;
// give --box") or ("--grid: the scene's bounding box is flat in x; give --box") for a scene box that cannot
// be divided, and region::grid_cells' errors for counts below 1.
std::vector<region::RationalBox3> grid_view_cells(const Scene& scene, const std::array<long, 3>& n,
                                                  const std::optional<region::RationalBox3>& box = std::nullopt);

// Input: a scene and a request (cells checked: std::invalid_argument for an empty or inverted cell, a bad
// thread count or negative samples). Output: each cell's PVS (region::compute_cell_pvs, the command line's
// computation). Cost: that of the method per cell (docs/performance.md "pvs").
PvsAnswer pvs(const Scene& scene, const PvsRequest& request);

// The document `exactvis pvs --json` writes (docs/cli.md): {"scene": scene_label, "triangles", "cells":
// [CELL...], "stats"}, CELL with "witnesses" unless witnesses = false (--no-witnesses). Deterministic.
nlohmann::ordered_json pvs_json(const Scene& scene, const PvsAnswer& answer, const nlohmann::ordered_json& scene_label,
                                bool witnesses = true);

}  // namespace exactvis::api
