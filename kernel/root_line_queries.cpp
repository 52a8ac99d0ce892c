#include "kernel/root_line_queries.hpp"

namespace exactvis {
namespace {
bool is_zero(const Vec3<RootNumber>& v) { return CGAL::is_zero(v.x) && CGAL::is_zero(v.y) && CGAL::is_zero(v.z); }
}  // namespace

Sign side_sign(const PluckerLine<RootNumber>& x, const PluckerLine<Exact>& l) {
  return sign_of(static_cast<int>(CGAL::sign(side(x, PluckerLine<RootNumber>::from(l)))));
}

std::optional<Vec3<RootNumber>> meeting_point(const PluckerLine<RootNumber>& x, const PluckerLine<Exact>& l) {
  const auto r = PluckerLine<RootNumber>::from(l);
  if (!CGAL::is_zero(side(x, r)) || is_zero(cross(x.d, r.d))) return std::nullopt;
  // (m x m_l) = P (m . d_l) for the meeting point P when the origin is off the common plane
  // ((P x d) x (P x d_l) = P (P . (d x d_l)) and P . (d x d_l) = m . d_l).
  for (int k = -1; k < 3; ++k) {
    Vec3<RootNumber> o;
    if (k >= 0) o[k] = RootNumber(1);
    const Vec3<RootNumber> mx = x.m - cross(o, x.d), ml = r.m - cross(o, r.d);
    const RootNumber den = dot(mx, r.d);
    if (CGAL::is_zero(den)) continue;
    const Vec3<RootNumber> c = cross(mx, ml);
    return Vec3<RootNumber>{o.x + c.x / den, o.y + c.y / den, o.z + c.z / den};
  }
  return std::nullopt;  // unreachable for meeting, non-parallel real lines
}

}  // namespace exactvis
