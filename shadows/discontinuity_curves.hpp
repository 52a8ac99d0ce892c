#pragma once
// Discontinuity curves of an area light on receiver triangles (docs/theory.md section 11, "Curves").
//
// From the light-restricted events (events/): an EV free interval of (V, E) with V a light vertex and E not a
// light edge reaches, beyond E, its front object; with E a light edge and V not a light vertex, its back
// object behind V; with neither on the light (blocker-blocker events, shadows/blocker_events.hpp, passed in
// the same EvResult), the object at the end that is not a light triangle. EV intervals are split where these objects change, so the whole open interval ends on one
// receiver R and its curve is the segment from L(t0) to L(t1) intersected with R's plane (exact, rational).
// An EEE interval with a light edge whose generator point is the outermost one on one side reaches the object
// beyond the other side; a blocker-blocker EEE interval (no light edge, shadows/blocker_eee_events.hpp, passed
// in the same EeeResult) a light triangle at one end and the receiver at the other. EEE intervals are split
// exactly where those objects change (shadows/eee_interval_split.hpp); each run of pieces ending on one
// receiver R gives a curve: the conic where the ruled event surface meets R's plane, through the exact points
// of lines at rational parameters (irrational ends: see eee_curve). D0 curves: the segment where a blocker
// triangle not in R's plane
// meets R (a blocker resting on or piercing the receiver).
//
// Orders: D0 contacts 0; EV 1 when an edge at V other than E's lies in the wedge plane (V, E) (the hidden
// area then changes linearly across the surface: a light edge parallel to a blocker edge), else 2; EEE 2.
#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"
#include "kernel/number_types.hpp"
#include "kernel/root_number.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"
#include "shadows/receiver_frame.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace exactvis::shadows {

struct DiscontinuityCurve {
  enum class Kind { EV, EEE };
  Kind kind = Kind::EV;
  int order = 2;                   // 0, 1, 2
  std::int64_t receiver = -1;      // stable triangle id of the receiver
  // Generators. EV: vertex, edge (vertex ids); EEE: edges; D0 (order 0): blocker (stable triangle id).
  int vertex = -1;
  std::array<int, 2> edge{-1, -1};
  std::array<std::array<int, 2>, 3> edges{};
  std::int64_t blocker = -1;
  bool light_vertex = false;       // EV: V is on the light (else E is, unless blocker_blocker)
  bool blocker_blocker = false;    // no generator on the light (EV: neither V nor E; EEE: no edge)
  int light_edge = -1;             // EEE: which generator edge is on the light (-1: blocker-blocker)
  RootNumber t0 = 0, t1 = 0;       // the event family's parameter range of the curve (not for D0)
  // Exact points on the curve in order: EV and D0 the two ends; EEE the points of lines at rational
  // parameters (exactly on the conic), from the first end (or, when that end is irrational, the point of a
  // rational parameter beyond it by less than 2^-40) to the last.
  std::vector<Vec3<Exact>> points;
  // The ends in doubles (exact ends are points.front() and .back() unless `ends_exact` is false).
  std::array<Point3, 2> ends{};
  bool ends_exact = true;
  // EEE: the supporting conic in the receiver's frame, coefficients of u^2, uv, v^2, u, v, 1 (exact).
  std::array<Exact, 6> conic{};
};

struct EeeCurveOptions {
  int samples = 16;  // polyline pieces per EEE curve (display chords; the arrangement's arc is exact)
};

// Input: scene, index, light (indices into Scene::triangles), the light-restricted EV and EEE events of the
// scene (with segment ends), receivers (indices; only curves on them are kept). Output: the curves, grouped
// by receiver stable id, each group ordered EV, EEE as the events are. Exact (see the header comment).
std::map<std::int64_t, std::vector<DiscontinuityCurve>> event_curves(const Scene& scene, const TriangleIndex& index,
                                                                     const std::vector<int>& light,
                                                                     const EvResult& ev, const EeeResult& eee,
                                                                     const std::vector<std::int64_t>& receivers,
                                                                     const EeeCurveOptions& options = {});

// The EEE curve of `event` for parameters [t0, t1] (a run ending on the receiver of `frame`; `inside` a
// rational strictly between t0 and t1) with samples + 1 exact conic points at evenly spaced rational
// parameters. An irrational end is replaced by a rational parameter beyond it by less than 2^-40 (the arc
// overshoots its end by a dangling piece instead of stopping short of the curve it ends on); ends_exact is
// then false. Fields receiver, light_edge, blocker_blocker are left for the caller. std::nullopt if some
// sample line has no point in the plane (not for lines of a free interval).
std::optional<DiscontinuityCurve> eee_curve(const Scene& scene, const EeeEvent& event, const RootNumber& t0,
                                            const RootNumber& t1, const Exact& inside, const ReceiverFrame& frame,
                                            int samples);

// The D0 curves of receiver `receiver` (index): blockers (not light, not in its plane) meeting it in a
// segment of positive length, clipped to the receiver. Exact.
std::vector<DiscontinuityCurve> contact_curves(const Scene& scene, const TriangleIndex& index,
                                               const std::vector<int>& light, std::int64_t receiver);

// The EEE regulus quadric restricted to the frame's plane: Q(u, v) = det(d1 x (X - A1), d2 x (X - A2),
// d3 x (X - A3)) (A_i, d_i = B_i - A_i of the three edges' lines), which vanishes exactly on the points of
// lines meeting all three lines (cubic terms cancel). Coefficients as DiscontinuityCurve::conic.
std::array<Exact, 6> eee_conic(const Scene& scene, const std::array<std::array<int, 2>, 3>& edges,
                               const ReceiverFrame& frame);

}  // namespace exactvis::shadows
