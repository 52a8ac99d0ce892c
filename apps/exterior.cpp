// `exactvis exterior MODEL [-o reduced.ply] [--json] [--vtp F]`: exact exterior visibility of a model's
// triangles (docs/theory.md §5.6): the triangles some escaping ray of positive measure leaves, each with its
// witness ray; the others are proved hidden. `--method sampled` runs the sampling pipeline of seed 003
// instead; `--compare sampled` runs both and reports where the sampler is wrong.
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "io/atomic_file.hpp"
#include "io/json_number.hpp"
#include "io/load_scene.hpp"
#include "io/write_mesh.hpp"
#include "io/write_visibility_vtp.hpp"
#include "kernel/float_ray_caster.hpp"
#include "kernel/triangle_index.hpp"
#include "region/exterior_sampled.hpp"
#include "region/exterior_visibility.hpp"
#include "util/progress_bar.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <iostream>
#include <map>

namespace {

using namespace exactvis;

struct ExteriorCliOptions {
  std::vector<std::string> models;
  std::string output;
  bool json = false;
  std::string vtp;
  std::string method = "exact";
  std::string compare;
  int rays = 4096;
  int samples = 48;
  int views = 256;
  int resolution = 256;
  int mc_rays = 64;
  std::string seed = "1";
  int threads = 0;
  bool quiet = false;
};

nlohmann::ordered_json vec_json(const Vec3<Exact>& p) {
  return nlohmann::ordered_json::array({app::exact_json(p.x), app::exact_json(p.y), app::exact_json(p.z)});
}

// The model with only the triangles whose flag is set: same vertex coordinates (only the vertices they
// use, in their original order), same objects, triangle ids renumbered in order.
Scene reduced_scene(const Scene& scene, const std::vector<bool>& keep) {
  Scene out;
  out.objects = scene.objects;
  std::vector<int> new_index(scene.vertices.size(), -1);
  std::vector<bool> used(scene.vertices.size(), false);
  for (std::size_t i = 0; i < scene.triangles.size(); ++i)
    if (keep[i])
      for (const int v : scene.triangles[i].v) used[static_cast<std::size_t>(v)] = true;
  for (std::size_t v = 0; v < scene.vertices.size(); ++v)
    if (used[v]) {
      new_index[v] = static_cast<int>(out.vertices.size());
      out.vertices.push_back(scene.vertices[v]);
    }
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    if (!keep[i]) continue;
    SceneTriangle t = scene.triangles[i];
    for (int& v : t.v) v = new_index[static_cast<std::size_t>(v)];
    t.id = static_cast<std::int64_t>(out.triangles.size());
    out.triangles.push_back(t);
  }
  out.faces_read = static_cast<std::int64_t>(out.triangles.size());
  return out;
}

// A display segment for a witness ray: from q to where the ray leaves the enclosing box (doubles).
WitnessSegment display_segment(std::int64_t id, const region::ExteriorWitness& w, const region::RationalBox3& box) {
  const Point3 q{CGAL::to_double(w.q.x), CGAL::to_double(w.q.y), CGAL::to_double(w.q.z)};
  const double dx = CGAL::to_double(w.d.x), dy = CGAL::to_double(w.d.y), dz = CGAL::to_double(w.d.z);
  double s = std::numeric_limits<double>::infinity();
  const double d[3] = {dx, dy, dz};
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) continue;
    const double bound = CGAL::to_double(d[k] > 0 ? box.hi[k] : box.lo[k]);
    s = std::min(s, (bound - q[k]) / d[k]);
  }
  if (!std::isfinite(s) || s < 0) s = 0;
  return {id, q, Point3{q.x + s * dx, q.y + s * dy, q.z + s * dz}};
}

