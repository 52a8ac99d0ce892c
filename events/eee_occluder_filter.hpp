#pragma once
// Interval certificates that an occluder cannot meet any generator segment of an EEE family (docs/theory.md
// section 6, "Occlusion"; the floating-point filter of eee_event's occluder loop).
//
// eee_event encloses every generator segment of a triple in conv(H), H six exact points (the swept parts of
// the three edges). An occluder triangle T disjoint from conv(H) blocks nothing and is skipped. This class
// proves such disjointness with interval arithmetic only (no rationals): double planes are *proposed* from
// the rounded points of H (the facet planes of their hull), and each plane's offset is then taken as a
// certified upper bound of n.h over the exact points h of H (outward-rounded intervals), so conv(H) lies in
// the half-space n.x <= c by construction; T is separated when all its corners are certified strictly
// beyond one such plane, or when all of H is certified strictly on one side of T's plane. A `false` answer
// only means "not proved": the caller then runs the exact occluder analysis, so rounding never decides.
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <vector>

namespace exactvis {

class EeeOccluderFilter {
 public:
  // Input: the six exact points H. Cost: 20 double orientation proposals, 6 interval dot products per kept
  // plane.
  explicit EeeOccluderFilter(const std::array<Vec3<Exact>, 6>& hull_points);

  // True iff the closed triangle (a, b, c) is proved disjoint from conv(H) (see the header comment).
  // Counted as predicate "eee_occluder_separated" (interval layer: proved; exact layer: not proved, the
  // exact occluder analysis follows). Always false when the filter is off (set_filter_enabled). Thread-safe for concurrent const calls.
  bool separated(const Point3& a, const Point3& b, const Point3& c) const;

 private:
  struct Plane {
    double n[3];
    double c;  // certified: n.h <= c for every exact point h of H
  };
  std::vector<Plane> planes_;
  std::array<std::array<double, 6>, 6> box_{};  // per point of H: [lo x, lo y, lo z, hi x, hi y, hi z]
};

}  // namespace exactvis
