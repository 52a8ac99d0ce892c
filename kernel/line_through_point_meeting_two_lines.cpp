#include "kernel/line_through_point_meeting_two_lines.hpp"

namespace exactvis {
namespace {
bool is_zero(const Vec3<Exact>& v) { return v.x == 0 && v.y == 0 && v.z == 0; }
bool is_real_line(const PluckerLine<Exact>& l) { return !is_zero(l.d) && quadric(l) == 0; }
}  // namespace

LineThroughPointMeetingTwoLines line_through_point_meeting_two_lines(const RationalPoint3& p,
                                                                     const PluckerLine<Exact>& a,
                                                                     const PluckerLine<Exact>& b) {
  LineThroughPointMeetingTwoLines r;
  if (!is_real_line(a) || !is_real_line(b)) return r;
  // Normal of the plane through p containing line (d, m): p x d - m (zero iff p is on the line).
  const Vec3<Exact> na = cross(p, a.d) - a.m;
  const Vec3<Exact> nb = cross(p, b.d) - b.m;
  if (is_zero(na) || is_zero(nb)) {
    r.kind = PointTwoLinesKind::Infinite;
    return r;
  }
  const Vec3<Exact> d = cross(na, nb);
  if (is_zero(d)) {  // both planes contain p and are parallel: the same plane
    r.kind = PointTwoLinesKind::Infinite;
    return r;
  }
  r.line = {d, cross(p, d)};
  r.kind = (is_zero(cross(d, a.d)) || is_zero(cross(d, b.d))) ? PointTwoLinesKind::None : PointTwoLinesKind::Unique;
  return r;
}

LineThroughPointMeetingTwoLines line_through_point_meeting_two_lines(const Point3& p,
                                                                     const PluckerLine<Exact>& a,
                                                                     const PluckerLine<Exact>& b) {
  return line_through_point_meeting_two_lines(to_rational(p), a, b);
}

PluckerLine<Exact> exact_line_through(const Point3& p, const Point3& q) {
  return line_through(to_rational(p), to_rational(q));
}
PluckerLine<Exact> exact_line_through(const RationalPoint3& p, const RationalPoint3& q) { return line_through(p, q); }

}  // namespace exactvis