int run_exterior(const ExteriorCliOptions& o) {
  if (o.method != "exact" && o.method != "sampled")
    throw std::invalid_argument("--method: '" + o.method + "' is not a method (exact or sampled)");
  if (!o.compare.empty() && o.compare != "sampled")
    throw std::invalid_argument("--compare: '" + o.compare + "' is not a method to compare with (sampled)");
  if (!o.compare.empty() && o.method != "exact")
    throw std::invalid_argument("--compare: compares the sampled pipeline with the exact answer (use --method exact)");
  if (o.rays < 0) throw std::invalid_argument("--rays: must be >= 0");
  if (o.samples < 0) throw std::invalid_argument("--samples: must be >= 0");
  if (o.views < 1) throw std::invalid_argument("--views: must be >= 1");
  if (o.resolution < 1 || o.resolution > 8192) throw std::invalid_argument("--resolution: must be in 1 .. 8192");
  if (o.mc_rays < 0) throw std::invalid_argument("--mc-rays: must be >= 0");
  const std::uint64_t seed = app::parse_uint64(o.seed, "--seed");
  const int threads = app::check_thread_count(o.threads, "--threads");

  const Scene scene = load_scenes(o.models);
  OutputFiles outputs({o.output, o.vtp});  // checked before the work; all written or none
  const TriangleIndex index(scene);
  const FloatRayCaster caster(scene);
  const std::size_t n = scene.triangles.size();
  const bool progress = app::progress_wanted(o.quiet);

  // The exact answer (unless only the sampler runs).
  std::optional<region::ExteriorVisibility> exact;
  double exact_seconds = 0;
  if (o.method == "exact") {
    region::ExteriorOptions eo;
    eo.rays = o.rays;
    eo.query.samples = o.samples;
    eo.query.seed = seed;
    eo.seed = seed;
    eo.threads = threads;
    ProgressBar bar("exterior", n, progress);
    eo.on_triangle_done = [&bar] { bar.advance(); };
    const auto t0 = std::chrono::steady_clock::now();
    exact = region::exterior_visibility(scene, index, &caster, eo);
    exact_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  std::optional<region::SampledExterior> sampled;
  if (o.method == "sampled" || !o.compare.empty()) {
    region::SampledExteriorOptions so;
    so.views = o.views;
    so.resolution = o.resolution;
    so.mc_rays = o.mc_rays;
    so.seed = seed;
    so.threads = threads;
    ProgressBar bar("sampled", static_cast<std::uint64_t>(o.views) + 1, progress);
    so.on_view_done = [&bar] { bar.advance(); };
    sampled = region::sampled_exterior_visibility(scene, caster, so);
  }

  std::vector<bool> keep(n, false);
  for (std::size_t i = 0; i < n; ++i) keep[i] = exact ? exact->triangles[i].visible : sampled->kept[i];

  nlohmann::ordered_json j;
  j["kept"] = nlohmann::ordered_json::array();
  j["removed"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < n; ++i) (keep[i] ? j["kept"] : j["removed"]).push_back(scene.triangles[i].id);
  if (exact) {
    j["witnesses"] = nlohmann::ordered_json::object();
    for (std::size_t i = 0; i < n; ++i)
      if (keep[i]) {
        const region::ExteriorWitness& w = *exact->triangles[i].witness;
        j["witnesses"][std::to_string(scene.triangles[i].id)] = {vec_json(w.q), vec_json(w.d)};
      }
  }
  // The sampler's mistakes against the exact answer.
  std::vector<std::size_t> missed, wrongly_kept;
  if (exact && sampled) {
    for (std::size_t i = 0; i < n; ++i) {
      if (keep[i] && !sampled->kept[i]) missed.push_back(i);
      if (!keep[i] && sampled->kept[i]) wrongly_kept.push_back(i);
    }
    nlohmann::ordered_json c;
    c["method"] = "sampled";
    c["sampled_kept"] = sampled->kept_count;
    c["removed_but_visible"] = nlohmann::ordered_json::array();
    for (const std::size_t i : missed) c["removed_but_visible"].push_back(scene.triangles[i].id);
    c["kept_but_hidden"] = nlohmann::ordered_json::array();
    for (const std::size_t i : wrongly_kept) c["kept_but_hidden"].push_back(scene.triangles[i].id);
    c["exact_seconds"] = exact_seconds;
    c["sampled_seconds"] = sampled->seconds;
    c["sampled_rays"] = sampled->rays_cast;
    j["compare"] = c;
  }

  // Outputs: each written whole or not at all.
  if (!o.vtp.empty()) {
    std::vector<int> state(n);
    std::vector<WitnessSegment> segs;
    for (std::size_t i = 0; i < n; ++i) {
      state[i] = keep[i] ? 1 : 0;
      if (exact && keep[i])
        segs.push_back(display_segment(scene.triangles[i].id, *exact->triangles[i].witness, exact->enclosing_box));
    }
    outputs.write(o.vtp, [&](const std::string& temp) {
      write_visibility_vtp(temp, scene, state, segs);
      return true;
    });
  }
  if (!o.output.empty()) {
    const Scene reduced = reduced_scene(scene, keep);
    outputs.write(o.output, [&](const std::string& temp) {
      write_scene_mesh(temp, reduced);
      return true;
    });
  }
  outputs.commit();

  const std::size_t kept = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), true));
  if (o.json) {
    std::cout << exactvis::app::json_text(j);
  } else {
    std::cout << "kept " << kept << "\n" << "removed " << (n - kept) << "\n";
    if (exact && sampled) {
      std::cout << "sampled kept " << sampled->kept_count << " in " << sampled->seconds << " s (exact: "
                << exact_seconds << " s)\n";
      std::cout << "sampled removed but exactly visible " << missed.size() << "\n";
      for (const std::size_t i : missed) {
        const region::ExteriorWitness& w = *exact->triangles[i].witness;
        std::cout << "  triangle " << scene.triangles[i].id << " witness " << vec_json(w.q).dump() << " "
                  << vec_json(w.d).dump() << "\n";
      }
      std::cout << "sampled kept but exactly hidden " << wrongly_kept.size() << "\n";
      for (const std::size_t i : wrongly_kept) std::cout << "  triangle " << scene.triangles[i].id << "\n";
    }
  }
  return 0;
}

