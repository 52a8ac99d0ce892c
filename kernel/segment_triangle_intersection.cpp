#include "kernel/segment_triangle_intersection.hpp"

#include <CGAL/Mpzf.h>

#include <algorithm>

namespace exactvis {
namespace {

// sign(orient2d(p,q,a) + orient2d(p,q,b)) in projection `axis`: orient2d is affine in its last point, so
// this is the orientation of the midpoint (a+b)/2 without constructing it.
template <class C>
Sign orient2d_projected_midpoint(const Vec3<C>& p, const Vec3<C>& q, const Vec3<C>& a, const Vec3<C>& b,
                                 int axis) {
  static PredicateCounter counter("orient2d_projected_midpoint");
  using ExactNT = std::conditional_t<std::is_same_v<C, double>, CGAL::Mpzf, Exact>;  // division-free
  return filtered_sign<ExactNT>(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const NT pu = as<NT>(p[u]), pv = as<NT>(p[v]);
    const NT du = as<NT>(q[u]) - pu, dv = as<NT>(q[v]) - pv;
    return du * (as<NT>(a[v]) - pv) - dv * (as<NT>(a[u]) - pu) + du * (as<NT>(b[v]) - pv) -
           dv * (as<NT>(b[u]) - pu);
  });
}

bool opposite(Sign x, Sign y) { return to_int(x) * to_int(y) < 0; }
bool mixed(Sign a, Sign b, Sign c) {  // some strictly positive and some strictly negative
  const bool pos = a == Sign::Positive || b == Sign::Positive || c == Sign::Positive;
  const bool neg = a == Sign::Negative || b == Sign::Negative || c == Sign::Negative;
  return pos && neg;
}

template <class C>
bool same_2d(const Vec3<C>& p, const Vec3<C>& q, int axis) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  return p[u] == q[u] && p[v] == q[v];
}

// r within the coordinate bounding box of p, q on every coordinate in `coords` (exact comparisons).
template <class C>
bool in_box(const Vec3<C>& p, const Vec3<C>& q, const Vec3<C>& r, std::initializer_list<int> coords) {
  for (int k : coords) {
    const C& lo = std::min(p[k], q[k]);
    const C& hi = std::max(p[k], q[k]);
    if (r[k] < lo || r[k] > hi) return false;
  }
  return true;
}

// Projected point r on the projected closed segment [p,q] (p == q allowed).
template <class C>
bool point_on_closed_segment_2d(const Vec3<C>& r, const Vec3<C>& p, const Vec3<C>& q, int axis) {
  if (orient2d_projected(p, q, r, axis) != Sign::Zero) return false;
  return in_box(p, q, r, {(axis + 1) % 3, (axis + 2) % 3});
}

// Projected open segment (a,b) (a != b in 3D, but the projections may coincide: then it projects to one
// point) vs projected closed segment [c,d] (c == d allowed).
template <class C>
bool open_segment_meets_closed_segment_2d(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& c,
                                          const Vec3<C>& d, int axis) {
  if (same_2d(a, b, axis)) return point_on_closed_segment_2d(a, c, d, axis);
  const Sign sc = orient2d_projected(a, b, c, axis);
  const Sign sd = orient2d_projected(a, b, d, axis);
  if (sc == Sign::Zero && sd == Sign::Zero) {
    // c, d on the line ab: compare along a coordinate on which a and b differ (injective on that line).
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const int w = a[u] != b[u] ? u : v;
    const C& lo = std::min(a[w], b[w]);
    const C& hi = std::max(a[w], b[w]);
    return std::max(c[w], d[w]) > lo && std::min(c[w], d[w]) < hi;
  }
  if (to_int(sc) * to_int(sd) > 0) return false;
  // Lines ab and cd meet in one point X, which lies on [c,d]; it must be strictly inside (a,b).
  return opposite(orient2d_projected(c, d, a, axis), orient2d_projected(c, d, b, axis));
}

// Projected point in the projected closed triangle, which must be non-degenerate in this projection.
template <class C>
bool point_in_closed_triangle_2d(const Vec3<C>& p, const Vec3<C>& t0, const Vec3<C>& t1, const Vec3<C>& t2,
                                 int axis) {
  return !mixed(orient2d_projected(t0, t1, p, axis), orient2d_projected(t1, t2, p, axis),
                orient2d_projected(t2, t0, p, axis));
}

template <class C>
bool midpoint_in_closed_triangle_2d(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& t0, const Vec3<C>& t1,
                                    const Vec3<C>& t2, int axis) {
  return !mixed(orient2d_projected_midpoint(t0, t1, a, b, axis), orient2d_projected_midpoint(t1, t2, a, b, axis),
                orient2d_projected_midpoint(t2, t0, a, b, axis));
}

// An axis along which the projection of the (non-degenerate) triangle is non-degenerate, or -1 if the
// triangle has zero area.
template <class C>
int projection_axis(const Vec3<C>& t0, const Vec3<C>& t1, const Vec3<C>& t2) {
  for (int k = 0; k < 3; ++k)
    if (orient2d_projected(t0, t1, t2, k) != Sign::Zero) return k;
  return -1;
}

// Open segment (a,b), a != b, vs closed segment [c,d] in 3D. Both lie in one plane iff orient3d = 0; then
// they meet iff their projections meet along all three axes (one of them is injective on that plane).
template <class C>
bool open_segment_meets_closed_segment_3d(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& c,
                                          const Vec3<C>& d) {
  if (orient3d(a, b, c, d) != Sign::Zero) return false;
  for (int k = 0; k < 3; ++k)
    if (!open_segment_meets_closed_segment_2d(a, b, c, d, k)) return false;
  return true;
}

