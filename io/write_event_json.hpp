#pragma once
// JSON form of visual events (docs/cli.md, "events"): exact parameters as JSON numbers when they are exactly
// doubles, else "num/den" strings; approximations alongside as doubles.
#include "events/ev_events.hpp"

#include <nlohmann/json.hpp>

namespace exactvis {

// Input: the scene the events were computed on, and the EV result.
// Output: {"counts": {"EV": n}, "events": [{"kind": "EV", "vertex": id, "edge": [id, id],
//   "intervals": [[t0, t1], ...], "intervals_approx": [[..]], "ends": [[end, end], ...],
//   "segment_ends": [{"sample_t", "beyond_edge", "behind_vertex"}, ...]}, ...], "stats": {..}}
// where each end is {"t", "cause", "triangle", "feature", "line": {"through": [V, P(t)]}} (exact points).
nlohmann::json ev_events_to_json(const Scene& scene, const EvResult& result);

// One interval end as JSON (also used by the text output).
nlohmann::json event_end_to_json(const Scene& scene, const EvEvent& ev, const Exact& t, const EventEnd& end);

}  // namespace exactvis