const exactvis::app::CommandRegistration registration("exterior", 110, [](CLI::App& parent) {
  auto o = std::make_shared<ExteriorCliOptions>();
  CLI::App* sub = parent.add_subcommand(
      "exterior",
      "Exact exterior visibility of a model: keep the triangles some ray of positive measure leaves towards "
      "infinity (with a witness ray each), remove the others (proved hidden; docs/theory.md section 5.6)");
  sub->add_option("model", o->models, "Model files (.obj .ply .off .stl), loaded as one model")->required();
  exactvis::app::add_output_option(
      *sub, o->output, "Write the reduced mesh (the kept triangles, same vertex coordinates; .ply .obj .off .stl)");
  exactvis::app::add_json_flag(*sub, o->json, "Print {\"kept\", \"removed\", \"witnesses\"} as JSON on stdout");
  sub->add_option("--vtp", o->vtp, "Write the model coloured kept (visible=1) / removed (0) with the witness rays");
  sub->add_option("--method", o->method, "exact (default) or sampled (the sampling pipeline of seed 003)")
      ->capture_default_str();
  sub->add_option("--compare", o->compare,
                  "sampled: also run the sampler and report the triangles it gets wrong against the exact answer");
  sub->add_option("--rays", o->rays, "Exact method: Embree rays per triangle at most that propose witnesses (each re-checked exactly)")
      ->capture_default_str();
  exactvis::app::add_samples_option(*sub, o->samples, "Random segments per pair before each exact from-region query");
  sub->add_option("--views", o->views, "Sampled: view directions on the sphere")->capture_default_str();
  sub->add_option("--resolution", o->resolution, "Sampled: rays per side of each view's image")
      ->capture_default_str();
  sub->add_option("--mc-rays", o->mc_rays, "Sampled: rays from points of each triangle the views missed, over the whole sphere (0: none)")
      ->capture_default_str();
  exactvis::app::add_seed_option(*sub, o->seed, "Seed of the proposals and samplers (exact answers do not depend on it)");
  exactvis::app::add_threads_option(*sub, o->threads);
  exactvis::app::add_quiet_flag(*sub, o->quiet);
  return [o]() { return run_exterior(*o); };
});

}  // namespace
