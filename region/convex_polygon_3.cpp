#include "region/convex_polygon_3.hpp"

#include <stdexcept>

namespace exactvis::region {

Plane3 plane_through(const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& c) {
  Vec3<Exact> n = cross(b - a, c - a);
  return {n, dot(n, a)};
}

namespace {
template <class C>
Sign plane_side_impl(const Plane3& plane, const Vec3<C>& x) {
  static PredicateCounter counter("plane_side");
  return filtered_sign(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    return as<NT>(plane.normal.x) * as<NT>(x.x) + as<NT>(plane.normal.y) * as<NT>(x.y) +
           as<NT>(plane.normal.z) * as<NT>(x.z) - as<NT>(plane.offset);
  });
}
}  // namespace

Sign plane_side(const Plane3& plane, const Point3& x) { return plane_side_impl(plane, x); }
Sign plane_side(const Plane3& plane, const RationalPoint3& x) { return plane_side_impl(plane, x); }

Plane3 plane_of(const Polygon3& poly) {
  for (std::size_t i = 2; i < poly.size(); ++i)
    if (!collinear(poly[0], poly[1], poly[i])) return plane_through(poly[0], poly[1], poly[i]);
  throw std::invalid_argument("degenerate polygon has no plane");
}

Polygon3 clip_polygon(const Polygon3& poly, const Plane3& plane) {
  Polygon3 out;
  const std::size_t n = poly.size();
  if (n == 0) return out;
  std::vector<Exact> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = plane.value(poly[i]);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const int si = CGAL::sign(v[i]), sj = CGAL::sign(v[j]);
    if (si >= 0) out.push_back(poly[i]);
    if ((si > 0 && sj < 0) || (si < 0 && sj > 0)) {
      const Exact t = v[i] / (v[i] - v[j]);
      out.push_back(poly[i] + t * (poly[j] - poly[i]));
    }
  }
  // Remove repeated consecutive vertices (a vertex on the plane next to a crossing point).
  Polygon3 clean;
  for (const auto& p : out)
    if (clean.empty() || !(clean.back() == p)) clean.push_back(p);
  while (clean.size() > 1 && clean.front() == clean.back()) clean.pop_back();
  return clean;
}

bool is_degenerate(const Polygon3& poly) {
  if (poly.size() < 3) return true;
  for (std::size_t i = 2; i < poly.size(); ++i)
    if (!collinear(poly[0], poly[1], poly[i])) return false;
  // poly[0] == poly[1] makes every triple collinear; try other anchors.
  for (std::size_t a = 1; a < poly.size(); ++a)
    for (std::size_t b = a + 1; b < poly.size(); ++b)
      for (std::size_t c = b + 1; c < poly.size(); ++c)
        if (!collinear(poly[a], poly[b], poly[c])) return false;
  return true;
}

RationalPoint3 centroid(const Polygon3& poly) {
  RationalPoint3 c{Exact(0), Exact(0), Exact(0)};
  for (const auto& p : poly) c = c + p;
  const Exact k(static_cast<int>(poly.size()));
  return {c.x / k, c.y / k, c.z / k};
}

bool lies_in_plane(const Polygon3& poly, const Plane3& plane) {
  for (const auto& p : poly)
    if (CGAL::sign(plane.value(p)) != CGAL::ZERO) return false;
  return true;
}

}  // namespace exactvis::region
