#pragma once
// EV critical line sets with occlusion (docs/theory.md section 6).
//
// For vertex V and edge E = (A, B) of the scene (A, B vertex ids with A < B), the EV set is the lines through
// V and P(t) = A + t (B - A), t in [0, 1]. Line t is *valid* iff it is tangent at E (edge rule) and at V
// (vertex rule), and the open segment (V, P(t)) meets no occluder: a closed triangle not incident to V and
// not having E as an edge. The valid set is a finite union of intervals; reported are the closures of its
// components of positive length ("free intervals"), with exact rational ends (events/critical_interval.hpp)
// and the extremal line key of each end (events/interval_end_key.hpp).
#include "events/critical_interval.hpp"
#include "events/scene_adjacency.hpp"
#include "events/wedge_blocking.hpp"
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace exactvis {

class TriangleIndex;
struct VertexFan;

// An EV event: the free intervals (CriticalInterval, rational ends) of the family of V and E. In each
// interval, the end causes are CriticalEnd's EV causes (EdgeEndpoint with `vertex` = E's endpoint at t = 0
// or 1, Occluder, Tangency with V's triangle `triangle`, EndObjectChange); `generator` is unused (-1). The
// end objects (CriticalInterval::front_object: first triangle hit beyond E, from P(t) away from V;
// back_object: behind V, from V away from E) are those of the sample line L(sample_t), sample_t = (t0 + t1)
// / 2; filled by enumerate_ev_events when EvOptions::segment_ends is set; with
// EvOptions::split_at_end_objects (default) free intervals are split where they change, so they are
// constant on the open interval (t0, t1); without it they may change inside (docs/theory.md section 6).
struct EvEvent {
  int vertex = -1;                 // scene vertex id of V
  std::array<int, 2> edge{};       // scene vertex ids of E, edge[0] < edge[1]; t runs from edge[0] to edge[1]
  std::vector<CriticalInterval> intervals;  // sorted, disjoint except possibly sharing an end
};

struct EvStats {
  std::uint64_t pairs = 0;            // (V, E) pairs examined
  std::uint64_t tangent_pairs = 0;    // pairs passing the edge rule
  std::uint64_t occluder_tests = 0;   // exact wedge/occluder tests after culling
};

struct EvOptions {
  // Light restriction: when non-empty (indices into Scene::triangles), only events with V a vertex of a
  // light triangle or E an edge of a light triangle.
  std::vector<int> light_triangles;
  bool progress = false;   // progress bar on stderr
  bool parallel = true;    // oneTBB over vertices
  bool segment_ends = true;  // find the objects at both ends of each interval's sample line
  bool split_at_end_objects = true;  // with segment_ends: split free intervals where the end objects change
  // When set, only the (vertex, edge) pairs it accepts are enumerated (edge: its two vertex ids, sorted): the
  // result is then exactly the subset of the unrestricted result with accepted pairs (each event's intervals
  // and end objects are computed against the whole scene). A caller's restriction, e.g. the lazy skeleton
  // pair's wedge-plane test (skeleton/skeleton_pair).
  std::function<bool(int vertex, const std::array<int, 2>& edge)> accept_pair;
  // When set, each free interval of an event (before the end-object split) is kept only if it accepts it;
  // events left without intervals are dropped. The result is then exactly the unrestricted result with the
  // pieces of the rejected intervals removed (the split of an interval does not depend on the others). A
  // caller's restriction, e.g. the lazy skeleton pair's pencil-range test (skeleton/skeleton_pair).
  std::function<bool(int vertex, const std::array<int, 2>& edge, const CriticalInterval& interval)> accept_interval;
};

struct EvResult {
  std::vector<EvEvent> events;  // sorted by (vertex, edge); only events with at least one free interval
  EvStats stats;
};

// The per-vertex outputs of a parallel EV enumeration joined in vertex order (so the result does not depend on
// the thread count): events moved out of `per_vertex[v]` for v = 0, 1, ..., stats summed. Both vectors have one
// entry per vertex. Cost: linear in the events.
EvResult join_per_vertex_ev(std::vector<std::vector<EvEvent>>&& per_vertex, const std::vector<EvStats>& stats);

// All EV events of `scene` (see the header comment), exact.
EvResult enumerate_ev_events(const Scene& scene, const EvOptions& options = {});

// The one EV event of vertex `v` and edge `adj.edges[edge]` (std::nullopt if no free interval).
// `fan` must be build_vertex_fan(scene, adj, v). Exposed for tests and the skeleton.
std::optional<EvEvent> ev_event(const Scene& scene, const SceneAdjacency& adj, const TriangleIndex& index,
                                const VertexFan& fan, int edge, EvStats* stats = nullptr);

// The point P(t) on the edge (exact).
Vec3<Exact> ev_edge_point(const Scene& scene, const std::array<int, 2>& edge, const Exact& t);

}  // namespace exactvis
