#pragma once
// Interval certificate that no line of an EEE family over a parameter range meets an occluder triangle
// (docs/theory.md section 6, "Occlusion"; the second floating-point filter of eee_event's occluder loop,
// after EeeOccluderFilter).
//
// L(t) has Plücker coordinates (d(t), m(t)), each coordinate a polynomial of degree <= 2 in t with exact
// coefficients. For a closed triangle T = (c0, c1, c2) with edge lines e_k = line_through(c_k, c_k+1), the
// side operator q_k(t) = side(L(t), e_k) is a quadratic in t; a line meeting the closed triangle has side
// signs that are not strictly mixed (a transversal line passes all three edges on one side or through the
// boundary; a line in T's plane, or meeting the common line of a zero-area T, has all sides zero). So if, for
// every t of the range, some q_i(t) > 0 and some q_j(t) < 0, no line of the range meets T and T blocks
// nothing there. The filter proves this with interval arithmetic: the coefficients of each q_k are enclosed
// (outward rounding, from the exact coefficients and the double corners), the range is cut into 8 pieces
// and each q_k is evaluated over each piece by Horner's rule in interval arithmetic. A `false` answer only
// means "not proved": the caller runs the exact occluder analysis, so rounding never decides.
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"

#include <array>

namespace exactvis {

class EeeLineMissFilter {
 public:
  // Input: the exact coefficients of L(t)'s Plücker coordinates, d[axis][degree] and m[axis][degree]
  // (coordinate axis of d(t) = sum over degree of d[axis][degree] t^degree). Cost: 36 interval enclosures.
  EeeLineMissFilter(const std::array<std::array<Exact, 3>, 3>& d, const std::array<std::array<Exact, 3>, 3>& m);

  // True iff proved: for every t in [t_lo, t_hi] (doubles, t_lo <= t_hi; the caller rounds its exact range
  // outwards), the line L(t) misses the closed triangle (a, b, c). Counted as predicate "eee_line_misses"
  // (interval layer: proved; exact layer: not proved, the exact analysis follows). Always false when the
  // filter is off (set_filter_enabled). Thread-safe for concurrent const calls. Cost: about 250 interval
  // operations.
  bool misses(const Point3& a, const Point3& b, const Point3& c, double t_lo, double t_hi) const;

 private:
  // The interval certificate itself (rounding mode switched once inside).
  bool proved(const Point3& a, const Point3& b, const Point3& c, double t_lo, double t_hi) const;
  std::array<std::array<std::array<double, 2>, 3>, 3> d_{}, m_{};  // [axis][degree] = [lo, hi]
};

}  // namespace exactvis
