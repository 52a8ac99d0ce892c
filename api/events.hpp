#pragma once
// Job façade: EV and EEE visual events with occlusion (the critical line sets where the view of the scene
// changes), what `exactvis events` computes (docs/cli.md "events", definitions in docs/theory.md section 6).
//
//   #include <exactvis/api/events.hpp>
//   exactvis::Scene scene = exactvis::load_scene("scene.obj");
//   exactvis::api::EventsAnswer a = exactvis::api::events(scene, {});
//   nlohmann::json j = exactvis::api::events_json(scene, a);   // the JSON of `exactvis events --json`
//
// Conventions: an event is a generator set (EV: a vertex and an edge; EEE: three edges) with the exact
// free intervals of its one-parameter line family; parameters are exact rationals (EV) or numbers
// a + b*sqrt(c) (EEE), in JSON as numbers, "num/den" or "a+b*sqrt(c)" strings.
#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"
#include "events/light_source.hpp"
#include "kernel/scene.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <utility>

namespace exactvis::api {

struct EventsRequest {
  bool ev = true;   // compute EV events
  bool eee = true;  // compute EEE events (quadratic in the number of edges: docs/performance.md)
  // Only events with a generator on the light (events/light_source.hpp: light_from_object,
  // append_light_polygon; the scene must be the one the light was made for), or std::nullopt for all.
  std::optional<LightSource> light;
  bool split_at_end_objects = true;  // split EV free intervals where the objects at the ends change
  bool progress_bar = false;         // progress bars on stderr
};

struct EventsAnswer {
  EventsRequest request;  // what was computed
  EvResult ev;            // empty unless request.ev
  EeeResult eee;          // empty unless request.eee
};

// The kinds of `--kinds TEXT`: "EV", "EEE" or both comma-separated (any order) as (ev, eee). Throws
// std::invalid_argument("--kinds: unknown event kind 'X' (expected EV, EEE or EV,EEE)") or ("--kinds: no
// event kind given (expected EV, EEE or EV,EEE)").
std::pair<bool, bool> parse_event_kinds(const std::string& text);

// Input: a scene and a request. Output: the events (exact). Cost: docs/performance.md (EV: near-linear in
// practice; EEE: quadratic in the number of edges, restricted by a light).
EventsAnswer events(const Scene& scene, const EventsRequest& request);

// The JSON document `exactvis events --json` prints (docs/cli.md): {"counts", "events", "stats", "kinds",
// ["light"]}, with counts of kinds not computed as null.
nlohmann::json events_json(const Scene& scene, const EventsAnswer& answer);

}  // namespace exactvis::api
