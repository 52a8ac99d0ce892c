#include "kernel/ray_first_hit.hpp"

#include "kernel/filtered_predicate.hpp"
#include "kernel/predicates.hpp"

#include <CGAL/Gmpzf.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

namespace exactvis {
namespace {
constexpr int kCoverPieces = 32;  // boxes covering a ray inside the scene box (candidate query)

// The box's face coordinate on axis k (hi when `upper`).
double box_face(const Box3& box, int k, bool upper) {
  const Point3& p = upper ? box.hi : box.lo;
  return k == 0 ? p.x : k == 1 ? p.y : p.z;
}

void set_box_axis(Box3& b, int k, double lo, double hi) {
  (k == 0 ? b.lo.x : k == 1 ? b.lo.y : b.lo.z) = lo;
  (k == 0 ? b.hi.x : k == 1 ? b.hi.y : b.hi.z) = hi;
}


using ExactFloat = CGAL::Gmpzf;  // exact +, -, * on integer mantissas with a binary exponent: no gcd

// A rational vector as w * v = P with P integer and w > 0 the lcm of v's denominators (exact).
struct HomogeneousVector {
  Vec3<ExactFloat> p;
  ExactFloat w;
};

HomogeneousVector homogeneous(const Vec3<Exact>& v) {
  mpz_t w, f;
  mpz_init_set_ui(w, 1);
  mpz_init(f);
  for (int k = 0; k < 3; ++k) mpz_lcm(w, w, mpq_denref(v[k].mpq()));
  HomogeneousVector h;
  for (int k = 0; k < 3; ++k) {
    mpz_divexact(f, w, mpq_denref(v[k].mpq()));
    mpz_mul(f, f, mpq_numref(v[k].mpq()));
    h.p[k] = ExactFloat(f);
  }
  h.w = ExactFloat(w);
  mpz_clear(f);
  mpz_clear(w);
  return h;
}

// The ray's origin and direction (exact) with their enclosures, computed once per ray for layers 1 and 2,
// and (on first use) their homogeneous integer forms for layer 3. Every predicate below is a sign of a
// polynomial homogeneous of some degree in the differences (point - origin) and in the direction, so it
// keeps its sign when those are multiplied by the positive w_o and w_d: layer 3 evaluates it in ExactFloat
// on w_o p - P_o and P_d (integers times powers of two), without rationals.
struct RayInput {
  const Vec3<Exact>& o;
  const Vec3<Exact>& d;
  std::array<std::pair<double, double>, 3> oi, di;
  mutable std::optional<HomogeneousVector> ho, hd;
  // The origin as doubles when it is exactly representable (rays from scene vertices): then signs that
  // depend only on the origin and the scene's doubles go through the kernel's double predicates.
  std::optional<Point3> o_double;
  RayOriginOnEdgeLine on_edge;  // the origin lies on this edge's line (known by construction)
  RayInput(const Vec3<Exact>& origin, const Vec3<Exact>& dir, const RayOriginOnEdgeLine& origin_on = {})
      : o(origin), d(dir), on_edge(origin_on) {
    for (int k = 0; k < 3; ++k) oi[k] = enclosing_interval(o[k]), di[k] = enclosing_interval(d[k]);
    // A one-point enclosure [x, x] of a rational means it equals the double x.
    if (oi[0].first == oi[0].second && oi[1].first == oi[1].second && oi[2].first == oi[2].second)
      o_double = Point3{oi[0].first, oi[1].first, oi[2].first};
  }
  // p - origin (layers 1 and 2), or w_o (p - origin) (layer 3).
  template <class NT>
  Vec3<NT> from_origin(const Point3& p) const {
    if constexpr (std::is_same_v<NT, ExactFloat>) {
      if (!ho) ho = homogeneous(o);
      return Vec3<NT>(ho->w * NT(p.x), ho->w * NT(p.y), ho->w * NT(p.z)) - ho->p;
    } else {
      return point_as<NT>(p) - Vec3<NT>(NT(oi[0]), NT(oi[1]), NT(oi[2]));
    }
  }
  // The direction (layers 1 and 2), or w_d times it (layer 3).
  template <class NT>
  Vec3<NT> direction() const {
    if constexpr (std::is_same_v<NT, ExactFloat>) {
      if (!hd) hd = homogeneous(d);
      return hd->p;
    } else {
      return {NT(di[0]), NT(di[1]), NT(di[2])};
    }
  }
};

template <class NT>
Vec3<NT> corner_as(const Scene& scene, const SceneTriangle& t, int k) {
  return point_as<NT>(scene.corner(t, k));
}

template <class NT>
Vec3<NT> normal_as(const Scene& scene, const SceneTriangle& t) {
  const Vec3<NT> a = corner_as<NT>(scene, t, 0);
  return cross(corner_as<NT>(scene, t, 1) - a, corner_as<NT>(scene, t, 2) - a);
}

// Named, counted predicates of the ray against triangle t with normal n = (t1 - t0) x (t2 - t0)
// (docs/theory.md section 1, counters; section 6, "Maximal free segments").

// sign(n . d): zero iff the ray is parallel to t's plane.
Sign plane_dir_sign(const RayInput& r, const Scene& scene, const SceneTriangle& t) {
  static PredicateCounter counter("ray_plane_dir");
  return filtered_sign<ExactFloat>(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    return dot(normal_as<NT>(scene, t), r.direction<NT>());
  });
}

// sign(n . (t0 - o)): the side of t's plane the origin lies on (negated); the hit parameter is
// s = n . (t0 - o) / n . d.
Sign plane_offset_sign(const RayInput& r, const Scene& scene, const SceneTriangle& t) {
  // n . (t0 - o) = det[t1 - t0, t2 - t0, t0 - o] = -orient3d(t0, t1, t2, o): for a double origin the kernel's
  // orient3d (semi-static filter, then Mpzf) decides it, cheaply also when it is zero (o on t's plane, as for
  // every triangle at the vertex a ray starts from).
  if (r.o_double) return -orient3d(scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2), *r.o_double);
  // A triangle through the origin's edge line holds that line, hence the origin, in its plane.
  if (r.on_edge.a >= 0) {
    auto has = [&](int v) { return t.v[0] == v || t.v[1] == v || t.v[2] == v; };
    if (has(r.on_edge.a) && has(r.on_edge.b)) return Sign::Zero;
  }
  static PredicateCounter counter("ray_plane_offset");
  auto expr = [&](auto nt) {
    using NT = typename decltype(nt)::type;
    return dot(normal_as<NT>(scene, t), r.from_origin<NT>(scene.corner(t, 0)));
  };
  // Layer 1: the expression in BoundedDouble; where it cannot decide and the origin lies on a known edge
  // line, that line lies in t's plane (both its vertices do, by the kernel's orient3d on doubles) when the
  // offset is a structural zero, as for coplanar walls and ground triangles along the edge.
  return filtered_sign_with<ExactFloat>(
      counter,
      [&]() -> std::optional<Sign> {
        if (const auto s = expr(NumberTag<BoundedDouble>{}).certified_sign()) return s;
        if (r.on_edge.a < 0) return std::nullopt;
        const Point3 &t0 = scene.corner(t, 0), &t1 = scene.corner(t, 1), &t2 = scene.corner(t, 2);
        if (orient3d(t0, t1, t2, scene.vertices[r.on_edge.a]) == Sign::Zero &&
            orient3d(t0, t1, t2, scene.vertices[r.on_edge.b]) == Sign::Zero)
          return Sign::Zero;
        return std::nullopt;
      },
      expr);
}

