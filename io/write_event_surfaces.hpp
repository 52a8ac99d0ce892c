#pragma once
// Event surfaces as VTK XML PolyData (.vtp) for ParaView (docs/cli.md "events"): the strips of
// events/event_surfaces.hpp (swept maximal free segments, exact hits, double coordinates for display),
// triangulated, two triangles per pair of consecutive samples.
#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"

#include <string>

namespace exactvis {

// Input: output path, the scene, the EV and EEE results (either may be empty). Output: the file (written
// atomically) with triangles and cell arrays "kind" (0 = EV, 1 = EEE), "event" (index in its result's
// events), "vertex" (EV: V's id, EEE: -1), "edge0", "edge1" (EV: E; EEE: E1), "edge2".."edge5" (EEE: E2, E3;
// EV: -1), "interval" (index in the event), "t0", "t1" (approximate interval ends). Throws OutputError.
void write_event_surfaces_vtp(const std::string& path, const Scene& scene, const EvResult& ev,
                              const EeeResult& eee, int samples_per_interval = 8);

}  // namespace exactvis
