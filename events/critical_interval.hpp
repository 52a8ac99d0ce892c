#pragma once
// One-parameter sets of critical lines (EV and EEE events, docs/theory.md section 6): the type of their
// free intervals and of the ends of those intervals, shared by both families.
//
// A family is a curve of lines L(t), t in [0, 1] (EV: the lines through V and P(t) on E; EEE: the line
// through P(t) on E1 meeting E2 and E3). A free interval [t0, t1] is a closed parameter interval whose lines
// are valid; its ends are exact algebraic numbers of degree <= 2 (EV: rational; EEE: rational or
// a + b sqrt(D)). Each end is an extremal line: what ends the interval there (its cause) and the line's key
// (events/extremal_line_key.hpp, built by events/interval_end_key.hpp).
#include "events/extremal_line_key.hpp"
#include "events/wedge_blocking.hpp"
#include "kernel/number_types.hpp"
#include "kernel/root_number.hpp"

#include <cstdint>

namespace exactvis {

// Why a free interval ends at a parameter.
struct CriticalEnd {
  enum class Cause {
    EdgeEndpoint,  // the line passes through an endpoint of a generator edge: EV: t = 0 or 1 (E's
                   // endpoints: a VV line); EEE: of E1 (t = 0, 1), E2 or E3 (a VEE line). `vertex` = that
                   // endpoint's id; EEE: `generator` = 0, 1, 2 says which edge
    Occluder,      // an occluder starts/stops blocking: `triangle` (stable id) and its `feature` (EV:
                   // events/wedge_blocking.hpp; EEE: Vertex: VEE line through that occluder vertex, t
                   // rational; Edge: EEEE line meeting that occluder edge's line, t in Q(sqrt D); Face: a
                   // generator point of the line lies in the occluder's plane, t rational)
    Tangency,      // the line stops being tangent at a generator: it lies in the plane of `triangle`
                   // (stable id), a face incident to V (EV) or to generator edge `generator` (EEE)
    Singular,      // EEE only: the line is parallel to E2's (`generator` 1) or E3's (2) line there
    EndObjectChange,  // EV only, not an end of the valid set: a free interval is split here because an
                      // object at an end of the maximal free segment changes (events/ev_interval_split.hpp):
                      // the line passes through `feature` (Vertex or Edge) of `triangle`, or through a
                      // crossing of the faces `triangle` and `other_triangle` (feature Face)
  };
  Cause cause = Cause::EdgeEndpoint;
  int generator = -1;                // EEE: which generator edge (0, 1, 2), -1 when not defined; EV: -1
  int vertex = -1;                   // EdgeEndpoint: the endpoint's vertex id
  std::int64_t triangle = -1;        // stable triangle id, -1 when not defined
  std::int64_t other_triangle = -1;  // EndObjectChange at a crossing of two faces
  OccluderFeature feature;           // Occluder (and EndObjectChange)
  ExtremalLineKey line;              // the key of the end line
};

// A free interval of a family, with the objects at both ends of the maximal free segment of its sample line.
struct CriticalInterval {
  RootNumber t0, t1;     // 0 <= t0 < t1 <= 1, exact (EV: rational)
  CriticalEnd end0, end1;
  // A rational strictly inside (t0, t1) (EV: (t0 + t1) / 2 or the midpoint of the widest split piece).
  Exact sample_t;
  // Stable ids of the first closed scene triangles hit by the open rays extending the sample line beyond its
  // generators, -1 when the ray leaves the scene. The line is oriented along the family's direction (EV:
  // from V towards P(t); EEE: d = Q2 - P); `front_object` is hit beyond the generators in that direction
  // (EV: beyond E), `back_object` in the other (EV: behind V). EV intervals split at end-object changes have
  // them constant on the open interval.
  std::int64_t front_object = -1, back_object = -1;
};

// "edge_endpoint", "occluder", "tangency", "singular", "end_object_change" (the JSON names).
const char* cause_name(CriticalEnd::Cause cause);
// "vertex", "edge", "face", "wedge_side".
const char* feature_name(OccluderFeature::Kind kind);

// The rational value of an EV parameter (t must be rational; EV intervals' ends always are).
Exact rational_parameter(const RootNumber& t);

}  // namespace exactvis
