#include "kernel/predicates.hpp"

#include <CGAL/Mpzf.h>

namespace exactvis {
namespace {

// Exact number type of the fallback: for double inputs the (division-free) predicates below are evaluated
// with CGAL::Mpzf, exact and faster than rationals; for rational inputs with Exact.
template <class C>
using ExactFor = std::conditional_t<std::is_same_v<C, double>, CGAL::Mpzf, Exact>;

template <class C>
Sign side_of_lines_impl(const Vec3<C>& p1, const Vec3<C>& q1, const Vec3<C>& p2, const Vec3<C>& q2) {
  static PredicateCounter counter("side_of_lines");
  return filtered_sign<ExactFor<C>>(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    const auto a = line_through(point_as<NT>(p1), point_as<NT>(q1));
    const auto b = line_through(point_as<NT>(p2), point_as<NT>(q2));
    return side(a, b);
  });
}

template <class C>
Sign orient3d_impl(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& c, const Vec3<C>& d) {
  static PredicateCounter counter("orient3d");
  return filtered_sign<ExactFor<C>>(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    const auto A = point_as<NT>(a);
    return dot(cross(point_as<NT>(b) - A, point_as<NT>(c) - A), point_as<NT>(d) - A);
  });
}

template <class C>
Sign orient2d_projected_impl(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& c, int axis) {
  static PredicateCounter counter("orient2d_projected");
  return filtered_sign<ExactFor<C>>(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const NT au = as<NT>(a[u]), av = as<NT>(a[v]);
    return (as<NT>(b[u]) - au) * (as<NT>(c[v]) - av) - (as<NT>(b[v]) - av) * (as<NT>(c[u]) - au);
  });
}

template <class C>
bool collinear_impl(const Vec3<C>& a, const Vec3<C>& b, const Vec3<C>& c) {
  static PredicateCounter counter("collinear");
  // The cross product (b-a) x (c-a) vanishes iff collinear; test its three components.
  for (int k = 0; k < 3; ++k) {
    const Sign s = filtered_sign<ExactFor<C>>(counter, [&](auto nt) {
      using NT = typename decltype(nt)::type;
      const auto A = point_as<NT>(a);
      return cross(point_as<NT>(b) - A, point_as<NT>(c) - A)[k];
    });
    if (s != Sign::Zero) return false;
  }
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
