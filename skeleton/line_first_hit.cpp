#include "skeleton/line_first_hit.hpp"

#include "kernel/ray_first_hit.hpp"
#include "kernel/rational_between.hpp"
#include "kernel/segment_triangle_intersection.hpp"

#include <optional>

namespace exactvis {
namespace {

using R = RootNumber;

Vec3<R> lift(const Point3& p) { return {R(Exact(p.x)), R(Exact(p.y)), R(Exact(p.z))}; }

// The parameter interval {s : origin + s dir in closed T} as a homogeneous pair per bound; computed by
// clipping the line against T's plane (transversal) or T's three in-plane half-planes (coplanar).
// Returns the smallest s > 0 of that set (std::nullopt if none); s = 0 stands for "immediately after".
std::optional<R> first_parameter(const Vec3<R>& o, const Vec3<R>& d, const Vec3<R>& a, const Vec3<R>& b,
                                 const Vec3<R>& c) {
  const Vec3<R> n = cross(b - a, c - a);
  const R h0 = dot(n, o - a), h1 = dot(n, d);
  if (!CGAL::is_zero(h1)) {
    // Crossing at s = -h0 / h1, in T iff the point is inside every edge's half-plane.
    const R s = -h0 / h1;
    if (CGAL::sign(s) <= 0) return std::nullopt;
    const Vec3<R> x = o + s * d;
    const Vec3<R>* v[3] = {&a, &b, &c};
    for (int k = 0; k < 3; ++k) {
      const Vec3<R>& p = *v[k];
      const Vec3<R>& q = *v[(k + 1) % 3];
      if (CGAL::sign(dot(cross(q - p, x - p), n)) < 0) return std::nullopt;
    }
    return s;
  }
  if (!CGAL::is_zero(h0)) return std::nullopt;  // parallel to T's plane, off it
  // Coplanar: g_k(s) = ((q - p) x (o + s d - p)) . n >= 0 for each edge, linear in s.
  std::optional<R> lo, hi;
  const Vec3<R>* v[3] = {&a, &b, &c};
  for (int k = 0; k < 3; ++k) {
    const Vec3<R>& p = *v[k];
    const Vec3<R>& q = *v[(k + 1) % 3];
    const R g0 = dot(cross(q - p, o - p), n), g1 = dot(cross(q - p, d), n);
    if (CGAL::is_zero(g1)) {
      if (CGAL::sign(g0) < 0) return std::nullopt;
      continue;
    }
    const R root = -g0 / g1;
    if (CGAL::sign(g1) > 0) {
      if (!lo || *lo < root) lo = root;  // s >= root
    } else {
      if (!hi || root < *hi) hi = root;  // s <= root
    }
  }
  if (lo && hi && *hi < *lo) return std::nullopt;
  if (hi && CGAL::sign(*hi) <= 0) return std::nullopt;
  if (!lo || CGAL::sign(*lo) <= 0) return R(0);
  return *lo;
}

}  // namespace

bool open_segment_meets_triangle(const Vec3<RootNumber>& from, const Vec3<RootNumber>& to, const Point3& a,
                                 const Point3& b, const Point3& c) {
  Vec3<Exact> f, t;
  if (rational_vector(from, &f) && rational_vector(to, &t))  // the kernel's filtered exact test
    return open_segment_meets_closed_triangle(f, t, RationalPoint3{Exact(a.x), Exact(a.y), Exact(a.z)},
                                              RationalPoint3{Exact(b.x), Exact(b.y), Exact(b.z)},
                                              RationalPoint3{Exact(c.x), Exact(c.y), Exact(c.z)});
  // The first point of the ray from `from` through `to` in the triangle, before `to`.
  const auto s = first_parameter(from, to - from, lift(a), lift(b), lift(c));
  return s && *s < R(1);
}

bool rational_vector(const Vec3<RootNumber>& v, Vec3<Exact>* out) {
  return root_number_rational(v.x, &out->x) && root_number_rational(v.y, &out->y) &&
         root_number_rational(v.z, &out->z);
}

std::int64_t line_first_hit(const Scene& scene, const TriangleIndex& index, const Box3& box,
                            const Vec3<RootNumber>& origin, const Vec3<RootNumber>& dir) {
  Vec3<Exact> o, d;
  if (rational_vector(origin, &o) && rational_vector(dir, &d)) {
    const RayHit hit = ray_first_hit(scene, index, box, o, d);
    return hit.triangle >= 0 ? scene.triangles[hit.triangle].id : -1;
  }
  std::optional<R> best;
  std::int64_t best_id = -1;
  for (const SceneTriangle& t : scene.triangles) {
    const auto s = first_parameter(origin, dir, lift(scene.corner(t, 0)), lift(scene.corner(t, 1)),
                                   lift(scene.corner(t, 2)));
    if (s && (!best || *s < *best)) best = s, best_id = t.id;
  }
  return best_id;
}

}  // namespace exactvis
