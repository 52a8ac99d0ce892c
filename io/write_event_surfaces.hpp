#pragma once
// Event surfaces as VTK XML PolyData (.vtp) for ParaView: one polygon per free interval of each EV event,
// the triangle (V, P(t0), P(t1)) swept by the free generator segments (so it stops at V and at E and never
// crosses a blocker). Coordinates are double approximations of the exact ends (display only).
#include "events/ev_events.hpp"

#include <string>

namespace exactvis {

// Input: output path, the scene and the EV result. Output: the file (written atomically), cell arrays
// "event" (index in result.events), "kind" (0 = EV), "vertex", "edge0", "edge1" (scene vertex ids),
// "t0", "t1" (approximate interval ends). Throws OutputError.
void write_event_surfaces_vtp(const std::string& path, const Scene& scene, const EvResult& result);

}  // namespace exactvis