// sign(det[t_k - o, t_k+1 - o, d]). For a ray not parallel to the plane it equals sign(n . d) times the sign
// of the barycentric coordinate, opposite t_k+2, of the point where the ray's line meets the plane.
Sign edge_side_sign(const RayInput& r, const Scene& scene, const SceneTriangle& t, int k) {
  static PredicateCounter counter("ray_edge_side");
  return filtered_sign<ExactFloat>(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    return dot(cross(r.from_origin<NT>(scene.corner(t, k)), r.from_origin<NT>(scene.corner(t, (k + 1) % 3))),
               r.direction<NT>());
  });
}

// For t coplanar with the ray, edge k = t_k+1 - t_k: `of_direction` false gives sign(((e x (o - t_k)) . n),
// the origin's side of the edge's line in the plane; true gives sign((e x d) . n), the direction's.
Sign coplanar_edge_sign(const RayInput& r, const Scene& scene, const SceneTriangle& t, int k, bool of_direction) {
  static PredicateCounter counter("ray_coplanar_edge");
  return filtered_sign<ExactFloat>(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    const Vec3<NT> e = corner_as<NT>(scene, t, (k + 1) % 3) - corner_as<NT>(scene, t, k);
    const Vec3<NT> v = of_direction ? r.direction<NT>() : -r.from_origin<NT>(scene.corner(t, k));
    return dot(cross(e, v), normal_as<NT>(scene, t));
  });
}

