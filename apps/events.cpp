// `exactvis events SCENE... [--light SPEC] [--kinds EV,EEE] [--json] [--vtp FILE]`: EV and EEE visual events
// with occlusion (docs/cli.md "events", definitions in docs/theory.md section 6).
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "api/events.hpp"
#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"
#include "events/light_source.hpp"
#include "io/load_scene.hpp"
#include "io/write_event_json.hpp"
#include "io/write_event_surfaces.hpp"

#include <nlohmann/json.hpp>

#include <iostream>
#include <sstream>
#include <stdexcept>

namespace {

struct EventsOptions {
  std::vector<std::string> scenes;
  std::string light;
  bool json = false;
  std::string vtp;
  std::string kinds = "EV,EEE";
  bool no_split = false;
  bool no_progress = false;
};

int run_events(const EventsOptions& o) {
  const auto [want_ev, want_eee] = exactvis::api::parse_event_kinds(o.kinds);
  exactvis::Scene scene = exactvis::load_scenes(o.scenes);
  exactvis::api::EventsRequest request;  // the job itself is api/events.hpp (also the Python module's)
  request.ev = want_ev;
  request.eee = want_eee;
  if (!o.light.empty()) request.light = exactvis::app::parse_light(scene, o.light);
  request.progress_bar = exactvis::app::progress_wanted(o.no_progress);
  request.split_at_end_objects = !o.no_split;
  const exactvis::api::EventsAnswer answer = exactvis::api::events(scene, request);
  const exactvis::EvResult& r = answer.ev;
  const exactvis::EeeResult& eee = answer.eee;
  if (!o.vtp.empty()) exactvis::write_event_surfaces_vtp(o.vtp, scene, r, eee);
  if (o.json) {
    std::cout << exactvis::api::events_json(scene, answer).dump(2) << "\n";
    return 0;
  }
  if (want_ev) {
    std::cout << "EV events: " << r.events.size() << "\n"
              << "  pairs examined: " << r.stats.pairs << ", tangent at the edge: " << r.stats.tangent_pairs
              << ", exact occluder tests: " << r.stats.occluder_tests << "\n";
  } else {
    std::cout << "EV events: not computed (--kinds)\n";
  }
  if (want_eee) {
    std::cout << "EEE events: " << eee.events.size() << "\n"
              << "  outer pairs examined: " << eee.stats.outer_pairs << ", kept: " << eee.stats.outer_pairs_kept
              << ", candidate triples: " << eee.stats.candidate_triples
              << ", exact occluder tests: " << eee.stats.eee.occluder_tests << "\n";
  } else {
    std::cout << "EEE events: not computed (--kinds)\n";
  }
  for (const auto& ev : r.events) {
    std::cout << "EV vertex " << ev.vertex << " edge [" << ev.edge[0] << ", " << ev.edge[1] << "]:";
    // Free intervals proper: pieces cut where the end objects change are printed joined, with the cuts.
    for (std::size_t k = 0; k < ev.intervals.size();) {
      std::size_t last = k;
      while (last + 1 < ev.intervals.size() &&
             ev.intervals[last].end1.cause == exactvis::CriticalEnd::Cause::EndObjectChange &&
             ev.intervals[last].t1 == ev.intervals[last + 1].t0)
        ++last;
      std::cout << " [" << exactvis::root_number_to_string(ev.intervals[k].t0) << ", "
                << exactvis::root_number_to_string(ev.intervals[last].t1) << "]";
      if (last > k) {
        std::cout << " (end objects change at";
        for (std::size_t c = k; c < last; ++c) std::cout << " " << exactvis::root_number_to_string(ev.intervals[c].t1);
        std::cout << ")";
      }
      k = last + 1;
    }
    std::cout << "\n";
  }
  for (const auto& ev : eee.events) {
    std::cout << "EEE edges";
    for (const auto& e : ev.edges) std::cout << " [" << e[0] << ", " << e[1] << "]";
    std::cout << ":";
    for (const auto& iv : ev.intervals)
      std::cout << " [" << exactvis::root_number_to_string(iv.t0) << ", " << exactvis::root_number_to_string(iv.t1)
                << "]";
    std::cout << "\n";
  }
  return 0;
}

const exactvis::app::CommandRegistration registration("events", 110, [](CLI::App& parent) {
  auto opts = std::make_shared<EventsOptions>();
  CLI::App* sub = parent.add_subcommand("events", "EV and EEE visual events (critical line sets) with occlusion");
  sub->add_option("scene", opts->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene")->required();
  sub->add_option("--light", opts->light,
                  "Only events with a generator on the light: a scene object name, or a polygon "
                  "'x,y,z;x,y,z;x,y,z' appended to the scene");
  sub->add_option("--kinds", opts->kinds,
                  "Event kinds to compute: EV, EEE or EV,EEE (default). Full EEE enumeration is quadratic in the "
                  "number of edges (docs/performance.md): use --kinds EV or --light on large scenes")
      ->capture_default_str();
  sub->add_flag("--json", opts->json, "Machine-readable JSON on stdout");
  sub->add_option("--vtp", opts->vtp, "Write the event surfaces (EV wedges, EEE ruled strips) to this .vtp file");
  sub->add_flag("--no-split", opts->no_split,
                "Do not split EV free intervals where the end objects change (faster on large scenes; segment_ends "
                "are then those of each interval's midpoint line only)");
  sub->add_flag("-q,--quiet,--no-progress", opts->no_progress, "No progress bar on stderr");
  return [opts]() { return run_events(*opts); };
});

}  // namespace
