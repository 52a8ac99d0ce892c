#pragma once
// Blocker-to-blocker EEE events of an area light (docs/theory.md section 11, "Blocker-blocker events").
//
// Three edges E1, E2, E3, none of them a light edge, whose common transversals pass over the light: seen from
// a receiver point X on the event surface the three edges' images are concurrent over a visible light point
// (e.g. a hole between three blockers closes there). On such a line the light point q lies beyond one
// outermost generator point and every generator point lies between q and the other outermost point, so
// each generator meets conv(L ∪ F) (L a light triangle, F the far outer edge). Candidate triples use that
// (exact tests, conservative), the edge-rule prefilter of events/eee_prefilter.hpp and the tetrahedron
// query of eee_enumeration for the middle edge; each triple is then decided by events' eee_event. Which
// parts of the free intervals end on the light at one end and on a receiver at the other is decided later,
// exactly, per piece (shadows/eee_interval_split.hpp, shadows/discontinuity_curves.hpp).
#include "events/eee_enumeration.hpp"
#include "kernel/scene.hpp"
#include "shadows/blocker_events.hpp"

#include <vector>

namespace exactvis::shadows {

// Input: scene, light (indices into Scene::triangles). Output: the EEE events (sorted by edges) of the
// candidate triples with at least one free interval; front_object / back_object of each interval at its
// sample are filled (eee_segment_ends). stats: outer_pairs = ordered (near, far) pairs examined,
// outer_pairs_kept = those passing the filters, candidate_triples, eee. Exact. Cost: per non-light edge F
// an edge-box query of F and the light; per kept pair a tetrahedron query; one eee_event per triple.
EeeResult blocker_eee_events(const Scene& scene, const std::vector<int>& light, const BlockerEvOptions& options = {});

}  // namespace exactvis::shadows
