#pragma once
// JSON form of visual events (docs/cli.md, "events"): exact parameters as JSON numbers when they are exactly
// doubles, else "num/den" strings; approximations alongside as doubles.
#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"

#include <nlohmann/json.hpp>

namespace exactvis {

// Input: the scene the events were computed on, and the EV result.
// Output: {"counts": {"EV": n}, "events": [{"kind": "EV", "vertex": id, "edge": [id, id],
//   "intervals": [[t0, t1], ...], "intervals_approx": [[..]], "ends": [[end, end], ...],
//   "segment_ends": [{"interval", "t0", "t1", "sample_t", "beyond_edge", "behind_vertex"}, ...]}, ...],
//   "stats": {..}} where each end is {"t", "t_approx", "cause", "triangle", "feature", "line": {"through":
//   [V, P(t)]}, "key": KEY} (exact points; KEY: extremal_line_key_to_json). "intervals" are the free
//   intervals proper: intervals split at end-object changes are re-joined, and each piece is one
//   "segment_ends" entry naming its interval.
nlohmann::json ev_events_to_json(const Scene& scene, const EvResult& result);

// One interval end as JSON (also used by the text output).
nlohmann::json event_end_to_json(const Scene& scene, const EvEvent& ev, const RootNumber& t, const CriticalEnd& end);

// An extremal line key (events/extremal_line_key.hpp): {"kind": "VEE", "vertices": [ids], "edges": [[a, b],
// ...], "faces": [triangle ids], "branch": k (EEEE only)}; each list holds the kind's generators in the
// key's order (docs/cli.md).
nlohmann::json extremal_line_key_to_json(const ExtremalLineKey& key);

// An exact EEE parameter: a JSON number / "num/den" string when rational, else the string "a+b*sqrt(c)"
// (root_number_to_string).
nlohmann::json root_number_to_json(const RootNumber& x);

// Input: the scene the events were computed on, and the EEE result.
// Output: the array of EEE events [{"kind": "EEE", "edges": [[a, b], [c, d], [e, f]], "intervals": [[t0, t1],
//   ...], "intervals_approx": [[..]], "ends": [[end, end], ...], "segment_ends": [{"interval", "t0", "t1",
//   "sample_t", "front", "back"}, ...]}, ...] where each end is {"t", "t_approx", "cause", "generator", "vertex", "triangle",
//   "feature", "line", "key"}; "line" is {"through": [P(t), P(t) + d], "on_generators": [P(t), Q2, Q3]} with exact
//   coordinates (numbers, "num/den" or "a+b*sqrt(c)"; Q2/Q3 null where the line is parallel to that edge).
//   t runs along the first listed edge from its first to its second vertex.
nlohmann::json eee_events_to_json(const Scene& scene, const EeeResult& result);

}  // namespace exactvis
