#pragma once
// Event surfaces: for each free interval of each event, the surface swept by the lines' *maximal free
// segments* (docs/cli.md "events", --vtp). At a parameter t the segment runs from the first scene triangle
// hit behind the generators (or the scene box when the line leaves the scene) through the generators to the
// first triangle hit beyond them (or the box). EV: from behind V to beyond E; EEE: from beyond the one outer
// generator to beyond the other. The surface of an interval is the strip between the segments of
// `samples_per_interval + 1` rational parameters across it (the ends themselves when rational, else
// rationals just inside them). Hits are exact (kernel/ray_first_hit.hpp); the segment ends are returned as
// double approximations (display only) with the triangles hit.
#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace exactvis {

// The maximal free segment of one sample line.
struct SurfaceSample {
  Exact t;                 // the line's parameter in its event (rational, inside the closed interval)
  Point3 back, front;      // its ends (double approximations): behind the generators, beyond them
  std::int64_t back_triangle = -1, front_triangle = -1;  // index into Scene::triangles hit there, -1: box
};

// The surface of one free interval: the strip between consecutive samples (in increasing t).
struct EventSurface {
  enum class Kind { EV, EEE };
  Kind kind = Kind::EV;
  std::size_t event = 0;     // index in its result's events
  std::size_t interval = 0;  // index in the event's intervals
  std::vector<SurfaceSample> samples;  // >= 2 (EEE samples at singular parameters are left out)
};

// Input: the scene and the EV and EEE results computed on it (either may be empty), and the number of
// strip pieces per interval (>= 1; smaller values count as 1). Output: one surface per interval, EV events'
// intervals first, each in result order. Cost: two exact ray casts per sample.
std::vector<EventSurface> event_surfaces(const Scene& scene, const EvResult& ev, const EeeResult& eee,
                                         int samples_per_interval = 8);

}  // namespace exactvis
