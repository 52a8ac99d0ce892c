#pragma once
// Event surfaces as VTK XML PolyData (.vtp) for ParaView (docs/cli.md "events").
//
// For each free interval of each event, the surface swept by the lines' *maximal free segments*: at a
// parameter t the segment runs from the first scene triangle hit behind the generators (or the scene box when
// the line leaves the scene) through the generators to the first triangle hit beyond them (or the box).
// EV: from behind V to beyond E; EEE: from beyond the one outer generator to beyond the other. The surface is
// a triangulated strip between these segments at `samples_per_interval + 1` rational parameters across the
// interval (the ends themselves when rational, else rationals just inside them). Hits are exact
// (events/ray_first_hit.hpp); coordinates are double approximations (display only).
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
