#pragma once
// The 3D visibility skeleton (Durand, Drettakis, Puech 1997), exact (docs/theory.md section 9).
//
// Nodes are extremal stabbing lines named by their extremal line key (events/extremal_line_key.hpp: VV,
// VEE, EEEE, the face kinds FVE and FEE, and the degenerate kinds VEF, EEEF, EEP, VEFF); arcs are the free
// intervals of the EV and EEE critical line sets (events/), cut at the nodes: EV intervals where the end
// objects change (events/ev_interval_split.hpp), EEE intervals at the EEEE nodes inside them. An arc's two
// end nodes are the keys of its ends, so the same line reached from different families is one node. Each
// node carries its spanned segment (between its outermost generator points, exact) and the objects at both
// ends of its maximal free segment; nodes and arcs are also stored by the pair of objects at those ends
// (Durand's table).
#include "events/critical_interval.hpp"
#include "events/extremal_line_key.hpp"
#include "kernel/number_types.hpp"
#include "kernel/root_number.hpp"
#include "kernel/scene.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <vector>

namespace exactvis {

struct SkeletonNode {
  ExtremalLineKey key;  // kind and generators: the node's identity
  // The spanned segment: the outermost of the node's generator points (vertices; the points where the
  // line meets its edges; FEE: also the points of the EEE family's three edges), exact in Q or Q(sqrt D).
  // `from` == `to` never happens for a node of a valid arc end.
  Vec3<RootNumber> from, to;
  // Stable triangle ids of the first closed triangles met by the open rays beyond `from` (away from `to`)
  // and beyond `to` (away from `from`); -1 when the ray leaves the scene.
  std::array<std::int64_t, 2> ends{-1, -1};
  // Whether the line is a valid node of its kind (skeleton/node_validity.hpp); invalid ones are the
  // degenerate arc ends, kept in the graph and counted apart.
  bool valid = false;
  std::vector<int> arcs;  // indices into Skeleton3D::arcs ending here, increasing (an arc ending at the
                          // same node at both ends is listed twice)
};

enum class SkeletonArcKind : std::uint8_t { EV, EEE };

// "EV" or "EEE".
const char* arc_kind_name(SkeletonArcKind kind);

struct SkeletonArc {
  SkeletonArcKind kind = SkeletonArcKind::EV;
  int vertex = -1;                  // EV: V's vertex id; EEE: -1
  std::array<EdgeIds, 3> edges{{{-1, -1}, {-1, -1}, {-1, -1}}};  // EV: edges[0] = E; EEE: E1 < E2 < E3
  RootNumber t0, t1;                // the family's parameter (as in events/), t0 < t1
  Exact sample_t;                   // rational, strictly inside (t0, t1)
  std::array<int, 2> nodes{-1, -1};  // indices into Skeleton3D::nodes of the lines at t0 and t1
  // End objects of the sample line's maximal free segment (stable triangle ids, -1 = none): [0] behind the
  // family's first generator (EV: behind V; EEE: the back object), [1] beyond the last (EV: beyond E; EEE:
  // the front object). Constant on the open arc for EV; EEE arcs are cut only at EEEE nodes.
  std::array<std::int64_t, 2> ends{-1, -1};
};

// The nodes and arcs whose maximal free segments end on one pair of objects.
struct SkeletonPairSlice {
  std::vector<int> nodes, arcs;  // indices, increasing
};

struct SkeletonStats {
  std::size_t ev_events = 0, eee_events = 0;
  std::size_t eee_cuts = 0;  // EEE arcs cut at EEEE nodes inside them
  double seconds_events = 0, seconds_nodes = 0;
};

struct Skeleton3D {
  std::vector<SkeletonNode> nodes;  // sorted by key
  std::vector<SkeletonArc> arcs;    // EV arcs (by vertex, edge, t), then EEE arcs (by edges, t)
  // Durand's table: key = the two end objects' indices into Scene::objects (-1 = none), sorted.
  std::map<std::array<int, 2>, SkeletonPairSlice> by_objects;
  SkeletonStats stats;
};

struct SkeletonOptions {
  bool progress = false;  // progress bars on stderr
  bool parallel = true;   // oneTBB (events and node ends)
  // EV pairs to enumerate (EvOptions::accept_pair; unset: all). Arcs of rejected pairs and the nodes reached
  // only through them are then missing: for callers that need only a slice (build_pair_skeleton).
  std::function<bool(int vertex, const std::array<int, 2>& edge)> accept_ev_pair;
  // EV free intervals to keep (EvOptions::accept_interval; unset: all), with the same caveat.
  std::function<bool(int vertex, const std::array<int, 2>& edge, const CriticalInterval& interval)>
      accept_ev_interval;
  // For callers that need only the nodes and arcs whose end objects `wanted_ends` accepts, and the end nodes
  // of those arcs (build_pair_skeleton): when set, the other nodes are not tested for validity (valid =
  // false); nodes whose line `node_line_may_matter` rejects (given the line's point and direction; it must
  // reject only lines that are none of those) get no end objects (-1, -1).
  std::function<bool(const std::array<std::int64_t, 2>& ends)> wanted_ends;
  std::function<bool(const Vec3<RootNumber>& origin, const Vec3<RootNumber>& dir)> node_line_may_matter;
};

// Input: a scene. Output: its full visibility skeleton (see the header comment). Exact. Cost: the EV and
// EEE enumerations of events/ (dominant), one exact ray pair per node and per cut EEE arc.
Skeleton3D build_skeleton_3d(const Scene& scene, const SkeletonOptions& options = {});

// The slice of Durand's table for objects a and b (indices into Scene::objects, -1 = no object), in either
// order; an empty slice when nothing ends there.
SkeletonPairSlice skeleton_pair(const Skeleton3D& skeleton, int object_a, int object_b);

// (Re)builds skeleton.by_objects from the end objects of its nodes and arcs.
void fill_object_table(const Scene& scene, Skeleton3D& skeleton);

// Object index (into Scene::objects) of the triangle with stable id `id`, -1 for id -1.
int object_of_triangle(const Scene& scene, std::int64_t id);

}  // namespace exactvis