// sign(s_t - s_u) times sign(nd_t nd_u), s = no / nd, from no_t nd_u - no_u nd_t (no division).
Sign hit_order_sign(const RayInput& r, const Scene& scene, const SceneTriangle& t, const SceneTriangle& u) {
  static PredicateCounter counter("ray_hit_order");
  return filtered_sign<ExactFloat>(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    const Vec3<NT> d = r.direction<NT>();
    const Vec3<NT> nt_ = normal_as<NT>(scene, t), nu = normal_as<NT>(scene, u);
    return dot(nt_, r.from_origin<NT>(scene.corner(t, 0))) * dot(nu, d) -
           dot(nu, r.from_origin<NT>(scene.corner(u, 0))) * dot(nt_, d);
  });
}

// A triangle the ray's line crosses (not parallel to the plane) at s > 0 inside the closed triangle.
struct Crossing {
  std::int64_t triangle;
  Sign nd;  // sign(n . d)
};

// Does the open ray cross t (not parallel)? Decided by the predicates only, nothing constructed.
std::optional<Crossing> crossing(const RayInput& r, const Scene& scene, std::int64_t ti, Sign nd) {
  const SceneTriangle& t = scene.triangles[ti];
  if (plane_offset_sign(r, scene, t) != nd) return std::nullopt;  // s <= 0
  const Sign opposite = nd == Sign::Positive ? Sign::Negative : Sign::Positive;
  for (int k = 0; k < 3; ++k)
    if (edge_side_sign(r, scene, t, k) == opposite) return std::nullopt;  // outside edge k's side
  return Crossing{ti, nd};
}

// For t coplanar with the ray: the smallest s > 0, or the infimum 0 if the closed triangle contains the
// origin, where the ray meets t; nullopt if it does not. The signs are predicates; the entry and exit
// parameters -f0 / f1 are exact rationals compared exactly.
std::optional<Exact> coplanar_hit(const RayInput& r, const Scene& scene, const SceneTriangle& t) {
  const RationalPoint3 c[3] = {to_rational(scene.corner(t, 0)), to_rational(scene.corner(t, 1)),
                               to_rational(scene.corner(t, 2))};
  const Vec3<Exact> n = cross(c[1] - c[0], c[2] - c[0]);
  std::optional<Exact> lo, hi;
  for (int k = 0; k < 3; ++k) {
    const Sign s1 = coplanar_edge_sign(r, scene, t, k, true);
    if (s1 == Sign::Zero) {
      if (coplanar_edge_sign(r, scene, t, k, false) == Sign::Negative) return std::nullopt;
      continue;
    }
    const Vec3<Exact> e = c[(k + 1) % 3] - c[k];
    const Exact rk = -dot(cross(e, r.o - c[k]), n) / dot(cross(e, r.d), n);
    if (s1 == Sign::Positive) {
      if (!lo || rk > *lo) lo = rk;
    } else {
      if (!hi || rk < *hi) hi = rk;
    }
  }
  const Exact entry = (lo && exact_sign(*lo) == Sign::Positive) ? *lo : Exact(0);
  if (hi && (*hi < entry || exact_sign(*hi) != Sign::Positive)) return std::nullopt;
  return entry;
}

