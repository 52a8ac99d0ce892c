// `exactvis shadows SCENE --light SPEC [--receivers all|IDS] [-o mesh.vtp] [--ply F] [--json] [--png F]`:
// the exact discontinuity mesh of area lights on receiver triangles (docs/cli.md "shadows", definitions in
// docs/theory.md section 11).
#include "api/shadows.hpp"
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/render_png.hpp"
#include "io/write_shadow_mesh.hpp"
#include "shadows/shadow_mesh.hpp"

#include <nlohmann/json.hpp>

#include <iostream>
#include <set>
#include <stdexcept>

namespace {

struct ShadowsCliOptions {
  std::string scene;
  std::vector<std::string> lights;
  std::string receivers = "all";
  std::string vtp, ply, png;
  bool json = false;
  bool no_progress = false;
};

int run_shadows(const ShadowsCliOptions& o) {
  exactvis::OutputFiles outputs({o.vtp, o.ply, o.png});
  exactvis::Scene scene = exactvis::load_scenes({o.scene});
  exactvis::shadows::ShadowOptions opt;
  std::set<int> light;
  for (const auto& spec : o.lights) {
    const exactvis::LightSource ls = exactvis::app::parse_light(scene, spec);
    for (int t : ls.triangles)
      if (light.insert(t).second) opt.light.push_back(t);
  }
  opt.receivers = exactvis::api::parse_receivers(scene, o.receivers, opt.light);
  if (opt.receivers.empty() && light.size() == scene.triangles.size())
    throw std::invalid_argument(o.scene + ": no receiver triangles (every triangle is part of the light)");
  opt.progress = exactvis::app::progress_wanted(o.no_progress);
  opt.vertex_irradiance = !o.vtp.empty() || !o.ply.empty() || !o.png.empty();
  const exactvis::shadows::ShadowResult res = exactvis::api::shadows(scene, opt);
  if (!o.vtp.empty())
    outputs.write(o.vtp, [&](const std::string& tmp) { return exactvis::write_shadow_mesh_vtp(tmp, scene, res); });
  if (!o.ply.empty())
    outputs.write(o.ply, [&](const std::string& tmp) { return exactvis::write_shadow_mesh_ply(tmp, scene, res); });
  if (!o.png.empty())
    outputs.write(o.png, [&](const std::string& tmp) {
      return exactvis::render_shadows_png(tmp, scene, res, opt.light);
    });
  outputs.commit();

  if (o.json) {
    std::cout << exactvis::app::json_text(exactvis::api::shadows_json(scene, res, opt.light));
    return 0;
  }
  const exactvis::api::ShadowCounts n = exactvis::api::shadow_counts(res);
  std::cout << "receivers: " << n.receivers << "\n"
            << "curves: " << n.curves << " (EV " << n.ev << ", EEE " << n.eee << ", D0 " << n.d0 << ")\n"
            << "faces: " << n.faces << " (umbra " << n.umbra << ", penumbra " << n.penumbra << ", lit " << n.lit << ")\n"
            << "events: EV " << res.stats.ev_events << ", EEE " << res.stats.eee_events
            << "; backprojections: " << res.stats.backprojections << "\n";
  return 0;
}

const exactvis::app::CommandRegistration registration("shadows", 120, [](CLI::App& parent) {
  auto opts = std::make_shared<ShadowsCliOptions>();
  CLI::App* sub = parent.add_subcommand(
      "shadows", "Exact discontinuity mesh of area lights: shadow curves, umbra/penumbra/lit faces, irradiance");
  sub->add_option("scene", opts->scene, "Scene file (.obj .ply .off .stl .bsp)")->required();
  sub->add_option("--light", opts->lights,
                  "Area light: a scene object name, or a polygon 'x,y,z;x,y,z;x,y,z' appended to the scene "
                  "(repeat for several lights)")
      ->required();
  sub->add_option("--receivers", opts->receivers,
                  "'all' (every triangle not part of a light) or comma-separated scene triangle ids")
      ->capture_default_str();
  sub->add_option("-o,--vtp", opts->vtp, "Write the conforming mesh (.vtp: irradiance per vertex, class per cell)");
  sub->add_option("--ply", opts->ply, "Write the conforming mesh as ASCII .ply");
  sub->add_option("--png", opts->png, "Render the lit scene to a PNG (VTK offscreen; starts Xvfb when DISPLAY is unset)");
  exactvis::app::add_json_flag(*sub, opts->json);
  exactvis::app::add_quiet_or_no_progress_flag(*sub, opts->no_progress);
  return [opts]() { return run_shadows(*opts); };
});

}  // namespace
