#include "kernel/predicates.hpp"

#include "kernel/semi_static_filters.hpp"

#include <CGAL/Mpzf.h>

namespace exactvis {
namespace {

// Layers (kernel/filtered_predicate.hpp): on double inputs a hand-written semi-static filter, then
// intervals, then CGAL::Mpzf (exact for these division-free expressions, faster than rationals); on rational
// inputs BoundedDouble on the inputs' enclosures, intervals, then Exact.

// orient3d(a, b, c, d) through the three layers, counted by `counter`. side(line(p1,q1), line(p2,q2)) is
// exactly orient3d(p1, q1, p2, q2) (docs/theory.md section 2), so side_of_lines on points uses it too.
template <class C>
Sign orient3d_counted(PredicateCounter& counter, const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& c,
                      const Vec3<C>& d) {
  auto expr = [&](auto nt) {
    using NT = typename decltype(nt)::type;
    const auto A = point_as<NT>(a);
    return dot(cross(point_as<NT>(b) - A, point_as<NT>(c) - A), point_as<NT>(d) - A);
  };
  if constexpr (std::is_same_v<C, double>)
    return filtered_sign_with<CGAL::Mpzf>(counter, [&] { return orient3d_semi_static(a, b, c, d); }, expr);
  else
    return filtered_sign<Exact>(counter, expr);
}

// Component `axis` of (b - a) x (c - a): orient2d in the coordinates (axis+1, axis+2).
template <class C>
Sign cross_component_impl(PredicateCounter& counter, const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& c,
                          int axis) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  auto expr = [&](auto nt) {
    using NT = typename decltype(nt)::type;
    const NT au = as<NT>(a[u]), av = as<NT>(a[v]);
    return (as<NT>(b[u]) - au) * (as<NT>(c[v]) - av) - (as<NT>(b[v]) - av) * (as<NT>(c[u]) - au);
  };
  if constexpr (std::is_same_v<C, double>)
    return filtered_sign_with<CGAL::Mpzf>(
        counter, [&] { return orient2d_semi_static(a[u], a[v], b[u], b[v], c[u], c[v]); }, expr);
  else
    return filtered_sign<Exact>(counter, expr);
}

template <class C>
Sign side_of_lines_impl(const Vec3<C>& p1, const Vec3<C>& q1, const Vec3<C>& p2, const Vec3<C>& q2) {
  static PredicateCounter counter("side_of_lines");
  return orient3d_counted(counter, p1, q1, p2, q2);
}

template <class C>
Sign orient3d_impl(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& c, const Vec3<C>& d) {
  static PredicateCounter counter("orient3d");
  return orient3d_counted(counter, a, b, c, d);
}

template <class C>
Sign orient2d_projected_impl(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& c, int axis) {
  static PredicateCounter counter("orient2d_projected");
  return cross_component_impl(counter, a, b, c, axis);
}

template <class C>
bool collinear_impl(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& c) {
  static PredicateCounter counter("collinear");
  // The cross product (b-a) x (c-a) vanishes iff collinear; test its three components.
  for (int k = 0; k < 3; ++k)
    if (cross_component_impl(counter, a, b, c, k) != Sign::Zero) return false;
  return true;
}

}  // namespace

Sign side_of_lines(const Point3& p1, const Point3& q1, const Point3& p2, const Point3& q2) {
  return side_of_lines_impl(p1, q1, p2, q2);
}
Sign side_of_lines(const RationalPoint3& p1, const RationalPoint3& q1, const RationalPoint3& p2,
                   const RationalPoint3& q2) {
  return side_of_lines_impl(p1, q1, p2, q2);
}
Sign side_of_lines(const PluckerLine<Exact>& a, const PluckerLine<Exact>& b) {
  static PredicateCounter counter("side_of_plucker_lines");
  return filtered_sign(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    if constexpr (std::is_same_v<NT, Exact>) {
      return side(a, b);
    } else {
      PluckerLine<NT> ia, ib;
      for (int i = 0; i < 6; ++i) {
        ia[i] = as<NT>(a[i]);
        ib[i] = as<NT>(b[i]);
      }
      return side(ia, ib);
    }
  });
}
Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) { return orient3d_impl(a, b, c, d); }
Sign orient3d(const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& c, const RationalPoint3& d) {
  return orient3d_impl(a, b, c, d);
}
Sign orient2d_projected(const Point3& a, const Point3& b, const Point3& c, int axis) {
  return orient2d_projected_impl(a, b, c, axis);
}
Sign orient2d_projected(const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& c, int axis) {
  return orient2d_projected_impl(a, b, c, axis);
}
bool collinear(const Point3& a, const Point3& b, const Point3& c) { return collinear_impl(a, b, c); }
bool collinear(const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& c) {
  return collinear_impl(a, b, c);
}

}  // namespace exactvis