// Candidates of the exact path: triangles whose boxes meet one of 32 outward-rounded boxes covering the ray
// inside the box, the exit parameter constructed exactly. Used when the interval path below cannot bound
// the exit (direction components too small for their enclosures to exclude 0). nullopt: the ray leaves the
// box at once (no hit).
std::optional<std::vector<std::int64_t>> exact_cover_candidates(const TriangleIndex& index, const Box3& box,
                                                                const Vec3<Exact>& origin, const Vec3<Exact>& dir) {
  std::optional<Exact> exit;
  for (int k = 0; k < 3; ++k) {
    const Sign sd = exact_sign(dir[k]);
    if (sd == Sign::Zero) continue;
    const Exact s = (Exact(box_face(box, k, sd == Sign::Positive)) - origin[k]) / dir[k];
    if (!exit || s < *exit) exit = s;
  }
  if (!exit || exact_sign(*exit) != Sign::Positive) return std::nullopt;
  std::vector<std::int64_t> cand;
  for (int i = 0; i < kCoverPieces; ++i) {
    const Vec3<Exact> p = origin + (*exit * Exact(i, kCoverPieces)) * dir;
    const Vec3<Exact> q = origin + (*exit * Exact(i + 1, kCoverPieces)) * dir;
    Box3 b;
    for (int k = 0; k < 3; ++k) {
      const auto ip = CGAL::to_interval(p[k]), iq = CGAL::to_interval(q[k]);
      set_box_axis(b, k, std::min(ip.first, iq.first), std::max(ip.second, iq.second));
    }
    const auto c = index.candidates_in_box(b);
    cand.insert(cand.end(), c.begin(), c.end());
  }
  return cand;
}

}  // namespace

std::optional<std::vector<std::int64_t>> ray_cover_candidates(const TriangleIndex& index, const Box3& box,
                                                              const RayEnclosure& ray,
                                                              const std::function<Sign(int, double)>& gap_sign) {
  using I = CGAL::Interval_nt<>;
  std::array<I, 3> o, d;
  for (int k = 0; k < 3; ++k) {
    o[k] = I(ray.origin[k].first, ray.origin[k].second);
    d[k] = I(ray.dir[k].first, ray.dir[k].second);
  }
  double exit_hi = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const Sign sd = ray.dir_sign[k];
    if (sd == Sign::Zero) continue;
    const double face = box_face(box, k, sd == Sign::Positive);
    // sign(face - o_k) must equal sign(d_k), else exit <= 0.
    const I gap = I(face) - o[k];
    Sign sg;
    if (gap.inf() > 0) sg = Sign::Positive;
    else if (gap.sup() < 0) sg = Sign::Negative;
    else sg = gap_sign(k, face);
    if (sg != sd) return std::vector<std::int64_t>{};
    if (d[k].inf() > 0 || d[k].sup() < 0) exit_hi = std::min(exit_hi, (gap / d[k]).sup());
  }
  if (!std::isfinite(exit_hi)) return std::nullopt;
  std::vector<std::int64_t> cand;
  const I s_hi(exit_hi);
  std::array<I, 3> prev = o;
  for (int i = 1; i <= kCoverPieces; ++i) {
    const I s = s_hi * I(double(i) / kCoverPieces);  // i / 32 is exact in binary
    Box3 b;
    std::array<I, 3> cur;
    for (int k = 0; k < 3; ++k) {
      cur[k] = o[k] + s * d[k];
      set_box_axis(b, k, std::min(prev[k].inf(), cur[k].inf()), std::max(prev[k].sup(), cur[k].sup()));
    }
    if (!std::isfinite(b.lo.x) || !std::isfinite(b.lo.y) || !std::isfinite(b.lo.z) || !std::isfinite(b.hi.x) ||
        !std::isfinite(b.hi.y) || !std::isfinite(b.hi.z))
      return std::nullopt;
    const auto c = index.candidates_in_box(b);
    cand.insert(cand.end(), c.begin(), c.end());
    prev = cur;
  }
  return cand;
}

