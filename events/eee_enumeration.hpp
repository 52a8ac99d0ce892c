#pragma once
// Enumeration of all EEE events of a scene (docs/theory.md section 6, "Candidate generators").
//
// Candidate triples are restricted exactly-conservatively (never dropping a triple that has a valid line):
// on a valid EEE line the three meeting points are distinct and ordered, the middle one lies between the two
// others, so the middle edge meets the tetrahedron conv(Ei ∪ Ej) of the two outer edges. Outer pairs must
// pass the edge-rule prefilter both ways (events/eee_prefilter.hpp); middle edges come from an AABB tree
// over the edges queried with that tetrahedron (kernel/edge_index.hpp). Each distinct candidate triple is
// then decided exactly by eee_event (events/eee_events.hpp).
#include "events/eee_events.hpp"
#include "kernel/edge_index.hpp"
#include "events/scene_adjacency.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace exactvis {

struct EeeOptions {
  // Light restriction: when non-empty (indices into Scene::triangles), only triples with at least one edge of
  // a light triangle (as an outer or as the middle edge).
  std::vector<int> light_triangles;
  bool progress = false;  // progress bars on stderr
  bool parallel = true;   // oneTBB over outer edges and over candidate triples
  bool segment_ends = true;  // find the objects at both ends of each interval's sample line (eee_segment_ends)
};

struct EeeEnumerationStats {
  std::uint64_t outer_pairs = 0;        // (outer, outer) or (outer, light middle) edge pairs examined
  std::uint64_t outer_pairs_kept = 0;   // pairs passing the shared-vertex, skewness and edge-rule prefilters
  std::uint64_t candidate_triples = 0;  // distinct triples handed to eee_event
  EeeStats eee;                         // sum of eee_event's statistics over the candidate triples
};

struct EeeResult {
  std::vector<EeeEvent> events;  // sorted by edges (vertex ids); only triples with at least one free interval
  EeeEnumerationStats stats;
};

// All EEE events of `scene` (restricted to the light when options.light_triangles is non-empty). Exact.
EeeResult enumerate_eee_events(const Scene& scene, const EeeOptions& options = {});

// The candidate triples (indices into adj.edges, each sorted increasingly; the list sorted and without
// duplicates) that enumerate_eee_events hands to eee_event. Exposed for tests. `stats` may be null.
std::vector<std::array<int, 3>> eee_candidate_triples(const Scene& scene, const SceneAdjacency& adj,
                                                      const EdgeIndex& edges, const EeeOptions& options,
                                                      EeeEnumerationStats* stats = nullptr);

// The events of given candidate triples (indices into adj.edges): eee_event on each, against the triangles
// of `occluders` (whose index must be over `scene`), in parallel when `parallel` (tasks of `grain` triples),
// with a progress bar `label` on stderr when `progress`. `on_found` (may be empty) runs on the worker thread
// for each event found (e.g. eee_segment_ends). Output: the events sorted by edges (vertex ids) and, in
// stats.eee, eee_event's statistics summed over the triples (the other stats fields stay zero). Shared by
// enumerate_eee_events and the shadows' blocker-blocker EEE pass. Cost: one eee_event per triple.
EeeResult eee_events_of_triples(const Scene& scene, const SceneAdjacency& adj, const TriangleIndex& occluders,
                                const std::vector<std::array<int, 3>>& triples, bool parallel, std::size_t grain,
                                const std::string& label, bool progress,
                                const std::function<void(EeeEvent&)>& on_found = {});

}  // namespace exactvis
