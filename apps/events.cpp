// `exactvis events SCENE... [--light SPEC] [--json] [--vtp FILE]`: EV visual events with occlusion
// (docs/cli.md "events", definitions in docs/theory.md section 6).
#include "apps/command_registry.hpp"
#include "events/ev_events.hpp"
#include "events/light_source.hpp"
#include "io/load_scene.hpp"
#include "io/write_event_json.hpp"
#include "io/write_event_surfaces.hpp"

#include <nlohmann/json.hpp>

#include <iostream>
#include <unistd.h>

namespace {

struct EventsOptions {
  std::vector<std::string> scenes;
  std::string light;
  bool json = false;
  std::string vtp;
  bool no_progress = false;
};

int run_events(const EventsOptions& o) {
  exactvis::Scene scene = exactvis::load_scenes(o.scenes);
  exactvis::EvOptions opt;
  exactvis::LightSource light;
  if (!o.light.empty()) {
    light = exactvis::select_light(scene, o.light);
    opt.light_triangles = light.triangles;
  }
  opt.progress = !o.no_progress && isatty(STDERR_FILENO);
  const exactvis::EvResult r = exactvis::enumerate_ev_events(scene, opt);
  if (!o.vtp.empty()) exactvis::write_event_surfaces_vtp(o.vtp, scene, r);
  if (o.json) {
    nlohmann::json j = exactvis::ev_events_to_json(scene, r);
    j["counts"]["EEE"] = nullptr;  // not computed yet: see docs/cli.md
    j["not_computed"] = {"EEE"};
    if (!o.light.empty())
      j["light"] = {{"object", light.name}, {"appended", light.appended}, {"triangles", [&] {
                       std::vector<std::int64_t> ids;
                       for (int ti : light.triangles) ids.push_back(scene.triangles[ti].id);
                       return ids;
                     }()}};
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << "EV events: " << r.events.size() << "\n"
            << "EEE events: not computed (see docs/cli.md)\n"
            << "pairs examined: " << r.stats.pairs << ", tangent at the edge: " << r.stats.tangent_pairs
            << ", exact occluder tests: " << r.stats.occluder_tests << "\n";
  for (const auto& ev : r.events) {
    std::cout << "EV vertex " << ev.vertex << " edge [" << ev.edge[0] << ", " << ev.edge[1] << "]:";
    for (const auto& iv : ev.intervals)
      std::cout << " [" << exactvis::to_rational_string(iv.t0) << ", " << exactvis::to_rational_string(iv.t1) << "]";
    std::cout << "\n";
  }
  return 0;
}

const exactvis::app::CommandRegistration registration("events", 110, [](CLI::App& parent) {
  auto opts = std::make_shared<EventsOptions>();
  CLI::App* sub = parent.add_subcommand("events", "EV visual events (critical line sets) with occlusion");
  sub->add_option("scene", opts->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene")->required();
  sub->add_option("--light", opts->light,
                  "Only events with a generator on the light: a scene object name, or a polygon "
                  "'x,y,z;x,y,z;x,y,z' appended to the scene");
  sub->add_flag("--json", opts->json, "Machine-readable JSON on stdout");
  sub->add_option("--vtp", opts->vtp, "Write the event surfaces (EV wedges) to this .vtp file");
  sub->add_flag("--no-progress", opts->no_progress, "No progress bar on stderr");
  return [opts]() { return run_events(*opts); };
});

}  // namespace