namespace {

// The cover of a rational ray from its interval enclosures (ray_cover_candidates; no rational constructed,
// the exact signs of face_k - o_k only where their intervals cannot decide).
std::optional<std::vector<std::int64_t>> interval_cover_candidates(const TriangleIndex& index, const Box3& box,
                                                                   const Vec3<Exact>& origin, const Vec3<Exact>& dir) {
  RayEnclosure ray;
  for (int k = 0; k < 3; ++k) {
    ray.origin[k] = enclosing_interval(origin[k]);
    ray.dir[k] = enclosing_interval(dir[k]);
    ray.dir_sign[k] = exact_sign(dir[k]);
  }
  return ray_cover_candidates(index, box, ray,
                              [&](int k, double face) { return exact_sign(Exact(face) - origin[k]); });
}

}  // namespace

RayHit ray_first_hit(const Scene& scene, const TriangleIndex& index, const Box3& box, const Vec3<Exact>& origin,
                     const Vec3<Exact>& dir, const RayOriginOnEdgeLine& origin_on) {
  RayHit best;
  if (box.empty()) return best;
  // Candidates: triangles whose boxes meet the boxes covering the ray inside the scene box (from interval
  // enclosures; the exact construction only when those cannot bound the exit). Both cover every triangle
  // the open ray can hit, so the result does not depend on which path ran.
  std::optional<std::vector<std::int64_t>> cover = interval_cover_candidates(index, box, origin, dir);
  if (!cover) cover = exact_cover_candidates(index, box, origin, dir);
  if (!cover || cover->empty()) return best;
  std::vector<std::int64_t>& cand = *cover;
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  // Every candidate is decided by the counted predicates above; among the crossed triangles the nearest is
  // found by comparing hit parameters without constructing them (ties: the lowest index, as the candidates
  // are in index order), and only the winner's parameter is constructed. Coplanar triangles (rare) construct
  // their entry parameter exactly.
  const RayInput r(origin, dir, origin_on);
  std::optional<Crossing> nearest;
  std::vector<std::pair<std::int64_t, Exact>> coplanar;
  for (const std::int64_t ti : cand) {
    const SceneTriangle& t = scene.triangles[ti];
    const Sign nd = plane_dir_sign(r, scene, t);
    if (nd == Sign::Zero) {
      if (plane_offset_sign(r, scene, t) != Sign::Zero) continue;  // parallel, off the plane
      if (auto s = coplanar_hit(r, scene, t)) coplanar.emplace_back(ti, std::move(*s));
      continue;
    }
    const auto c = crossing(r, scene, ti, nd);
    if (!c) continue;
    // s_c < s_nearest iff order * nd_c * nd_nearest < 0
    if (!nearest ||
        hit_order_sign(r, scene, t, scene.triangles[nearest->triangle]) * c->nd * nearest->nd == Sign::Negative)
      nearest = c;
  }
  if (nearest) {
    const RationalPoint3 a = to_rational(scene.corner(scene.triangles[nearest->triangle], 0));
    const RationalPoint3 b = to_rational(scene.corner(scene.triangles[nearest->triangle], 1));
    const RationalPoint3 c = to_rational(scene.corner(scene.triangles[nearest->triangle], 2));
    const Vec3<Exact> n = cross(b - a, c - a);
    best = {static_cast<int>(nearest->triangle), dot(n, a - origin) / dot(n, dir)};
  }
  for (auto& [ti, s] : coplanar)
    if (best.triangle < 0 || s < best.s || (s == best.s && ti < best.triangle)) best = {static_cast<int>(ti), s};
  return best;
}

}  // namespace exactvis
