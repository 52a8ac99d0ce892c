#include "events/ev_pencil_filter.hpp"

#include "kernel/filtered_predicate.hpp"
#include "kernel/predicate_counters.hpp"
#include "kernel/predicates.hpp"

#include <CGAL/FPU.h>

namespace exactvis {
namespace {

using I = CGAL::Interval_nt<false>;  // arithmetic only under CGAL::Protect_FPU_rounding<true>
using IVec = std::array<I, 3>;

IVec diff(const Point3& p, const Point3& o) { return {I(p.x) - I(o.x), I(p.y) - I(o.y), I(p.z) - I(o.z)}; }
IVec icross(const IVec& u, const IVec& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
I idot(const IVec& u, const IVec& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

// +1 / -1 when the interval is certainly positive / negative, 0 when not certain.
int certain_sign(const I& x) { return x.inf() > 0 ? 1 : (x.sup() < 0 ? -1 : 0); }

// The common certain sign of (g0, g1) at one point: +1 (in R+), -1 (in R-), 0 (not proved).
int region_of(const I& g0, const I& g1) {
  const int s0 = certain_sign(g0), s1 = certain_sign(g1);
  return s0 != 0 && s0 == s1 ? s0 : 0;
}

PredicateCounter& counter() {
  static PredicateCounter c("ev_pencil_misses");
  return c;
}

bool counted(bool proved) {
  std::atomic<std::uint64_t>* counts = counter().thread_counts();
  detail::bump(counts[0]);
  detail::bump(counts[1 + static_cast<int>(proved ? FilterLayer::Interval : FilterLayer::Exact)]);
  return proved;
}

}  // namespace

// A point's exact side of P (sign of f = (p - V) . n) and enclosures of f, g_t0, g_t1.
struct EvPencilRange::PointData {
  int o = 0;
  I f, g0, g1;
};

EvPencilRange::EvPencilRange(const Point3& v, const Point3& a, const Point3& b, double t0_lo, double t0_hi,
                             double t1_lo, double t1_hi)
    : v_(v), a_(a), b_(b) {
  CGAL::Protect_FPU_rounding<true> guard;
  const IVec av = diff(a, v), bv = diff(b, v);
  n_ = icross(av, bv);
  const IVec cb = icross(n_, av), ca = icross(bv, n_);  // beta's and alpha's gradients (scaled by |n|^2)
  const I t0(t0_lo, t0_hi), t1(t1_lo, t1_hi);
  for (int k = 0; k < 3; ++k) {
    w0_[k] = (I(1) - t0) * cb[k] - t0 * ca[k];
    w1_[k] = (I(1) - t1) * cb[k] - t1 * ca[k];
  }
}

EvPencilRange::PointData EvPencilRange::point_data(const Point3& p) const {
  PointData d;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const IVec x = diff(p, v_);
    d.f = idot(x, n_), d.g0 = idot(x, w0_), d.g1 = idot(x, w1_);
    d.o = certain_sign(d.f);
  }
  // Exact (filtered; outside the rounding-mode guard, which its double filter must not run under) when the
  // enclosure is not certain.
  if (d.o == 0) d.o = to_int(orient3d(v_, a_, b_, p));
  return d;
}

bool EvPencilRange::section_misses(const PointData* c[3]) const {
  const int o[3] = {c[0]->o, c[1]->o, c[2]->o};
  if ((o[0] > 0 && o[1] > 0 && o[2] > 0) || (o[0] < 0 && o[1] < 0 && o[2] < 0)) return true;
  const bool coplanar = o[0] == 0 && o[1] == 0 && o[2] == 0;
  CGAL::Protect_FPU_rounding<true> guard;
  int region = 0;  // common region of the section points so far
  auto add = [&](int s) {
    if (s == 0 || (region != 0 && s != region)) return false;
    region = s;
    return true;
  };
  for (int k = 0; k < 3; ++k) {
    if (o[k] == 0 || coplanar) {  // a corner in P
      if (!add(region_of(c[k]->g0, c[k]->g1))) return false;
    }
    const int j = (k + 1) % 3;
    if (!coplanar && o[k] * o[j] < 0) {
      // The crossing X = (f_k c_j - f_j c_k) / (f_k - f_j): g(X) = (f_k g_j - f_j g_k) / (f_k - f_j), and
      // f_k - f_j has the sign o[k].
      const I h0 = c[k]->f * c[j]->g0 - c[j]->f * c[k]->g0, h1 = c[k]->f * c[j]->g1 - c[j]->f * c[k]->g1;
      if (!add(o[k] * region_of(h0, h1))) return false;
    }
  }
  return region != 0;
}

bool EvPencilRange::misses_triangle(const Point3& p, const Point3& q, const Point3& r) const {
  if (!filter_enabled()) return counted(false);
  const PointData d[3] = {point_data(p), point_data(q), point_data(r)};
  const PointData* c[3] = {&d[0], &d[1], &d[2]};
  return counted(section_misses(c));
}

bool EvPencilRange::misses_box(const Box3& box) const {
  if (!filter_enabled()) return false;
  CGAL::Protect_FPU_rounding<true> guard;
  int side = 2, region = 2;  // 2: no corner seen yet; 0: not proved
  for (int m = 0; m < 8; ++m) {
    const Point3 c{(m & 1) ? box.hi.x : box.lo.x, (m & 2) ? box.hi.y : box.lo.y, (m & 4) ? box.hi.z : box.lo.z};
    const IVec x = diff(c, v_);
    const int s = certain_sign(idot(x, n_));
    side = side == 2 ? s : (side == s ? side : 0);
    const int g = region_of(idot(x, w0_), idot(x, w1_));
    region = region == 2 ? g : (region == g ? region : 0);
    if (side == 0 && region == 0) return false;
  }
  return side != 0 || region != 0;
}

bool EvPencilRange::misses_side(const PencilSide& side) const {
  if (!filter_enabled()) return counted(false);
  if (misses_box(side.box)) return counted(true);
  thread_local std::vector<PointData> data;
  thread_local std::vector<char> done;
  data.resize(side.points.size());
  done.assign(side.points.size(), 0);
  for (const auto& t : side.triangles) {
    const PointData* c[3];
    for (int k = 0; k < 3; ++k) {
      if (!done[t[k]]) data[t[k]] = point_data(side.points[t[k]]), done[t[k]] = 1;
      c[k] = &data[t[k]];
    }
    if (!section_misses(c)) return counted(false);
  }
  return counted(true);
}

}  // namespace exactvis
