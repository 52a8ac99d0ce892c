#include "region/convex_polygon_3.hpp"

#include <algorithm>
#include <limits>
#include <optional>
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

namespace {
// The exact sign of plane.value(x) from the plane's enclosure (computed once per clip): BoundedDouble first
// (docs/theory.md section 1, semi-static layer), the exact value only when the bound does not decide it.
struct PlaneEnclosure {
  BoundedDouble nx, ny, nz, off;
  explicit PlaneEnclosure(const Plane3& pl)
      : nx(enclosing_interval(pl.normal.x)), ny(enclosing_interval(pl.normal.y)),
        nz(enclosing_interval(pl.normal.z)), off(enclosing_interval(pl.offset)) {}
  std::optional<Sign> sign_at(const RationalPoint3& x) const {
    const BoundedDouble v = nx * BoundedDouble(enclosing_interval(x.x)) +
                            ny * BoundedDouble(enclosing_interval(x.y)) +
                            nz * BoundedDouble(enclosing_interval(x.z)) - off;
    return v.certified_sign();
  }
};
}  // namespace

Polygon3 clip_polygon(const Polygon3& poly, const Plane3& plane) {
  Polygon3 out;
  const std::size_t n = poly.size();
  if (n == 0) return out;
  // Signs first (filtered); the exact values only at the ends of the edges that cross the plane, which are
  // the only ones the crossing points need. The same signs and values as computing every value exactly.
  std::vector<int> s(n);
  std::vector<std::optional<Exact>> v(n);
  const PlaneEnclosure enc(plane);
  for (std::size_t i = 0; i < n; ++i) {
    if (const std::optional<Sign> f = enc.sign_at(poly[i])) {
      s[i] = to_int(*f);
    } else {
      v[i] = plane.value(poly[i]);
      s[i] = CGAL::sign(*v[i]);
    }
  }
  auto value = [&](std::size_t i) -> const Exact& {
    if (!v[i]) v[i] = plane.value(poly[i]);
    return *v[i];
  };
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const int si = s[i], sj = s[j];
    if (si >= 0) out.push_back(poly[i]);
    if ((si > 0 && sj < 0) || (si < 0 && sj > 0)) {
      const Exact& vi = value(i);
      const Exact t = vi / (vi - value(j));
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

void validate_source_polygon(const Polygon3& poly) {
  if (poly.size() < 3) throw std::invalid_argument("source polygon needs at least 3 vertices");
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (poly[i] == poly[(i + 1) % poly.size()]) throw std::invalid_argument("source polygon repeats a vertex");
  if (is_degenerate(poly)) throw std::invalid_argument("source polygon has zero area (collinear vertices)");
  const Plane3 pl = plane_of(poly);
  if (!lies_in_plane(poly, pl)) throw std::invalid_argument("source polygon is not planar");
  // Convex: every vertex turns the same way (w.r.t. the plane normal) and the loop winds once.
  int turn = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    const auto& c = poly[(i + 2) % poly.size()];
    const int s = CGAL::sign(dot(cross(b - a, c - b), pl.normal));
    if (s == 0) continue;
    if (turn != 0 && s != turn) throw std::invalid_argument("source polygon is not convex");
    turn = s;
  }
  // Winding once: every vertex must be on the inner side of every edge (closed), which rules out stars.
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    for (const auto& v : poly)
      if (CGAL::sign(dot(cross(b - a, v - a), pl.normal)) * turn < 0)
        throw std::invalid_argument("source polygon is not convex");
  }
}

bool in_closed_polygon(const RationalPoint3& p, const Polygon3& poly) {
  const Plane3 pl = plane_of(poly);
  if (CGAL::sign(pl.value(p)) != CGAL::ZERO) return false;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    if (CGAL::sign(dot(cross(b - a, p - a), pl.normal)) == CGAL::NEGATIVE) return false;
  }
  return true;
}

bool in_triangle_relative_interior(const RationalPoint3& q, const std::array<RationalPoint3, 3>& t) {
  if (orient3d(t[0], t[1], t[2], q) != Sign::Zero) return false;
  const Vec3<Exact> n = cross(t[1] - t[0], t[2] - t[0]);
  for (int i = 0; i < 3; ++i) {
    const auto& a = t[i];
    const auto& b = t[(i + 1) % 3];
    if (CGAL::sign(dot(cross(b - a, q - a), n)) != CGAL::POSITIVE) return false;
  }
  return true;
}

std::array<RationalPoint3, 3> triangle_points(const Scene& scene, std::int64_t index) {
  const auto& t = scene.triangles[index];
  return {to_rational(scene.corner(t, 0)), to_rational(scene.corner(t, 1)), to_rational(scene.corner(t, 2))};
}

std::vector<long> random_weights(std::size_t n, std::mt19937_64& rng) {
  std::vector<long> w(n);
  for (auto& x : w) x = 1 + static_cast<long>(rng() % (1u << 20));
  return w;
}

RationalPoint3 weighted_point(const Polygon3& poly, const std::vector<long>& w) {
  RationalPoint3 acc{Exact(0), Exact(0), Exact(0)};
  long total = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    acc = acc + Exact(w[i]) * poly[i];
    total += w[i];
  }
  const Exact t(total);
  return {acc.x / t, acc.y / t, acc.z / t};
}

Point3 weighted_point_approx(const std::vector<Point3>& poly, const std::vector<long>& w) {
  Point3 acc{0, 0, 0};
  double total = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    acc = acc + static_cast<double>(w[i]) * poly[i];
    total += static_cast<double>(w[i]);
  }
  return {acc.x / total, acc.y / total, acc.z / total};
}

std::vector<Point3> approximate_polygon(const Polygon3& poly) {
  std::vector<Point3> out;
  for (const auto& p : poly) out.push_back({CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)});
  return out;
}

RationalPoint3 random_interior_point(const Polygon3& poly, std::mt19937_64& rng) {
  return weighted_point(poly, random_weights(poly.size(), rng));
}

RationalBox3 exact_box(const Box3& b) { return {to_rational(b.lo), to_rational(b.hi)}; }

Polygon3 box_face(const RationalBox3& b, int axis, bool high) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  auto pt = [&](const Exact& a, const Exact& bu, const Exact& bv) {
    RationalPoint3 p;
    p[axis] = a;
    p[u] = bu;
    p[v] = bv;
    return p;
  };
  const Exact& a = high ? b.hi[axis] : b.lo[axis];
  return {pt(a, b.lo[u], b.lo[v]), pt(a, b.hi[u], b.lo[v]), pt(a, b.hi[u], b.hi[v]), pt(a, b.lo[u], b.hi[v])};
}

bool in_closed_box(const RationalPoint3& p, const RationalBox3& b) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < b.lo[k] || p[k] > b.hi[k]) return false;
  return true;
}

Box3 approximate_box(const RationalBox3& b) {
  return {{CGAL::to_double(b.lo.x), CGAL::to_double(b.lo.y), CGAL::to_double(b.lo.z)},
          {CGAL::to_double(b.hi.x), CGAL::to_double(b.hi.y), CGAL::to_double(b.hi.z)}};
}

Box3 enclosing_box(const std::vector<RationalPoint3>& pts) {
  const double inf = std::numeric_limits<double>::infinity();
  Box3 b{{inf, inf, inf}, {-inf, -inf, -inf}};
  for (const auto& p : pts)
    for (int k = 0; k < 3; ++k) {
      const auto iv = enclosing_interval(p[k]);
      b.lo[k] = std::min(b.lo[k], iv.first);
      b.hi[k] = std::max(b.hi[k], iv.second);
    }
  return b;
}

}  // namespace exactvis::region
