// `exactvis events SCENE... [--light SPEC] [--kinds EV,EEE] [--json] [--vtp FILE] [--png FILE [--png-size WxH]]
//  [-q]`: EV and EEE visual events
// with occlusion (docs/cli.md "events", definitions in docs/theory.md section 6).
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "api/events.hpp"
#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"
#include "events/light_source.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/result_pictures.hpp"
#include "io/write_event_json.hpp"
#include "io/write_event_surfaces.hpp"
#include "util/format_number.hpp"
#include "util/text_table.hpp"

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
  std::string png;
  std::string png_size = "1280x960";
  std::string kinds = "EV,EEE";
  bool no_split = false;
  bool no_progress = false;
};

int run_events(const EventsOptions& o) {
  const auto [want_ev, want_eee] = exactvis::api::parse_event_kinds(o.kinds);
  const std::array<int, 2> png_size = exactvis::app::parse_png_size(o.png_size);
  exactvis::OutputFiles outputs({o.vtp, o.png});  // checked now, written together at the end
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
  if (!o.vtp.empty())
    outputs.write(o.vtp, [&](const std::string& temp) { return exactvis::write_event_surfaces_vtp(temp, scene, r, eee), true; });
  if (!o.png.empty()) {
    // Two strip pieces per free interval: two exact ray casts per sample, a third of the --vtp cost.
    const exactvis::ScenePicture picture = exactvis::events_picture(
        scene, r, eee, 2,
        "exactvis events: " + exactvis::format_count(static_cast<std::int64_t>(r.events.size())) + " EV, " +
            exactvis::format_count(static_cast<std::int64_t>(eee.events.size())) + " EEE");
    outputs.write(o.png, [&](const std::string& temp) {
      return exactvis::render_scene_png(temp, picture, png_size[0], png_size[1]);
    });
  }
  outputs.commit();
  if (o.json) {
    std::cout << exactvis::app::json_text(exactvis::api::events_json(scene, answer));
    return 0;
  }
  using exactvis::format_count;
  if (want_ev) {
    std::cout << "EV events: " << format_count(static_cast<std::int64_t>(r.events.size())) << "\n"
              << "  pairs examined: " << format_count(r.stats.pairs)
              << ", tangent at the edge: " << format_count(r.stats.tangent_pairs)
              << ", exact occluder tests: " << format_count(r.stats.occluder_tests) << "\n";
    std::vector<std::vector<std::string>> rows;
    for (const auto& ev : r.events) {
      if (rows.size() == exactvis::kSummaryRows) break;
      // Free intervals proper: pieces cut where the end objects change are shown joined.
      std::string intervals;
      std::size_t count = 0;
      for (std::size_t k = 0; k < ev.intervals.size();) {
        std::size_t last = k;
        while (last + 1 < ev.intervals.size() &&
               ev.intervals[last].end1.cause == exactvis::CriticalEnd::Cause::EndObjectChange &&
               ev.intervals[last].t1 == ev.intervals[last + 1].t0)
          ++last;
        intervals += (count++ ? " " : "") + std::string("[") + exactvis::root_number_to_string(ev.intervals[k].t0) +
                     ", " + exactvis::root_number_to_string(ev.intervals[last].t1) + "]";
        k = last + 1;
      }
      rows.push_back({format_count(ev.vertex), "[" + format_count(ev.edge[0]) + ", " + format_count(ev.edge[1]) + "]",
                      intervals});
    }
    exactvis::print_table(std::cout, {"vertex", "edge", "free intervals"}, rows,
                          static_cast<std::int64_t>(r.events.size()));
  } else {
    std::cout << "EV events: not computed (--kinds)\n";
  }
  if (want_eee) {
    std::cout << "EEE events: " << format_count(static_cast<std::int64_t>(eee.events.size())) << "\n"
              << "  outer pairs examined: " << format_count(eee.stats.outer_pairs)
              << ", kept: " << format_count(eee.stats.outer_pairs_kept)
              << ", candidate triples: " << format_count(eee.stats.candidate_triples)
              << ", exact occluder tests: " << format_count(eee.stats.eee.occluder_tests) << "\n";
    std::vector<std::vector<std::string>> rows;
    for (const auto& ev : eee.events) {
      if (rows.size() == exactvis::kSummaryRows) break;
      std::string edges, intervals;
      for (const auto& e : ev.edges)
        edges += (edges.empty() ? "" : " ") + std::string("[") + format_count(e[0]) + ", " + format_count(e[1]) + "]";
      for (const auto& iv : ev.intervals)
        intervals += (intervals.empty() ? "" : " ") + std::string("[") + exactvis::root_number_to_string(iv.t0) + ", " +
                     exactvis::root_number_to_string(iv.t1) + "]";
      rows.push_back({edges, intervals});
    }
    exactvis::print_table(std::cout, {"edges", "free intervals"}, rows, static_cast<std::int64_t>(eee.events.size()));
  } else {
    std::cout << "EEE events: not computed (--kinds)\n";
  }
  for (const std::string& f : {o.vtp, o.png})
    if (!f.empty()) std::cout << "wrote " << f << "\n";
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
  exactvis::app::add_json_flag(*sub, opts->json);
  sub->add_option("--vtp", opts->vtp, "Write the event surfaces (EV wedges, EEE ruled strips) to this .vtp file");
  sub->add_option("--png", opts->png,
                  "Render a picture (VTK offscreen; starts Xvfb when DISPLAY is unset): the event surfaces (EV "
                  "orange, EEE purple) over the scene in grey, a legend");
  sub->add_option("--png-size", opts->png_size, "Size of the --png picture in pixels, WxH")->capture_default_str();
  sub->add_flag("--no-split", opts->no_split,
                "Do not split EV free intervals where the end objects change (faster on large scenes; segment_ends "
                "are then those of each interval's midpoint line only)");
  exactvis::app::add_quiet_or_no_progress_flag(*sub, opts->no_progress);
  return [opts]() { return run_events(*opts); };
});

}  // namespace
