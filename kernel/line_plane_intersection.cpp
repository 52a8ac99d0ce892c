#include "kernel/line_plane_intersection.hpp"

namespace exactvis {
namespace {

struct Plane {
  Vec3<Exact> n;  // normal (t1-t0) x (t2-t0)
  Exact w;        // n . t0
};

Plane plane_through(const RationalPoint3& t0, const RationalPoint3& t1, const RationalPoint3& t2) {
  const Vec3<Exact> n = cross(t1 - t0, t2 - t0);
  return {n, dot(n, t0)};
}

bool is_zero(const Vec3<Exact>& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

}  // namespace

LinePlaneIntersection line_plane_intersection(const RationalPoint3& p, const RationalPoint3& q,
                                              const RationalPoint3& t0, const RationalPoint3& t1,
                                              const RationalPoint3& t2) {
  LinePlaneIntersection r;
  const Plane pl = plane_through(t0, t1, t2);
  const Vec3<Exact> d = q - p;
  if (is_zero(pl.n) || is_zero(d)) return r;
  const Exact denom = dot(pl.n, d);
  const Exact num = pl.w - dot(pl.n, p);
  if (denom == 0) {
    r.kind = num == 0 ? LinePlaneKind::Contained : LinePlaneKind::Parallel;
    return r;
  }
  r.kind = LinePlaneKind::Point;
  r.t = num / denom;
  r.point = p + r.t * d;
  return r;
}

LinePlaneIntersection line_plane_intersection(const Point3& p, const Point3& q, const Point3& t0,
                                              const Point3& t1, const Point3& t2) {
  return line_plane_intersection(to_rational(p), to_rational(q), to_rational(t0), to_rational(t1),
                                 to_rational(t2));
}

LinePlaneIntersection line_plane_intersection(const PluckerLine<Exact>& line, const RationalPoint3& t0,
                                              const RationalPoint3& t1, const RationalPoint3& t2) {
  LinePlaneIntersection r;
  const Plane pl = plane_through(t0, t1, t2);
  if (is_zero(pl.n) || is_zero(line.d) || quadric(line) != 0) return r;
  const Exact denom = dot(pl.n, line.d);
  if (denom == 0) {
    // Parallel: contained iff a point of the line is on the plane. The point of the line closest to the
    // origin is (d x m) / |d|^2.
    const Vec3<Exact> p0 = (Exact(1) / dot(line.d, line.d)) * cross(line.d, line.m);
    r.kind = dot(pl.n, p0) == pl.w ? LinePlaneKind::Contained : LinePlaneKind::Parallel;
    return r;
  }
  r.kind = LinePlaneKind::Point;
  r.point = (Exact(1) / denom) * (cross(pl.n, line.m) + pl.w * line.d);
  return r;
}

}  // namespace exactvis
