#pragma once
// Job façade: the exact discontinuity mesh of area lights (shadow boundaries on receiver triangles, faces
// classified umbra / penumbra / lit with their exact backprojections and irradiance), what `exactvis shadows`
// computes (docs/cli.md "shadows", definitions in docs/theory.md section 11).
//
//   #include <exactvis/api/shadows.hpp>
//   exactvis::Scene scene = exactvis::load_scene("room.obj");
//   exactvis::shadows::ShadowOptions opt;
//   opt.light = exactvis::light_from_object(scene, "lamp")->triangles;   // events/light_source.hpp
//   opt.receivers = exactvis::api::parse_receivers(scene, "all", opt.light);
//   exactvis::shadows::ShadowResult r = exactvis::api::shadows(scene, opt);
//   nlohmann::ordered_json j = exactvis::api::shadows_json(scene, r, opt.light);   // `shadows --json`
//
// Conventions: lights and receivers are indices into Scene::triangles in ShadowOptions, stable triangle ids
// in the JSON; coordinates in the JSON are exact (a number when exactly a double, else "num/den"), except
// where docs/cli.md says double (areas, fractions, irradiance, EEE ends at irrational parameters).
#include "kernel/scene.hpp"
#include "shadows/shadow_mesh.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace exactvis::api {

// `--receivers all|IDS`: "all" (an empty list: every triangle not in the light) or comma-separated stable
// triangle ids, as indices into Scene::triangles (each once, in the order given). Throws
// std::invalid_argument("--receivers: 'X' is not a triangle id"), ("--receivers: the scene has no triangle
// N"), ("--receivers: triangle N is part of the light") or ("--receivers: expected 'all' or comma-separated
// triangle ids").
std::vector<std::int64_t> parse_receivers(const Scene& scene, const std::string& text, const std::vector<int>& light);

// Input: the scene (with the light's triangles in it) and options (options.light non-empty). Output: the
// discontinuity mesh of every receiver (shadows/shadow_mesh.hpp compute_shadows). Cost: docs/performance.md.
shadows::ShadowResult shadows(const Scene& scene, const shadows::ShadowOptions& options);

// The counts `exactvis shadows` prints and writes in "counts".
struct ShadowCounts {
  std::uint64_t receivers = 0, curves = 0, ev = 0, eee = 0, d0 = 0, faces = 0, umbra = 0, penumbra = 0, lit = 0;
};
ShadowCounts shadow_counts(const shadows::ShadowResult& result);

// The JSON `exactvis shadows --json` prints (docs/cli.md): {"receivers": [{"triangle", "curves", "faces"}],
// "counts", "light": {"triangles": [ids]}, "stats"}; `light` as in ShadowOptions (indices).
nlohmann::ordered_json shadows_json(const Scene& scene, const shadows::ShadowResult& result, const std::vector<int>& light);

}  // namespace exactvis::api
