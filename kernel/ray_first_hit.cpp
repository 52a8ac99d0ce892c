#include "kernel/ray_first_hit.hpp"

#include "kernel/predicates.hpp"

#include <algorithm>
#include <optional>

namespace exactvis {
namespace {

// Smallest s > 0 (or the infimum 0 for a coplanar triangle containing the origin) where the ray meets the
// closed triangle; nullopt if it does not.
std::optional<Exact> hit_parameter(const Vec3<Exact>& o, const Vec3<Exact>& d, const std::array<Vec3<Exact>, 3>& t) {
  const Vec3<Exact> n = cross(t[1] - t[0], t[2] - t[0]);
  const Exact nd = dot(n, d), no = dot(n, t[0] - o);
  if (CGAL::sign(nd) != 0) {
    const Exact s = no / nd;
    if (CGAL::sign(s) <= 0) return std::nullopt;
    const Vec3<Exact> x = o + s * d;
    for (int k = 0; k < 3; ++k)
      if (CGAL::sign(dot(cross(t[(k + 1) % 3] - t[k], x - t[k]), n)) < 0) return std::nullopt;
    return s;
  }
  if (CGAL::sign(no) != 0) return std::nullopt;  // parallel, off the plane
  // Coplanar: s in [lo, hi] from the three closed half-planes, intersected with s > 0.
  std::optional<Exact> lo, hi;
  for (int k = 0; k < 3; ++k) {
    const Vec3<Exact> e = t[(k + 1) % 3] - t[k];
    const Exact f0 = dot(cross(e, o - t[k]), n), f1 = dot(cross(e, d), n);
    if (CGAL::sign(f1) == 0) {
      if (CGAL::sign(f0) < 0) return std::nullopt;
      continue;
    }
    const Exact r = -f0 / f1;
    if (CGAL::sign(f1) > 0) {
      if (!lo || r > *lo) lo = r;
    } else {
      if (!hi || r < *hi) hi = r;
    }
  }
  const Exact entry = (lo && CGAL::sign(*lo) > 0) ? *lo : Exact(0);
  if (hi && (*hi < entry || CGAL::sign(*hi) <= 0)) return std::nullopt;
  return entry;
}

}  // namespace

RayHit ray_first_hit(const Scene& scene, const TriangleIndex& index, const Box3& box, const Vec3<Exact>& origin,
                     const Vec3<Exact>& dir) {
  RayHit best;
  if (box.empty()) return best;
  // Exit parameter from the scene box.
  std::optional<Exact> exit;
  for (int k = 0; k < 3; ++k) {
    const int sd = CGAL::sign(dir[k]);
    if (sd == 0) continue;
    const double face = sd > 0 ? (k == 0 ? box.hi.x : k == 1 ? box.hi.y : box.hi.z)
                               : (k == 0 ? box.lo.x : k == 1 ? box.lo.y : box.lo.z);
    const Exact s = (Exact(face) - origin[k]) / dir[k];
    if (!exit || s < *exit) exit = s;
  }
  if (!exit || CGAL::sign(*exit) <= 0) return best;
  // Candidates: triangles whose boxes meet one of 32 outward-rounded boxes covering the ray inside the box.
  std::vector<std::int64_t> cand;
  const int pieces = 32;
  for (int i = 0; i < pieces; ++i) {
    const Vec3<Exact> p = origin + (*exit * Exact(i, pieces)) * dir;
    const Vec3<Exact> q = origin + (*exit * Exact(i + 1, pieces)) * dir;
    Box3 b;
    for (int k = 0; k < 3; ++k) {
      const auto ip = CGAL::to_interval(p[k]), iq = CGAL::to_interval(q[k]);
      const double lo = std::min(ip.first, iq.first), hi = std::max(ip.second, iq.second);
      (k == 0 ? b.lo.x : k == 1 ? b.lo.y : b.lo.z) = lo;
      (k == 0 ? b.hi.x : k == 1 ? b.hi.y : b.hi.z) = hi;
    }
    const auto c = index.candidates_in_box(b);
    cand.insert(cand.end(), c.begin(), c.end());
  }
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  // Interval filter: a candidate is certainly missed if a sign is certainly wrong; the rest are tested
  // exactly in order of their interval lower bound, stopping once that bound exceeds the best exact hit.
  std::vector<std::pair<double, std::int64_t>> maybe;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    auto iv = [](const Point3& q) { return Vec3<Interval>(Interval(q.x), Interval(q.y), Interval(q.z)); };
    const Vec3<Interval> o(CGAL::to_interval(origin.x), CGAL::to_interval(origin.y), CGAL::to_interval(origin.z));
    const Vec3<Interval> d(CGAL::to_interval(dir.x), CGAL::to_interval(dir.y), CGAL::to_interval(dir.z));
    for (const std::int64_t ti : cand) {
      const auto& t = scene.triangles[ti];
      const Vec3<Interval> a = iv(scene.corner(t, 0)), b = iv(scene.corner(t, 1)), c = iv(scene.corner(t, 2));
      const Vec3<Interval> n = cross(b - a, c - a);
      const Interval nd = dot(n, d), no = dot(n, a - o);
      double lower = 0;  // lower bound of the hit parameter
      if (nd.inf() > 0 || nd.sup() < 0) {
        const Interval si = no / nd;
        if (si.sup() <= 0) continue;  // certainly s <= 0
        const Vec3<Interval> x = o + si * d;
        bool out = false;
        const Vec3<Interval> tri[3] = {a, b, c};
        for (int k = 0; k < 3 && !out; ++k)
          out = dot(cross(tri[(k + 1) % 3] - tri[k], x - tri[k]), n).sup() < 0;
        if (out) continue;
        lower = std::max(0.0, si.inf());
      } else if (no.inf() > 0 || no.sup() < 0) {
        if (nd.inf() == 0 && nd.sup() == 0) continue;  // exactly parallel and off the plane
      }
      maybe.emplace_back(lower, ti);
    }
  }
  std::sort(maybe.begin(), maybe.end());
  for (const auto& [lower, ti] : maybe) {
    if (best.triangle >= 0 && Exact(lower) > best.s) break;
    const auto& t = scene.triangles[ti];
    const auto s = hit_parameter(origin, dir,
                                 {to_rational(scene.corner(t, 0)), to_rational(scene.corner(t, 1)),
                                  to_rational(scene.corner(t, 2))});
    if (!s) continue;
    if (best.triangle < 0 || *s < best.s || (*s == best.s && ti < best.triangle)) best = {static_cast<int>(ti), *s};
  }
  return best;
}

}  // namespace exactvis
