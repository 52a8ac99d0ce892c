#include "events/eee_occluder_filter.hpp"

#include "kernel/filtered_predicate.hpp"
#include "kernel/predicate_counters.hpp"

#include <CGAL/FPU.h>

#include <algorithm>
#include <cmath>

namespace exactvis {
namespace {

using I = Interval;  // CGAL::Interval_nt<false>: only under Protect_FPU_rounding below

I dot_interval(const double n[3], const std::array<double, 6>& box) {
  I s(0);
  for (int k = 0; k < 3; ++k) s += I(n[k]) * I(box[k], box[3 + k]);
  return s;
}

}  // namespace

EeeOccluderFilter::EeeOccluderFilter(const std::array<Vec3<Exact>, 6>& h) {
  std::array<Vec3<double>, 6> p;
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 3; ++k) {
      const auto [lo, hi] = enclosing_interval(h[i][k]);
      box_[i][k] = lo;
      box_[i][3 + k] = hi;
      p[i][k] = 0.5 * (lo + hi);
    }
  // Proposals in plain doubles (any plane is fine: the offset below makes it correct).
  std::vector<std::array<double, 3>> normals;
  for (int a = 0; a < 6; ++a)
    for (int b = a + 1; b < 6; ++b)
      for (int c = b + 1; c < 6; ++c) {
        const Vec3<double> u = p[b] - p[a], v = p[c] - p[a];
        const Vec3<double> n = cross(u, v);
        const double len = std::sqrt(dot(n, n));
        if (!(len > 0) || !std::isfinite(len)) continue;
        const double scale = std::sqrt(dot(u, u) * dot(v, v));
        if (len <= 1e-12 * scale) continue;  // (nearly) collinear: no useful plane
        int pos = 0, neg = 0;
        for (int d = 0; d < 6; ++d) {
          const double s = dot(n, p[d] - p[a]) / len;
          const double tol = 1e-9 * std::sqrt(scale) + 1e-300;
          pos += s > tol;
          neg += s < -tol;
        }
        if (pos > 0 && neg > 0) continue;  // not a facet of the rounded hull
        if (pos == 0 && neg == 0) {        // flat hull: both sides are useful
          normals.push_back({n.x, n.y, n.z});
          normals.push_back({-n.x, -n.y, -n.z});
          continue;
        }
        if (pos > 0) normals.push_back({-n.x, -n.y, -n.z});  // outward: H on the non-positive side
        else normals.push_back({n.x, n.y, n.z});
      }
  CGAL::Protect_FPU_rounding<true> guard;
  for (const auto& n : normals) {
    Plane pl{{n[0], n[1], n[2]}, -HUGE_VAL};
    for (int i = 0; i < 6; ++i) pl.c = std::max(pl.c, dot_interval(pl.n, box_[i]).sup());
    if (std::isfinite(pl.c)) planes_.push_back(pl);
  }
}

bool EeeOccluderFilter::separated(const Point3& a, const Point3& b, const Point3& c) const {
  static PredicateCounter counter("eee_occluder_separated");
  std::atomic<std::uint64_t>* counts = counter.thread_counts();
  detail::bump(counts[0]);
  bool proved = false;
  if (filter_enabled()) {
    CGAL::Protect_FPU_rounding<true> guard;
    const Point3* t[3] = {&a, &b, &c};
    for (const Plane& pl : planes_) {
      bool beyond = true;
      for (int k = 0; k < 3 && beyond; ++k) {
        const I s = I(pl.n[0]) * I(t[k]->x) + I(pl.n[1]) * I(t[k]->y) + I(pl.n[2]) * I(t[k]->z) - I(pl.c);
        beyond = s.inf() > 0;
      }
      if (beyond) {
        proved = true;
        break;
      }
    }
    if (!proved) {
      // All of H strictly on one side of T's plane: (h - a) . ((b - a) x (c - a)).
      const I ux = I(b.x) - I(a.x), uy = I(b.y) - I(a.y), uz = I(b.z) - I(a.z);
      const I vx = I(c.x) - I(a.x), vy = I(c.y) - I(a.y), vz = I(c.z) - I(a.z);
      const I nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      int side = 0;
      proved = true;
      for (const auto& bx : box_) {
        const I s = (I(bx[0], bx[3]) - I(a.x)) * nx + (I(bx[1], bx[4]) - I(a.y)) * ny + (I(bx[2], bx[5]) - I(a.z)) * nz;
        const int sd = s.inf() > 0 ? 1 : (s.sup() < 0 ? -1 : 0);
        if (sd == 0 || (side != 0 && sd != side)) {
          proved = false;
          break;
        }
        side = sd;
      }
    }
  }
  detail::bump(counts[1 + static_cast<int>(proved ? FilterLayer::Interval : FilterLayer::Exact)]);
  return proved;
}

}  // namespace exactvis
