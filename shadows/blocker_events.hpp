#pragma once
// Blocker-to-blocker EV events of an area light (docs/theory.md section 11, "Blocker-blocker events").
//
// An EV family (V, E) with V not a vertex of the light and E not an edge of it can still change the
// backprojection's structure: seen from a receiver point X on its surface, V and E appear aligned in front
// of the light. It does so exactly on the lines of the family that are free from the light to the receiver:
// free between V and E (a free interval), with the first triangle beyond one generator a light triangle and
// the first one beyond the other a receiver. This function returns those events: for each (V, E) whose wedge
// plane meets a light triangle (exact orient3d prefilter; with BlockerEvOptions::cull only the pairs that the
// light's tetrahedra admit) the free intervals (events/ev_events.hpp) split where
// the end objects change (events/ev_interval_split.hpp), kept where exactly one end object is a light
// triangle and the other a triangle that is not part of the light.
#include "events/ev_events.hpp"
#include "kernel/scene.hpp"

#include <vector>

namespace exactvis::shadows {

struct BlockerEvOptions {
  bool parallel = true;   // oneTBB over vertices
  bool progress = false;  // progress bar on stderr
  // EV: examine only the pairs (V, E) with E meeting conv(V ∪ L) or V in conv(L ∪ E) for a light triangle L
  // (exact; no other pair has a kept interval, docs/theory.md section 11); off: every vertex with every
  // edge (the events are identical, tests/shadows/test_blocker_events).
  bool cull = true;
};

// Input: scene, light (indices into Scene::triangles). Output: the events (EvEvent, sorted by vertex then
// edge) with only the kept intervals, each with front_object / back_object filled; stats.pairs counts the
// (V, E) pairs passing the prefilter. Exact. Cost: with the cull, one tetrahedron edge query per vertex and
// light triangle and one box query per edge and light triangle (O(V * E * L) orient3d tests without it),
// then one EV event and its interval split per remaining pair.
EvResult blocker_ev_events(const Scene& scene, const std::vector<int>& light, const BlockerEvOptions& options = {});

}  // namespace exactvis::shadows
