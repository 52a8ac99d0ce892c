#include "region/witness.hpp"

#include "kernel/bounded_double.hpp"
#include "kernel/round_to_doubles.hpp"
#include "kernel/segment_triangle_intersection.hpp"

#include <algorithm>
#include <array>

namespace exactvis::region {
namespace {

mpq_class q_at(const RatVec6& x) { return x[0] * x[3] + x[1] * x[4] + x[2] * x[5]; }

RatVec6 lerp(const IntVec6& a, const IntVec6& b, const mpq_class& t) {
  RatVec6 x;
  for (int k = 0; k < 6; ++k) x[k] = (1 - t) * a[k] + t * b[k];
  return x;
}

// The real line (d, m - (d.m / d.d) d) next to a 6-vector with d != 0.
std::optional<RatVec6> realify(const RatVec6& x) {
  const mpq_class dd = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
  if (sgn(dd) == 0) return std::nullopt;
  const mpq_class f = q_at(x) / dd;
  RatVec6 y = x;
  for (int k = 0; k < 3; ++k) y[3 + k] -= f * x[k];
  return y;
}

RationalPoint3 meet_plane(const RatVec6& line, const Plane3& plane) {
  const Vec3<Exact> d{Exact(line[0].get_mpq_t()), Exact(line[1].get_mpq_t()), Exact(line[2].get_mpq_t())};
  const Vec3<Exact> m{Exact(line[3].get_mpq_t()), Exact(line[4].get_mpq_t()), Exact(line[5].get_mpq_t())};
  const Exact dd = dot(d, d);
  const Vec3<Exact> dm = cross(d, m);
  const RationalPoint3 p0{dm.x / dd, dm.y / dd, dm.z / dd};  // point of the line closest to the origin
  const Exact t = (plane.offset - dot(plane.normal, p0)) / dot(plane.normal, d);
  return p0 + t * d;
}

IntVec6 scaled_sum(const IntVec6& a, unsigned shift, const IntVec6& c) {
  IntVec6 v;
  for (int k = 0; k < 6; ++k) v[k] = (a[k] << shift) + c[k];
  return v;
}

// A point of the open cone K with q of sign `s`, next to the closure point `x` (q(x) has sign s).
IntVec6 push_inside(const IntVec6& x, const IntVec6& interior, int s) {
  for (unsigned shift = 1;; shift += 4) {
    IntVec6 y = scaled_sum(x, shift, interior);
    if (sgn(plucker_form(y)) == s) return y;
  }
}

}  // namespace

std::optional<Witness> line_in_cone(const PolyhedralCone6& cone, const RealLineTest& test, const StabbingPair& pair,
                                    std::mt19937_64& rng) {
  IntVec6 c = interior_point(cone);
  if (!cone.rays.empty()) {  // vary the interior point between attempts
    const IntVec6 r = cone.rays[rng() % cone.rays.size()].to_gmp();
    const long factor = 1 + static_cast<long>(rng() % 7);
    for (int k = 0; k < 6; ++k) c[k] += r[k] * factor;
  }
  const IntVec6 a = push_inside(test.positive_point.to_gmp(), c, +1);
  const IntVec6 b = push_inside(test.negative_point.to_gmp(), c, -1);
  mpq_class lo = 0, hi = 1;
  for (int iter = 1; iter <= 2048; ++iter) {
    const mpq_class mid = (lo + hi) / 2;
    const int s = sgn(q_at(lerp(a, b, mid)));
    if (s == 0) {
      lo = hi = mid;
    } else if (s > 0) {
      lo = mid;
    } else {
      hi = mid;
    }
    if (iter % 16 != 0 && s != 0) continue;
    const auto line = realify(lerp(a, b, lo));
    if (!line) continue;
    if (!in_open_cone(cone, to_integer(*line))) {
      if (s == 0) return std::nullopt;
      continue;
    }
    return Witness{meet_plane(*line, pair.source_plane), meet_plane(*line, pair.target_plane)};
  }
  return std::nullopt;
}

std::optional<Witness> round_witness(const Scene& scene, const CandidateFinder& candidates,
                                     const std::function<bool(const RationalPoint3&)>& on_source,
                                     std::int64_t triangle_index, const Witness& w) {
  const Witness r{round_to_doubles(w.p), round_to_doubles(w.q)};
  if (r.p == w.p && r.q == w.q) return w;
  const auto tri = triangle_points(scene, triangle_index);
  if (!on_source(r.p) || !in_triangle_relative_interior(r.q, tri)) return std::nullopt;
  const auto cands = candidates(enclosing_box({w.p, w.q, r.p, r.q}));
  if (!segment_is_free(scene, cands, r.p, r.q, triangle_index)) return std::nullopt;
  return r;
}

namespace {

using BD = BoundedDouble;

// sign(dot(cross(b - a, c - a), d - a)), orient3d's expression, certified by the semi-static layer or nullopt.
template <class P, class Q, class R, class S>
std::optional<Sign> certified_orient3d(const P& a, const Q& b, const R& c, const S& d) {
  const BD ax(a[0]), ay(a[1]), az(a[2]);
  const BD ux = BD(b[0]) - ax, uy = BD(b[1]) - ay, uz = BD(b[2]) - az;
  const BD vx = BD(c[0]) - ax, vy = BD(c[1]) - ay, vz = BD(c[2]) - az;
  const BD wx = BD(d[0]) - ax, wy = BD(d[1]) - ay, wz = BD(d[2]) - az;
  return ((uy * vz - uz * vy) * wx + (uz * vx - ux * vz) * wy + (ux * vy - uy * vx) * wz).certified_sign();
}

struct BoundedPoint {  // a rational point as enclosures of its coordinates
  std::array<BD, 3> c;
  explicit BoundedPoint(const RationalPoint3& p)
      : c{BD(tight_interval(p.x)), BD(tight_interval(p.y)), BD(tight_interval(p.z))} {}
  const BD& operator[](int k) const { return c[static_cast<std::size_t>(k)]; }
};

// open_segment_meets_closed_triangle(p, q, t) decided in the semi-static layer when it can (the same
// expressions as its exact path, so the same answer), else nullopt. The triangle's corners are doubles.
std::optional<bool> certified_meets(const BoundedPoint& p, const BoundedPoint& q, const Point3& t0, const Point3& t1,
                                    const Point3& t2) {
  const auto op = certified_orient3d(t0, t1, t2, p), oq = certified_orient3d(t0, t1, t2, q);
  if (!op || !oq) return std::nullopt;
  // A certified non-zero value means the triangle has positive area (the exact path then tests the sides).
  if (*op != Sign::Zero && *op == *oq) return false;  // both strictly on one side
  if (*op == Sign::Zero || *oq == Sign::Zero) return std::nullopt;
  // Strictly on opposite sides: the crossing lies in the closed triangle iff the three signs are not mixed.
  const auto s0 = certified_orient3d(p, q, t0, t1), s1 = certified_orient3d(p, q, t1, t2),
             s2 = certified_orient3d(p, q, t2, t0);
  if (!s0 || !s1 || !s2) return std::nullopt;
  const bool pos = *s0 == Sign::Positive || *s1 == Sign::Positive || *s2 == Sign::Positive;
  const bool neg = *s0 == Sign::Negative || *s1 == Sign::Negative || *s2 == Sign::Negative;
  return !(pos && neg);
}

bool is_double(const RationalPoint3& p) {
  for (int k = 0; k < 3; ++k) {
    const auto e = tight_interval(p[k]);  // a point exactly when the coordinate is a double
    if (e.first != e.second) return false;
  }
  return true;
}

}  // namespace

bool segment_is_free(const Scene& scene, const std::vector<std::int64_t>& candidates, const RationalPoint3& p,
                     const RationalPoint3& q, std::int64_t skip) {
  // A box of doubles enclosing the closed segment: a triangle whose (double) bounding box misses it cannot
  // meet the segment, so it is skipped before the exact test and its conversion to rationals (most
  // candidates of a query box lie far from any one segment). The answer is unchanged.
  std::array<double, 3> lo, hi;
  for (int k = 0; k < 3; ++k) {
    const auto ep = enclosing_interval(p[k]), eq = enclosing_interval(q[k]);
    lo[static_cast<std::size_t>(k)] = std::min(ep.first, eq.first);
    hi[static_cast<std::size_t>(k)] = std::max(ep.second, eq.second);
  }
  // Endpoints that are doubles exactly (rounded witnesses): the double form of the same exact predicate
  // (its exact layer works on doubles, not rationals). Otherwise the semi-static layer decides most
  // triangles from enclosures of the endpoints computed once; the rest take the rational path.
  const bool doubles = is_double(p) && is_double(q);
  Point3 a{}, b{};
  if (doubles) {
    a = {CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)};
    b = {CGAL::to_double(q.x), CGAL::to_double(q.y), CGAL::to_double(q.z)};
  }
  const BoundedPoint bp(p), bq(q);
  for (const std::int64_t idx : candidates) {
    if (idx == skip) continue;
    const SceneTriangle& st = scene.triangles[static_cast<std::size_t>(idx)];
    bool apart = false;
    for (int k = 0; k < 3 && !apart; ++k) {
      const double x = scene.corner(st, 0)[k], y = scene.corner(st, 1)[k], z = scene.corner(st, 2)[k];
      apart = std::max({x, y, z}) < lo[static_cast<std::size_t>(k)] || std::min({x, y, z}) > hi[static_cast<std::size_t>(k)];
    }
    if (apart) continue;
    const Point3 &t0 = scene.corner(st, 0), &t1 = scene.corner(st, 1), &t2 = scene.corner(st, 2);
    if (doubles) {
      if (open_segment_meets_closed_triangle(a, b, t0, t1, t2)) return false;
      continue;
    }
    if (const auto m = certified_meets(bp, bq, t0, t1, t2)) {
      if (*m) return false;
      continue;
    }
    const auto t = triangle_points(scene, idx);
    if (open_segment_meets_closed_triangle(p, q, t[0], t[1], t[2])) return false;
  }
  return true;
}

bool segment_is_free(const std::vector<std::array<RationalPoint3, 3>>& occluders, const RationalPoint3& p,
                     const RationalPoint3& q) {
  for (const auto& t : occluders)
    if (open_segment_meets_closed_triangle(p, q, t[0], t[1], t[2])) return false;
  return true;
}

std::optional<Witness> witness_inside_cell(const Scene& scene, const std::vector<std::int64_t>& cands,
                                           const Polygon3& t_in, const std::array<RationalPoint3, 3>& tri,
                                           const RationalBox3& cell, std::int64_t target, std::uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0x5bd1e995u);
  const Plane3 pl = plane_of({tri[0], tri[1], tri[2]});
  for (int attempt = 0; attempt < 64; ++attempt) {
    const RationalPoint3 q = random_interior_point(t_in, rng);
    for (int s : {+1, -1}) {
      Exact delta(1);
      for (int halving = 0; halving < 200; ++halving, delta = delta / 2) {
        const RationalPoint3 p = q + (Exact(s) * delta) * pl.normal;
        if (!in_closed_box(p, cell)) continue;
        if (segment_is_free(scene, cands, p, q, target)) return Witness{p, q};
      }
    }
  }
  return std::nullopt;
}

}  // namespace exactvis::region
