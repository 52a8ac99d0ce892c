#pragma once
// Which lines of an EV wedge a closed triangle blocks (docs/theory.md section 6, "Occlusion").
//
// The wedge of vertex V and edge E = (A, B) is the set of open segments (V, P(t)), P(t) = A + t (B - A),
// t in [0, 1]. A closed occluder triangle T blocks parameter t iff T meets the open segment (V, P(t)).
// The blocked set is an interval of t; this returns its closure (exact rational ends) and, for each end,
// which feature of T defines it.
#include "events/ev_parameter.hpp"
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <optional>
#include <vector>

namespace exactvis {

// The feature of an occluder that defines a blocked-interval end. kind:
//   Vertex: the end line passes through V and occluder vertex `ids[0]` (a VV line through E);
//   Edge:   the end line passes through V, E and occluder edge (ids[0], ids[1]) (a VEE line);
//   Face:   the occluder's face meets E or lies in the wedge plane (degenerate; ids are its 3 vertices);
//   WedgeSide: the end is t = 0 or t = 1 (the occluder crosses the wedge side VA or VB).
struct OccluderFeature {
  enum class Kind { Vertex, Edge, Face, WedgeSide };
  Kind kind = Kind::WedgeSide;
  std::vector<int> ids;  // occluder vertex ids (indices into Scene::vertices)
};

struct BlockedInterval {
  EvParameter lo, hi;           // closure of the blocked parameter set, 0 <= lo <= hi <= 1 (exact)
  OccluderFeature lo_feature, hi_feature;
};

// Blocked interval of wedge (v, a, b) by the closed triangle with corners p[0..2] whose vertex ids are
// ids[0..2]; std::nullopt if T blocks no line of the wedge. Requires v, a, b not collinear. Exact.
std::optional<BlockedInterval> wedge_blocked_interval(const Point3& v, const Point3& a, const Point3& b,
                                                      const std::array<Point3, 3>& p,
                                                      const std::array<int, 3>& ids);

}  // namespace exactvis