template <class C>
bool point_on_closed_segment_3d(const Vec3<C>& p, const Vec3<C>& c, const Vec3<C>& d) {
  return collinear(c, d, p) && in_box(c, d, p, {0, 1, 2});
}

template <class C>
bool point_in_closed_triangle_impl(const Vec3<C>& p, const Vec3<C>& t0, const Vec3<C>& t1, const Vec3<C>& t2) {
  const int axis = projection_axis(t0, t1, t2);
  if (axis < 0)  // zero-area triangle: the union of its three closed edges
    return point_on_closed_segment_3d(p, t0, t1) || point_on_closed_segment_3d(p, t1, t2) ||
           point_on_closed_segment_3d(p, t2, t0);
  if (orient3d(t0, t1, t2, p) != Sign::Zero) return false;
  return point_in_closed_triangle_2d(p, t0, t1, t2, axis);
}

template <class C>
bool open_segment_meets_closed_triangle_impl(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& t0,
                                             const Vec3<C>& t1, const Vec3<C>& t2) {
  if (a == b) return false;
  const int axis = projection_axis(t0, t1, t2);
  if (axis < 0)
    return open_segment_meets_closed_segment_3d(a, b, t0, t1) || open_segment_meets_closed_segment_3d(a, b, t1, t2) ||
           open_segment_meets_closed_segment_3d(a, b, t2, t0);
  const Sign oa = orient3d(t0, t1, t2, a);
  const Sign ob = orient3d(t0, t1, t2, b);
  if (oa == Sign::Zero && ob == Sign::Zero) {
    // Coplanar. (a,b) is connected: if it misses the boundary it lies wholly inside or wholly outside, so
    // testing the three edges and the midpoint suffices.
    return open_segment_meets_closed_segment_2d(a, b, t0, t1, axis) ||
           open_segment_meets_closed_segment_2d(a, b, t1, t2, axis) ||
           open_segment_meets_closed_segment_2d(a, b, t2, t0, axis) ||
           midpoint_in_closed_triangle_2d(a, b, t0, t1, t2, axis);
  }
  // The line ab crosses the plane once; the crossing is strictly inside (a,b) iff a, b are strictly on
  // opposite sides. Then it lies in the closed triangle iff the line passes no two edges on opposite sides.
  if (!opposite(oa, ob)) return false;
  return !mixed(orient3d(a, b, t0, t1), orient3d(a, b, t1, t2), orient3d(a, b, t2, t0));
}

template <class C>
bool segment_meets_closed_triangle_impl(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& t0,
                                        const Vec3<C>& t1, const Vec3<C>& t2) {
  // [a,b] = {a} u (a,b) u {b}.
  return point_in_closed_triangle_impl(a, t0, t1, t2) || point_in_closed_triangle_impl(b, t0, t1, t2) ||
         open_segment_meets_closed_triangle_impl(a, b, t0, t1, t2);
}

template <class C>
bool segment_crosses_triangle_interior_impl(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& t0,
                                            const Vec3<C>& t1, const Vec3<C>& t2) {
  if (!opposite(orient3d(t0, t1, t2, a), orient3d(t0, t1, t2, b))) return false;  // also rules out area 0
  const Sign s0 = orient3d(a, b, t0, t1);
  if (s0 == Sign::Zero) return false;
  return orient3d(a, b, t1, t2) == s0 && orient3d(a, b, t2, t0) == s0;
}

}  // namespace

bool segment_meets_closed_triangle(const Point3& a, const Point3& b, const Point3& t0, const Point3& t1,
                                   const Point3& t2) {
  return segment_meets_closed_triangle_impl(a, b, t0, t1, t2);
}
bool segment_meets_closed_triangle(const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& t0,
                                   const RationalPoint3& t1, const RationalPoint3& t2) {
  return segment_meets_closed_triangle_impl(a, b, t0, t1, t2);
}
bool open_segment_meets_closed_triangle(const Point3& a, const Point3& b, const Point3& t0, const Point3& t1,
                                        const Point3& t2) {
  return open_segment_meets_closed_triangle_impl(a, b, t0, t1, t2);
}
bool open_segment_meets_closed_triangle(const RationalPoint3& a, const RationalPoint3& b,
                                        const RationalPoint3& t0, const RationalPoint3& t1,
                                        const RationalPoint3& t2) {
  return open_segment_meets_closed_triangle_impl(a, b, t0, t1, t2);
}
bool segment_crosses_triangle_interior(const Point3& a, const Point3& b, const Point3& t0, const Point3& t1,
                                       const Point3& t2) {
  return segment_crosses_triangle_interior_impl(a, b, t0, t1, t2);
}
bool segment_crosses_triangle_interior(const RationalPoint3& a, const RationalPoint3& b,
                                       const RationalPoint3& t0, const RationalPoint3& t1,
                                       const RationalPoint3& t2) {
  return segment_crosses_triangle_interior_impl(a, b, t0, t1, t2);
}
bool point_in_closed_triangle(const Point3& p, const Point3& t0, const Point3& t1, const Point3& t2) {
  return point_in_closed_triangle_impl(p, t0, t1, t2);
}
bool point_in_closed_triangle(const RationalPoint3& p, const RationalPoint3& t0, const RationalPoint3& t1,
                              const RationalPoint3& t2) {
  return point_in_closed_triangle_impl(p, t0, t1, t2);
}

}  // namespace exactvis
