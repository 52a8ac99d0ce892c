#pragma once
// Interval certificate that no line of an EV pencil over a parameter range meets a closed triangle (or any
// point of a box) (docs/theory.md section 9, "Lazy build of one pair", the pencil-range lemma).
//
// The EV family of V and E = (A, B) is L(t) = line(V, P(t)), P(t) = A + t (B - A). With a = A - V, b = B - V,
// n = a x b, the lines of [t0, t1] fill the double wedge W = {V + s d(t) : t in [t0, t1], s real} of the plane
// P through V and E. For a point X let g_t(X) = (X - V) . ((1 - t) (n x a) - t (b x n)) (linear in X; zero on
// the plane through V containing d(t) and n; for X in P it is |n|^2 (alpha + beta) (t(X) - t) up to the
// positive factor, alpha, beta the affine coordinates of X - V in (a, b) and t(X) = beta / (alpha + beta) the
// parameter of the line VX). A point X of P lies in W iff g_t0(X) g_t1(X) <= 0; the rest of P is the two open
// convex sectors R+ = {g_t0 > 0, g_t1 > 0} and R- = {g_t0 < 0, g_t1 < 0}. So a convex set whose section by P
// lies in one of R+, R- (or that misses P) meets no line of the range. A `true` answer is a certificate
// (exact plane sides by orient3d, the rest in interval arithmetic under outward rounding); `false` only means
// "not proved": rounding never decides a result.
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "kernel/vec3.hpp"

#include <CGAL/Interval_nt.h>

#include <array>
#include <vector>

namespace exactvis {

// One side (an object or a triangle) for EvPencilRange::misses_side: its distinct corner points, its
// triangles as indices into them, and its bounding box.
struct PencilSide {
  std::vector<Point3> points;
  std::vector<std::array<int, 3>> triangles;
  Box3 box{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
};

class EvPencilRange {
 public:
  // Input: V, E's endpoints A, B (doubles, not collinear) and enclosures [t0_lo, t0_hi] of t0 and
  // [t1_lo, t1_hi] of t1 (0 <= t0 <= t1 <= 1; the caller rounds its exact ends outwards). Cost: two cross
  // products in interval arithmetic.
  EvPencilRange(const Point3& v, const Point3& a, const Point3& b, double t0_lo, double t0_hi, double t1_lo,
                double t1_hi);

  // True iff proved: no line L(t), t in [t0, t1], meets the closed triangle (p, q, r). Exact orient3d for the
  // triangle's sides of P; its section by P (corners in P, crossings of its edges) must lie certainly in R+
  // or certainly in R-. Always false when the filter is off (set_filter_enabled). Counted as predicate
  // "ev_pencil_misses" (interval layer: proved; exact layer: not proved). Thread-safe. Cost: 3 orient3d, about
  // 40 interval operations.
  bool misses_triangle(const Point3& p, const Point3& q, const Point3& r) const;

  // True iff proved: no line L(t), t in [t0, t1], meets the closed box (its 8 corners certainly on one side
  // of P, or certainly all in R+ or all in R-: the box is convex). Always false when the filter is off.
  // Cost: about 80 interval operations.
  bool misses_box(const Box3& box) const;

  // True iff proved for the whole side: its box is missed, or each of its triangles is (misses_triangle, with
  // each point's plane side and g values computed once). Stops at the first triangle not proved. Cost: at
  // most that of misses_box plus misses_triangle per triangle, usually far less.
  bool misses_side(const PencilSide& side) const;

 private:
  using I = CGAL::Interval_nt<false>;  // under one CGAL::Protect_FPU_rounding per call
  struct PointData;
  PointData point_data(const Point3& p) const;
  bool section_misses(const PointData* c[3]) const;
  Point3 v_, a_, b_;
  std::array<I, 3> n_, w0_, w1_;  // P's normal and the gradients of g_t0, g_t1
};

}  // namespace exactvis
