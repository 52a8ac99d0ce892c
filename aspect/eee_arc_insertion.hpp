#pragma once
// The free EEE arcs of an orthographic aspect graph (aspect/direction_event_arcs: conic arcs on the viewing
// sphere, docs/theory.md §10.7) placed in the exact arrangement of great circles of the EV arcs
// (aspect/great_circle_arrangement), exactly (docs/theory.md §10.11).
//
// Each EEE arc {o f(t) : t in [t0, t1]} is cut at its crossings with the circles (n . f(t) = 0: quadratic in t,
// roots exact in Q(sqrt D)); every open piece between consecutive cuts (a *sub-arc*) lies in one face of the
// arrangement (found from the sign vector of its rational sample). Every cut is a *point*: a vertex of the
// arrangement, a point inside one of its arcs (with its position lambda along the arc, exact), or an end of
// the arc inside a face. Within a face, sub-arcs of one arc must be pairwise disjoint (certified by exact
// rational boxes in the face's central chart, refined by bisection of the parameter); sub-arcs of two arcs meet
// only at common cut points and at crossings inside the face, found exactly by aspect/eee_crossings; the face's
// components follow from the plane graph they form (aspect/eee_face_split). An arc touching a circle (a double
// root, rational) is cut there like at a crossing. The subset handled (else `ok` is false with one line in
// `problem`): arc ends at rational parameters, no EEE arc lying on a circle, two EEE arcs sharing only rational
// cut points on the circles.
#include "aspect/direction_event_arcs.hpp"
#include "aspect/great_circle_arrangement.hpp"
#include "kernel/number_types.hpp"
#include "kernel/root_number.hpp"
#include "kernel/scene.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace exactvis {

// A cut point of a free EEE arc.
struct EeeArcPoint {
  int arc = -1;                 // index into DirectionEventArcs::arcs
  RootNumber t;                 // its parameter
  bool rational = false;        // t rational: then `direction` is exact
  Vec3<Exact> direction;        // o f(t) scaled so that its largest |component| is 1 (when rational)
  int circle = -1;              // a circle through it; -1 for an arc end inside a face
  int gc_vertex = -1;           // a vertex of the arrangement (on two or more circles), or
  int gc_arc = -1;              // the arrangement arc holding it strictly inside,
  RootNumber lambda;            //   at the direction (1 - lambda) from + lambda to, 0 < lambda < 1
  bool arc_end = false;         // t = t0 or t = t1
};

// An open piece of a free EEE arc between two consecutive cut points, inside one face.
struct EeeSubArc {
  int arc = -1;
  int face = -1;                // arrangement face holding it
  int first = -1, second = -1;  // its end points (indices into EeeArcInsertion::points), along increasing t
  Exact t;                      // a rational parameter strictly between its ends' parameters
  Vec3<Exact> sample;           // o f(t), scaled so that its largest |component| is 1
};

struct EeeArcInsertion {
  bool ok = true;
  std::string problem;          // when !ok: one line
  std::vector<EeeArcPoint> points;
  std::vector<EeeSubArc> subarcs;
  std::vector<std::vector<int>> subarcs_of_face;  // per arrangement face
  // Per EEE arc (index into DirectionEventArcs::arcs; empty for EV arcs): the symmetric matrix of its cone
  // q(d) = d^T Q d (zero exactly on the directions of lines meeting its three edge lines).
  std::vector<std::array<std::array<Exact, 3>, 3>> cone;
};

// Input: the scene, its free arcs, the arrangement of the circles `normals` (holding every free EV arc).
// Output: the cut points and sub-arcs of every free EEE arc, or ok = false (the subset above). Exact. Cost:
// O(m) quadratic root computations per EEE arc for m circles, O(F) to find each sub-arc's face by its sign
// vector (O(m F) once), and per face a box test per pair of its sub-arcs (with bisection where they are close).
// Arcs with `on_circle[i]` set (EEE arcs lying on a circle of the partition, handled as circle arcs) are skipped.
EeeArcInsertion insert_eee_arcs(const Scene& scene, const DirectionEventArcs& events,
                                const GreatCircleArrangement& arr, const std::vector<Vec3<Exact>>& normals,
                                const std::vector<char>& on_circle);

// The central chart of a face: d -> (d . e1, d . e2) / (d . s), s the face's sample (every direction of the
// face's closure has d . s > 0), e1 = s x axis, e2 = s x e1 (exact).
struct EeeFaceChart {
  Vec3<Exact> s, e1, e2;
};
EeeFaceChart eee_face_chart(const GreatCircleArrangement& arr, int face);
std::array<Exact, 2> chart_point(const EeeFaceChart& chart, const Vec3<Exact>& d);

// The direction (in the chart) in which an EEE arc leaves its cut point at the rational parameter t_end into
// the sub-arc on the side `end` (0: the sub-arc after it, t increasing; 1: the one before it). Exact.
std::array<Exact, 2> eee_end_tangent(const Scene& scene, const DirectionEventArc& arc, const EeeFaceChart& chart,
                                     const Exact& t_end, int end);

// A rational direction strictly inside face `face` of the arrangement, in the component of the face minus
// its sub-arcs whose closure holds the rational direction `p` (on the face's boundary, on no EEE cone of the
// face's sub-arcs): p moved towards the face's sample by an exact power of two small enough that the segment
// meets none of those cones, scaled so that its largest |component| is 1. None if p lies on one of those cones.
std::optional<Vec3<Exact>> sample_off_eee_arcs(const EeeArcInsertion& ins, const GreatCircleArrangement& arr,
                                               int face, const Vec3<Exact>& p);

}  // namespace exactvis
