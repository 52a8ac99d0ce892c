#include "api/events.hpp"

#include "io/write_event_json.hpp"

#include <sstream>
#include <stdexcept>

namespace exactvis::api {

std::pair<bool, bool> parse_event_kinds(const std::string& text) {
  bool ev = false, eee = false;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item == "EV") ev = true;
    else if (item == "EEE") eee = true;
    else throw std::invalid_argument("--kinds: unknown event kind '" + item + "' (expected EV, EEE or EV,EEE)");
  }
  if (!ev && !eee) throw std::invalid_argument("--kinds: no event kind given (expected EV, EEE or EV,EEE)");
  return {ev, eee};
}

EventsAnswer events(const Scene& scene, const EventsRequest& request) {
  EventsAnswer answer;
  answer.request = request;
  EvOptions ev;
  EeeOptions eee;
  if (request.light) ev.light_triangles = eee.light_triangles = request.light->triangles;
  ev.progress = eee.progress = request.progress_bar;
  ev.split_at_end_objects = request.split_at_end_objects;
  if (request.ev) answer.ev = enumerate_ev_events(scene, ev);
  if (request.eee) answer.eee = enumerate_eee_events(scene, eee);
  return answer;
}

nlohmann::json events_json(const Scene& scene, const EventsAnswer& a) {
  const EventsRequest& r = a.request;
  nlohmann::json j = ev_events_to_json(scene, a.ev);
  j["counts"]["EV"] = r.ev ? nlohmann::json(a.ev.events.size()) : nlohmann::json(nullptr);
  j["counts"]["EEE"] = r.eee ? nlohmann::json(a.eee.events.size()) : nlohmann::json(nullptr);
  j["kinds"] = nlohmann::json::array();
  if (r.ev) j["kinds"].push_back("EV");
  if (r.eee) j["kinds"].push_back("EEE");
  for (auto& e : eee_events_to_json(scene, a.eee)) j["events"].push_back(std::move(e));
  j["stats"]["eee_outer_pairs"] = a.eee.stats.outer_pairs;
  j["stats"]["eee_outer_pairs_kept"] = a.eee.stats.outer_pairs_kept;
  j["stats"]["eee_candidate_triples"] = a.eee.stats.candidate_triples;
  j["stats"]["eee_tangent_triples"] = a.eee.stats.eee.tangent_triples;
  j["stats"]["eee_occluder_tests"] = a.eee.stats.eee.occluder_tests;
  if (r.light) {
    std::vector<std::int64_t> ids;
    for (int ti : r.light->triangles) ids.push_back(scene.triangles[ti].id);
    j["light"] = {{"object", r.light->name}, {"appended", r.light->appended}, {"triangles", ids}};
  }
  return j;
}

}  // namespace exactvis::api
