#pragma once
// Hand-written semi-static filters (layer 1 of filtered_sign) of the hottest predicates on double inputs:
// the determinant of the coordinate differences in plain double arithmetic (default rounding mode) and an
// error bound from the largest difference per axis (column) times a proven constant, in the style of
// Shewchuk's and CGAL's static filters. Each returns the exact sign when it can prove it, nullopt otherwise
// (then the interval layer runs). Outside the fast path, two cold certificates: integer differences small
// enough for every operation to be exact, and columns rescaled by powers of two (the sign of a
// determinant does not change when a column is multiplied by 2^e) for magnitudes outside the safe range.
// Constants, ranges and proofs: docs/theory.md section 1, "Semi-static layer".
// Same preconditions as BoundedDouble (round-to-nearest, gradual underflow, no -ffast-math).
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace exactvis {

namespace semi_static {
// orient2d: |error| <= kOrient2dBound * mx * my when mx, my (largest |x|, |y| differences) lie in
// [kOrient2dMin, kOrient2dMax].
inline constexpr double kOrient2dBound = 0x1p-50 + 0x1p-90;  // 8u (1 + 2^-40), u = 2^-53
inline constexpr double kOrient2dMin = 0x1p-480, kOrient2dMax = 0x1p+500;
// orient3d: |error| <= kOrient3dBound * mx * my * mz when mx, my, mz lie in [kOrient3dMin, kOrient3dMax].
inline constexpr double kOrient3dBound = 0x3p-49 + 0x3p-89;  // 48u (1 + 2^-40)
inline constexpr double kOrient3dMin = 0x1p-300, kOrient3dMax = 0x1p+300;

// The cold paths (exact small integers, rescaled columns), on the same inputs as the fast paths below.
std::optional<Sign> cross2d_cold(double u0x, double u0y, double u1x, double u1y, double v0x, double v0y,
                                 double v1x, double v1y) noexcept;
std::optional<Sign> orient3d_cold(const Point3& a, const Point3& b, const Point3& c, const Point3& d) noexcept;

// sign(det) when |det| > bound, else nullopt.
inline std::optional<Sign> certified(double det, double bound) noexcept {
  if (det > bound) return Sign::Positive;
  if (det < -bound) return Sign::Negative;
  return std::nullopt;
}
inline bool in_range(double m, double lo, double hi) noexcept { return m >= lo && m <= hi; }

// det[u; v; w] of the rows of m, expanded along the first row (the evaluation order the bound assumes).
inline double det3(const double (&m)[3][3]) noexcept {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) + m[0][1] * (m[1][2] * m[2][0] - m[1][0] * m[2][2]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}
inline double column_max(const double (&m)[3][3], int j) noexcept {
  return std::max({std::fabs(m[0][j]), std::fabs(m[1][j]), std::fabs(m[2][j])});
}
}  // namespace semi_static

// Sign of cross(u1 - u0, v1 - v0) = (u1x - u0x)(v1y - v0y) - (u1y - u0y)(v1x - v0x), if certified (the
// same error analysis as orient2d, of which it is the general form).
inline std::optional<Sign> cross2d_semi_static(double u0x, double u0y, double u1x, double u1y, double v0x,
                                               double v0y, double v1x, double v1y) noexcept {
  using namespace semi_static;
  const double ux = u1x - u0x, uy = u1y - u0y, vx = v1x - v0x, vy = v1y - v0y;
  const double det = ux * vy - uy * vx;
  const double mx = std::max(std::fabs(ux), std::fabs(vx)), my = std::max(std::fabs(uy), std::fabs(vy));
  if (std::min(mx, my) >= kOrient2dMin && std::max(mx, my) <= kOrient2dMax) [[likely]] {
    if (const auto s = certified(det, kOrient2dBound * mx * my)) return s;
  }
  return cross2d_cold(u0x, u0y, u1x, u1y, v0x, v0y, v1x, v1y);
}

// Sign of (bx - ax)(cy - ay) - (by - ay)(cx - ax) (orient2d), if certified.
inline std::optional<Sign> orient2d_semi_static(double ax, double ay, double bx, double by, double cx,
                                                double cy) noexcept {
  return cross2d_semi_static(ax, ay, bx, by, ax, ay, cx, cy);
}

// Sign of b - a for doubles: always exact (a difference of doubles rounds to 0 only if it is 0, and
// rounding never changes a sign).
inline Sign difference_sign(double a, double b) noexcept {
  return b > a ? Sign::Positive : (b < a ? Sign::Negative : Sign::Zero);
}

// Sign of det[b - a, c - a, d - a] (orient3d), if certified.
inline std::optional<Sign> orient3d_semi_static(const Point3& a, const Point3& b, const Point3& c,
                                                const Point3& d) noexcept {
  using namespace semi_static;
  const double m[3][3] = {{b.x - a.x, b.y - a.y, b.z - a.z},
                          {c.x - a.x, c.y - a.y, c.z - a.z},
                          {d.x - a.x, d.y - a.y, d.z - a.z}};
  const double det = det3(m);
  const double mx = column_max(m, 0), my = column_max(m, 1), mz = column_max(m, 2);
  if (std::min({mx, my, mz}) >= kOrient3dMin && std::max({mx, my, mz}) <= kOrient3dMax) [[likely]] {
    if (const auto s = certified(det, kOrient3dBound * mx * my * mz)) return s;
  }
  return orient3d_cold(a, b, c, d);
}

}  // namespace exactvis
