#include "skeleton/line_first_hit.hpp"

#include "kernel/ray_first_hit.hpp"
#include "kernel/rational_between.hpp"
#include "kernel/segment_triangle_intersection.hpp"

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <numeric>
#include <optional>

namespace exactvis {
namespace {

using R = RootNumber;
// Unprotected intervals: every arithmetic on them runs under a CGAL::Protect_FPU_rounding<true> of the
// function doing it (one rounding-mode switch per test instead of one per operation; same enclosures).
using I = Interval;
using IVec = std::array<I, 3>;

IVec enclose(const Vec3<R>& v) {
  IVec r;
  for (int k = 0; k < 3; ++k) {
    const auto p = CGAL::to_interval(v[k]);
    r[k] = I(p.first, p.second);
  }
  return r;
}
IVec enclose(const Point3& p) { return {I(p.x), I(p.y), I(p.z)}; }
IVec sub(const IVec& a, const IVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
IVec cross(const IVec& a, const IVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
I dot(const IVec& a, const IVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool certainly_positive(const I& x) { return x.inf() > 0; }
bool certainly_negative(const I& x) { return x.sup() < 0; }

// Interval filter of first_parameter (below): true only when the exact test is certain to find no point of
// the open ray {o + s d : s > 0} in the closed triangle (a, b, c) -- or, with `to` (= o + d), none with
// 0 < s < 1. It decides only rays crossing the plane (sign(n . d) certain): s = -n.(o - a) / n.d must be > 0
// (and < 1), and the crossing point's barycentric coordinate opposite c_k+2 has the sign of
// det[c_k - o, c_k+1 - o, d] times sign(n . d) (docs/theory.md section 6, "Maximal free segments"), so a
// certain opposite sign excludes it. Everything else (parallel, coplanar, ambiguous) returns false.
bool certainly_misses(const IVec& o, const IVec& d, const IVec* to, const Point3& a, const Point3& b,
                      const Point3& c) {
  CGAL::Protect_FPU_rounding<true> guard;
  const IVec ia = enclose(a), ib = enclose(b), ic = enclose(c);
  const IVec n = cross(sub(ib, ia), sub(ic, ia));
  const I h1 = dot(n, d);
  const bool up = certainly_positive(h1);
  if (!up && !certainly_negative(h1)) return false;
  const I h0 = dot(n, sub(o, ia));  // s = -h0 / h1 > 0 needs sign(h0) = -sign(h1)
  if (up ? certainly_positive(h0) : certainly_negative(h0)) return true;
  if (to) {  // s < 1 needs sign(n . (to - a)) = sign(h1)
    const I h = dot(n, sub(*to, ia));
    if (up ? certainly_negative(h) : certainly_positive(h)) return true;
  }
  const IVec* v[3] = {&ia, &ib, &ic};
  for (int k = 0; k < 3; ++k) {
    const I det = dot(cross(sub(*v[k], o), sub(*v[(k + 1) % 3], o)), d);
    if (up ? certainly_negative(det) : certainly_positive(det)) return true;
  }
  return false;
}

// A lower bound of every parameter first_parameter can return for the ray (o, d) and the triangle (a, b, c)
// (enclosures o, d): the crossing parameter's interval when the ray certainly crosses the plane, else 0 (its
// results are >= 0).
double parameter_lower_bound(const IVec& o, const IVec& d, const Point3& a, const Point3& b, const Point3& c) {
  CGAL::Protect_FPU_rounding<true> guard;
  const IVec ia = enclose(a);
  const IVec n = cross(sub(enclose(b), ia), sub(enclose(c), ia));
  const I h1 = dot(n, d);
  if (!certainly_positive(h1) && !certainly_negative(h1)) return 0;
  const I s = -dot(n, sub(o, ia)) / h1;
  return std::max(0.0, s.inf());
}

Vec3<R> lift(const Point3& p) { return {R(Exact(p.x)), R(Exact(p.y)), R(Exact(p.z))}; }

// The parameter interval {s : origin + s dir in closed T} as a homogeneous pair per bound; computed by
// clipping the line against T's plane (transversal) or T's three in-plane half-planes (coplanar).
// Returns the smallest s > 0 of that set (std::nullopt if none); s = 0 stands for "immediately after".
// With `to` (= o + d), only whether some point with 0 < s < 1 exists: then it returns some s in [0, 1)
// (crossings: 0, not the crossing parameter), else nullopt or a value >= 1.
std::optional<R> first_parameter(const Vec3<R>& o, const Vec3<R>& d, const Vec3<R>& a, const Vec3<R>& b,
                                 const Vec3<R>& c, const Vec3<R>* to = nullptr) {
  const Vec3<R> n = cross(b - a, c - a);
  const R h0 = dot(n, o - a), h1 = dot(n, d);
  const int s1 = CGAL::sign(h1);
  if (s1 != 0) {
    // Crossing at s = -h0 / h1 > 0 iff sign(h0) = -sign(h1); the crossing point is in T iff every
    // det[p - o, q - o, d] * sign(h1) >= 0 (the signs certainly_misses filters): signs only, so the
    // division and the crossing point are computed only for a hit.
    const int s0 = CGAL::sign(h0);
    if (s0 == 0 || s0 == s1) return std::nullopt;
    if (to && CGAL::sign(dot(n, *to - a)) != s1) return std::nullopt;  // s < 1 iff sign(n.(to - a)) = sign(h1)
    const Vec3<R>* v[3] = {&a, &b, &c};
    for (int k = 0; k < 3; ++k) {
      const int det = CGAL::sign(dot(cross(*v[k] - o, *v[(k + 1) % 3] - o), d));
      if (det != 0 && det != s1) return std::nullopt;
    }
    if (to) return R(0);  // met before `to`; callers with `to` only ask whether
    return -h0 / h1;
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

OpenSegmentTest::OpenSegmentTest(const Vec3<RootNumber>& from, const Vec3<RootNumber>& to) : from_(from), to_(to) {
  rational_ = rational_vector(from, &from_q_) && rational_vector(to, &to_q_);
  for (int k = 0; k < 3; ++k) {
    const auto f = CGAL::to_interval(from[k]), t = CGAL::to_interval(to[k]);
    lo_hi_from_[k] = {f.first, f.second};
    lo_hi_to_[k] = {t.first, t.second};
  }
}

bool OpenSegmentTest::meets(const Point3& a, const Point3& b, const Point3& c) const {
  // The interval filter first, for rational segments too: it rejects the triangles the segment passes by
  // (most of the candidates of a free segment) with no rational arithmetic.
  const IVec o{I(lo_hi_from_[0][0], lo_hi_from_[0][1]), I(lo_hi_from_[1][0], lo_hi_from_[1][1]),
               I(lo_hi_from_[2][0], lo_hi_from_[2][1])};
  const IVec q{I(lo_hi_to_[0][0], lo_hi_to_[0][1]), I(lo_hi_to_[1][0], lo_hi_to_[1][1]),
               I(lo_hi_to_[2][0], lo_hi_to_[2][1])};
  IVec d;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    d = sub(q, o);
  }
  if (certainly_misses(o, d, &q, a, b, c)) return false;
  if (rational_)  // the kernel's filtered exact test
    return open_segment_meets_closed_triangle(from_q_, to_q_, RationalPoint3{Exact(a.x), Exact(a.y), Exact(a.z)},
                                              RationalPoint3{Exact(b.x), Exact(b.y), Exact(b.z)},
                                              RationalPoint3{Exact(c.x), Exact(c.y), Exact(c.z)});
  // The first point of the ray from `from` through `to` in the triangle, before `to`.
  const auto s = first_parameter(from_, to_ - from_, lift(a), lift(b), lift(c), &to_);
  return s && *s < R(1);
}

bool open_segment_meets_triangle(const Vec3<RootNumber>& from, const Vec3<RootNumber>& to, const Point3& a,
                                 const Point3& b, const Point3& c) {
  return OpenSegmentTest(from, to).meets(a, b, c);
}

bool rational_vector(const Vec3<RootNumber>& v, Vec3<Exact>* out) {
  return root_number_rational(v.x, &out->x) && root_number_rational(v.y, &out->y) &&
         root_number_rational(v.z, &out->z);
}

std::int64_t line_first_hit(const Scene& scene, const TriangleIndex& index, const Box3& box,
                            const Vec3<RootNumber>& origin, const Vec3<RootNumber>& dir,
                            const RayOriginOnEdgeLine& origin_on) {
  Vec3<Exact> o, d;
  if (rational_vector(origin, &o) && rational_vector(dir, &d)) {
    const RayHit hit = ray_first_hit(scene, index, box, o, d, origin_on);
    return hit.triangle >= 0 ? scene.triangles[hit.triangle].id : -1;
  }
  // In Q(sqrt D): the candidates of the interval cover of the ray (kernel/ray_first_hit.hpp; every triangle
  // when no direction enclosure excludes 0), each rejected by the interval filter or decided exactly; in
  // index order, so ties go to the lowest index as before.
  if (box.empty()) return -1;
  RayEnclosure ray;
  for (int k = 0; k < 3; ++k) {
    ray.origin[k] = CGAL::to_interval(origin[k]);
    ray.dir[k] = CGAL::to_interval(dir[k]);
    ray.dir_sign[k] = sign_of(CGAL::sign(dir[k]));
  }
  std::optional<std::vector<std::int64_t>> cover = ray_cover_candidates(
      index, box, ray, [&](int k, double face) { return sign_of(CGAL::sign(R(Exact(face)) - origin[k])); });
  std::vector<std::int64_t> cand;
  if (cover) {
    cand = std::move(*cover);
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  } else {
    cand.resize(scene.triangles.size());
    std::iota(cand.begin(), cand.end(), std::int64_t{0});
  }
  // The survivors of the filter in order of a lower bound of their parameter (interval arithmetic), decided
  // exactly until that bound exceeds an upper bound of the best exact parameter: the triangles further along
  // the ray are never computed. The minimum of (s, index) is the same in any order.
  const IVec io = enclose(origin), id = enclose(dir);
  std::vector<std::pair<double, std::int64_t>> live;
  for (const std::int64_t ti : cand) {
    const SceneTriangle& t = scene.triangles[ti];
    const Point3 &a = scene.corner(t, 0), &b = scene.corner(t, 1), &c = scene.corner(t, 2);
    if (certainly_misses(io, id, nullptr, a, b, c)) continue;
    live.emplace_back(parameter_lower_bound(io, id, a, b, c), ti);
  }
  std::sort(live.begin(), live.end());
  std::optional<R> best;
  double best_hi = 0;
  std::int64_t best_ti = -1;
  for (const auto& [lo, ti] : live) {
    if (best && lo > best_hi) break;
    const SceneTriangle& t = scene.triangles[ti];
    const auto s = first_parameter(origin, dir, lift(scene.corner(t, 0)), lift(scene.corner(t, 1)),
                                   lift(scene.corner(t, 2)));
    if (!s) continue;
    if (!best || *s < *best || (ti < best_ti && *s == *best)) {
      best = s, best_ti = ti;
      best_hi = CGAL::to_interval(*best).second;
    }
  }
  return best_ti >= 0 ? scene.triangles[best_ti].id : -1;
}

}  // namespace exactvis
