#pragma once
// Crossings of two free EEE arcs inside a face of the great circles, found and certified exactly (docs/theory.md
// 10.11, "EEE x EEE crossings").
//
// Arc a is o f_a(t) (f_a quadratic in t, 10.7) and arc b lies on the cone q_b(d) = d^T Q_b d = 0, so the points
// of a on b's cone are the roots of the quartic Phi(t) = q_b(f_a(t)) (rational coefficients), isolated by Sturm
// sequences (aspect/exact_real_roots). A root strictly inside the parameter range of a sub-arc u of a in face F
// is on b iff the parameter of b's line of that direction, t_b(d) = (d . ((A2 - A1) x u2)) / (d . (u1 x u2))
// (b's edge lines A_i + s u_i), lies inside the range of a sub-arc w of b in F (then the direction of b there
// lies in F, so it is the root's, not its antipode). These are all the points u and w share but their ends, so
// no box certification is needed between different arcs. Each crossing is certified to be one where the proof
// of its aspect holds (a simple root: the arcs cross transversally; on no other EEE cone of F; on no triangle's
// plane; each arc's line there meets no scene edge line other than its own three), else `ok` is false with one
// line. Its parameter on each arc is isolated (on b by the quartic q_a(f_b(s))), and the intervals of the
// crossings on one sub-arc are made disjoint, so they order the crossings along it.
#include "aspect/direction_event_arcs.hpp"
#include "aspect/eee_arc_insertion.hpp"
#include "aspect/exact_real_roots.hpp"
#include "aspect/great_circle_arrangement.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <string>
#include <vector>

namespace exactvis {

struct EeeCrossing {
  int face = -1;
  std::array<int, 2> subarc{-1, -1};      // indices into EeeArcInsertion::subarcs (of two different arcs)
  std::array<ExactPolynomial, 2> poly;    // square-free polynomial in each arc's parameter with the crossing as root
  std::array<IsolatedRoot, 2> t;          // the crossing's parameter on each arc, isolated strictly inside the
                                          // sub-arc's parameter range
  // The sign of the cross product of the two arcs' tangents (increasing parameter; subarc[0]'s first) at the
  // crossing in the face's central chart (eee_face_chart): +1 when subarc[1]'s forward direction is
  // counter-clockwise from subarc[0]'s in that chart.
  int turn = 0;
  std::array<double, 3> direction{};      // a double approximation (reports and tests only)
};

struct EeeCrossings {
  bool ok = true;
  std::string problem;                    // when !ok: one line (the arc's edges and the reason)
  std::vector<EeeCrossing> crossings;
  // Per sub-arc: its crossings in increasing parameter order, as (crossing index, side 0 or 1 of it).
  std::vector<std::vector<std::array<int, 2>>> of_subarc;
};

// Input: the scene, its free arcs, the arrangement and the inserted EEE arcs (ins.ok). Output: every crossing of
// two sub-arcs of different free EEE arcs in one face, or ok = false. Exact. Cost: per pair of sub-arcs of one
// face, one quartic's Sturm isolation; per crossing O(T + E + k) signs at the root (T triangles, E edges, k EEE
// arcs of the face).
EeeCrossings find_eee_crossings(const Scene& scene, const DirectionEventArcs& events, const GreatCircleArrangement& arr,
                                const EeeArcInsertion& ins);

// The left side of an EEE arc at its rational parameter t, for samples off a sub-arc: the direction w (exact)
// such that p + eps w, p = o f(t), lies on the left of the arc (increasing t) in the chart for small eps > 0
// (left: counter-clockwise from the tangent in that chart).
Vec3<Exact> eee_left_normal(const Scene& scene, const DirectionEventArc& arc, const EeeFaceChart& chart, const Exact& t);

// The sign of the cone q (symmetric matrix) on an EEE arc just after its rational parameter s_e, leaving it in
// the direction `sigma` (+1: increasing parameter, -1: decreasing): q(o f(s)) for s strictly between s_e and the
// nearest other root of that polynomial (exact Sturm counts). 0 when q vanishes on the whole arc. For ordering two
// arcs that leave a common point with one tangent (docs/theory.md 10.11, "Faces").
int eee_cone_sign_after(const Scene& scene, const DirectionEventArc& arc, const std::array<std::array<Exact, 3>, 3>& q,
                        const Exact& s_e, int sigma);

}  // namespace exactvis
