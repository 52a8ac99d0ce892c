#include "kernel/semi_static_filters.hpp"

namespace exactvis::semi_static {
namespace {

// x is an integer. Valid for |x| < 2^51: adding 1.5 * 2^52 rounds x to an integer (round-to-nearest).
bool is_integer(double x) { return std::fabs(x) < 0x1p51 && (x + 0x1.8p52) - 0x1.8p52 == x; }

Sign sign_of_double(double x) { return x > 0 ? Sign::Positive : (x < 0 ? Sign::Negative : Sign::Zero); }

// x * 2^-e. Exact unless the result is subnormal (then off by at most 2^-1075, which the bound's slack
// covers: docs/theory.md section 1).
double scaled(double x, int e) { return std::ldexp(x, -e); }

}  // namespace

std::optional<Sign> cross2d_cold(double u0x, double u0y, double u1x, double u1y, double v0x, double v0y,
                                 double v1x, double v1y) noexcept {
  const double ux = u1x - u0x, uy = u1y - u0y, vx = v1x - v0x, vy = v1y - v0y;
  const double mx = std::max(std::fabs(ux), std::fabs(vx)), my = std::max(std::fabs(uy), std::fabs(vy));
  if (mx == 0 || my == 0) return Sign::Zero;  // a zero column: all x (or all y) differences are exactly 0
  if (!std::isfinite(mx) || !std::isfinite(my)) return std::nullopt;  // an overflowed difference
  // Integer inputs below 2^51: the differences are exact integers; with mx my < 2^51 both products and
  // their difference are exact too.
  if (mx * my < 0x1p51 && is_integer(u0x) && is_integer(u0y) && is_integer(u1x) && is_integer(u1y) &&
      is_integer(v0x) && is_integer(v0y) && is_integer(v1x) && is_integer(v1y))
    return sign_of_double(ux * vy - uy * vx);
  if (in_range(mx, kOrient2dMin, kOrient2dMax) && in_range(my, kOrient2dMin, kOrient2dMax)) return std::nullopt;
  // Rescale each column so that its maximum lies in [1, 2): the determinant is multiplied by 2^-(ex + ey).
  const int ex = std::ilogb(mx), ey = std::ilogb(my);
  const double det = scaled(ux, ex) * scaled(vy, ey) - scaled(uy, ey) * scaled(vx, ex);
  return certified(det, kOrient2dBound * scaled(mx, ex) * scaled(my, ey));
}

std::optional<Sign> orient3d_cold(const Point3& a, const Point3& b, const Point3& c, const Point3& d) noexcept {
  const double m[3][3] = {{b.x - a.x, b.y - a.y, b.z - a.z},
                          {c.x - a.x, c.y - a.y, c.z - a.z},
                          {d.x - a.x, d.y - a.y, d.z - a.z}};
  const double mx = column_max(m, 0), my = column_max(m, 1), mz = column_max(m, 2);
  if (mx == 0 || my == 0 || mz == 0) return Sign::Zero;  // a zero column of the matrix
  if (!std::isfinite(mx) || !std::isfinite(my) || !std::isfinite(mz)) return std::nullopt;
  // Integer inputs below 2^51 and mx my mz < 2^50: the differences are exact integers, and every product,
  // minor and sum of the expansion is an integer below 2^53, hence exact.
  if (mx * my * mz < 0x1p50) {
    bool integers = true;
    for (const Point3* p : {&a, &b, &c, &d})
      integers = integers && is_integer(p->x) && is_integer(p->y) && is_integer(p->z);
    if (integers) return sign_of_double(det3(m));
  }
  if (in_range(mx, kOrient3dMin, kOrient3dMax) && in_range(my, kOrient3dMin, kOrient3dMax) &&
      in_range(mz, kOrient3dMin, kOrient3dMax))
    return std::nullopt;
  // Rescale each column so that its maximum lies in [1, 2): the determinant is multiplied by a power of 2.
  const int e[3] = {std::ilogb(mx), std::ilogb(my), std::ilogb(mz)};
  double s[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s[i][j] = scaled(m[i][j], e[j]);
  return certified(det3(s), kOrient3dBound * scaled(mx, e[0]) * scaled(my, e[1]) * scaled(mz, e[2]));
}

}  // namespace exactvis::semi_static
