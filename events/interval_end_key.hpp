#pragma once
// The extremal line key of each end of a free interval, from the family and the end's cause
// (docs/theory.md section 6, "Extremal line keys": the rules, cause by cause).
#include "events/critical_interval.hpp"
#include "events/eee_events.hpp"
#include "events/scene_adjacency.hpp"

namespace exactvis {

// The key of the end at parameter t (rational) of an EV family (vertex id V, edge E = [a, b] with a < b).
// EdgeEndpoint / WedgeSide: VV(V, a or b); Occluder Vertex w: VV(V, w); Occluder Edge: VEE(V; E, that edge);
// Occluder Face: VEF(V, E, the occluder); Tangency: VV(V, w) when the line runs through a vertex w of V's
// triangles, else FVE(f, V, E) with f the lowest triangle id among V's triangles whose plane contains the
// line; EndObjectChange: VV / VEE from its feature, VEFF at a crossing of two faces. Exact.
ExtremalLineKey ev_end_key(const Scene& scene, const SceneAdjacency& adj, int vertex, const EdgeIds& edge,
                           const Exact& t, const CriticalEnd& end);

// The key of the end at parameter t of the EEE family of `event` (its edges E1 < E2 < E3; t along E1).
// EdgeEndpoint at vertex v of generator k: VEE(v; the other two edges); Occluder Vertex w: VEE(w; E1, E2);
// Occluder Edge e: EEEE(E1, E2, E3, e) with its branch; Occluder Face T: EEEF(the other two; E_k; T) for the
// first generator k whose point lies in T's plane; Tangency at generator k: FEE(f; the other two) with f the
// lowest triangle id among E_k's triangles whose plane contains the line; Singular at k: EEP(the other two;
// E_k). Exact.
ExtremalLineKey eee_end_key(const Scene& scene, const SceneAdjacency& adj, const EeeEvent& event, const RootNumber& t,
                            const CriticalEnd& end);

}  // namespace exactvis
