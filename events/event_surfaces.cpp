#include "events/event_surfaces.hpp"

#include "events/eee_events.hpp"
#include "kernel/predicates.hpp"
#include "kernel/ray_first_hit.hpp"
#include "kernel/triangle_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace exactvis {
namespace {

Point3 approx(const Vec3<Exact>& p) { return {CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)}; }

// Where the ray origin + s dir (s >= 0) leaves the box (display only: doubles).
Point3 box_exit(const Box3& box, const Point3& o, const Point3& d) {
  double smax = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (d[k] > 0) smax = std::min(smax, (box.hi[k] - o[k]) / d[k]);
    if (d[k] < 0) smax = std::min(smax, (box.lo[k] - o[k]) / d[k]);
  }
  if (!std::isfinite(smax) || smax < 0) smax = 0;
  return {o[0] + smax * d[0], o[1] + smax * d[1], o[2] + smax * d[2]};
}

struct Context {
  const Scene& scene;
  TriangleIndex index;
  Box3 box;
};

// End of the maximal free segment on the ray from `origin` along `dir` (exact hit, double output).
Point3 free_end(const Context& c, const Vec3<Exact>& origin, const Vec3<Exact>& dir, std::int64_t* triangle) {
  const RayHit h = ray_first_hit(c.scene, c.index, c.box, origin, dir);
  *triangle = h.triangle;
  if (h.triangle >= 0) return approx(origin + h.s * dir);
  return box_exit(c.box, approx(origin), approx(dir));
}

// Rational parameters across [t0, t1]: t0 + (t1 - t0) k / n, with irrational ends replaced by rationals inside.
std::vector<Exact> rational_samples(const Exact& t0, const Exact& t1, int n) {
  std::vector<Exact> out;
  for (int k = 0; k <= n; ++k) out.push_back(t0 + (t1 - t0) * Exact(k) / Exact(n));
  return out;
}

std::vector<Exact> samples(const RootNumber& t0, const RootNumber& t1, int n) {
  auto inside = [&](const RootNumber& end, bool lower) {
    if (!end.is_extended() || CGAL::is_zero(end.a1())) return end.a0();
    // A rational near the end, moved towards the interior until it is inside (exact comparisons).
    const double w = CGAL::to_double(t1) - CGAL::to_double(t0);
    for (double f = 1e-9; f < 1; f *= 16) {
      const Exact q(CGAL::to_double(end) + (lower ? f : -f) * w);
      if (RootNumber(q) > t0 && RootNumber(q) < t1) return q;
    }
    return (Exact(CGAL::to_double(t0)) + Exact(CGAL::to_double(t1))) / 2;
  };
  return rational_samples(inside(t0, true), inside(t1, false), n);
}

}  // namespace

std::vector<EventSurface> event_surfaces(const Scene& scene, const EvResult& ev, const EeeResult& eee,
                                         int samples_per_interval) {
  const Context c{scene, TriangleIndex(scene), bounding_box(scene)};
  const int n = std::max(1, samples_per_interval);
  std::vector<EventSurface> out;
  for (std::size_t ei = 0; ei < ev.events.size(); ++ei) {
    const auto& e = ev.events[ei];
    const Vec3<Exact> V = to_rational(scene.vertices[e.vertex]);
    for (std::size_t ii = 0; ii < e.intervals.size(); ++ii) {
      const auto& iv = e.intervals[ii];
      EventSurface surface{EventSurface::Kind::EV, ei, ii, {}};
      for (const Exact& t : samples(iv.t0, iv.t1, n)) {
        const Vec3<Exact> p = ev_edge_point(scene, e.edge, t);
        const Vec3<Exact> d = p - V;
        SurfaceSample s;
        s.t = t;
        s.back = free_end(c, V, -d, &s.back_triangle);
        s.front = free_end(c, p, d, &s.front_triangle);
        surface.samples.push_back(std::move(s));
      }
      out.push_back(std::move(surface));
    }
  }
  for (std::size_t ei = 0; ei < eee.events.size(); ++ei) {
    const auto& e = eee.events[ei];
    for (std::size_t ii = 0; ii < e.intervals.size(); ++ii) {
      const auto& iv = e.intervals[ii];
      EventSurface surface{EventSurface::Kind::EEE, ei, ii, {}};
      for (const Exact& t : samples(iv.t0, iv.t1, n)) {
        const auto g = eee_generator_segment(scene, e, t);
        if (!g) continue;  // singular parameter (not inside a free interval; defensive)
        SurfaceSample s;
        s.t = t;
        s.back = free_end(c, g->back, -g->direction, &s.back_triangle);
        s.front = free_end(c, g->front, g->direction, &s.front_triangle);
        surface.samples.push_back(std::move(s));
      }
      out.push_back(std::move(surface));
    }
  }
  return out;
}

}  // namespace exactvis
