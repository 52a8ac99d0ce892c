#include "shadows/eee_interval_split.hpp"

#include "kernel/predicates.hpp"
#include "kernel/ray_first_hit.hpp"
#include "kernel/rational_between.hpp"
#include "util/sub_intervals.hpp"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace exactvis::shadows {
namespace {

using Poly = QuadraticPolynomial;
using I = CGAL::Interval_nt<>;

Exact rational_of(const RootNumber& x) {
  Exact q;
  if (!root_number_rational(x, &q)) throw std::logic_error("eee_line_polynomials: irrational value at rational t");
  return q;
}
Vec3<Exact> rational_of(const Vec3<RootNumber>& v) { return {rational_of(v.x), rational_of(v.y), rational_of(v.z)}; }

I interval_of(const Exact& x) {
  const auto p = CGAL::to_interval(x);
  return I(p.first, p.second);
}

// Interval coefficients of the line polynomials (for the root filter and the swept box).
struct IntervalLines {
  std::array<std::array<I, 3>, 3> d, m;  // [coordinate][power]
};
IntervalLines interval_lines(const EeeLinePolynomials& l) {
  IntervalLines r;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      r.d[k][j] = interval_of(l.d[k].c[j]);
      r.m[k][j] = interval_of(l.m[k].c[j]);
    }
  return r;
}

// The same coefficients and parameter ranges for may_vanish's unprotected interval arithmetic.
using IU = CGAL::Interval_nt<false>;  // needs the rounding mode set upward (CGAL::Protect_FPU_rounding)
struct VanishFilter {
  std::array<std::array<IU, 3>, 3> d, m;  // [coordinate][power]
  std::vector<IU> ranges;
};
VanishFilter vanish_filter(const IntervalLines& l, const std::vector<I>& ranges) {
  VanishFilter f;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      f.d[k][j] = IU(l.d[k][j].inf(), l.d[k][j].sup());
      f.m[k][j] = IU(l.m[k][j].inf(), l.m[k][j].sup());
    }
  for (const I& t : ranges) f.ranges.push_back(IU(t.inf(), t.sup()));
  return f;
}

// Can side(L(t), line(a, b)) vanish for some t in one of the ranges? Interval arithmetic only: `false` is a
// proof (the enclosure of the polynomial's values over each range excludes 0). One rounding-mode switch per
// call (the protected Interval_nt switched at every operation; the same intervals).
bool may_vanish(const VanishFilter& l, const Point3& a, const Point3& b) {
  CGAL::Protect_FPU_rounding<true> upward;
  const std::array<IU, 3> A{IU(a.x), IU(a.y), IU(a.z)}, B{IU(b.x), IU(b.y), IU(b.z)};
  const std::array<IU, 3> de{B[0] - A[0], B[1] - A[1], B[2] - A[2]};
  const std::array<IU, 3> me{A[1] * B[2] - A[2] * B[1], A[2] * B[0] - A[0] * B[2], A[0] * B[1] - A[1] * B[0]};
  std::array<IU, 3> c;
  for (int j = 0; j < 3; ++j) {
    c[j] = IU(0);
    for (int k = 0; k < 3; ++k) c[j] += l.d[k][j] * me[k] + de[k] * l.m[k][j];
  }
  for (const IU& t : l.ranges) {
    const IU v = c[0] + t * (c[1] + t * c[2]);
    if (v.inf() <= 0 && v.sup() >= 0) return true;
  }
  return false;
}

std::vector<I> parameter_ranges(const RootNumber& t0, const RootNumber& t1, int pieces) {
  const double lo = CGAL::to_interval(t0).first, hi = CGAL::to_interval(t1).second;
  std::vector<I> out;
  for (int k = 0; k < pieces; ++k) {
    const I a = I(lo) + (I(hi) - I(lo)) * I(k) / I(pieces);
    const I b = I(lo) + (I(hi) - I(lo)) * I(k + 1) / I(pieces);
    out.push_back(I(a.inf(), b.sup()));
  }
  return out;
}

}  // namespace

EeeLinePolynomials eee_line_polynomials(const Scene& scene, const EeeEvent& event) {
  const Exact ts[3] = {Exact(0), Exact(1, 2), Exact(1)};
  Vec3<Exact> d[3], p[3];
  for (int k = 0; k < 3; ++k) {
    const EeeLinePoints pts = eee_line_points(scene, event, RootNumber(ts[k]));
    d[k] = rational_of(pts.direction);
    p[k] = rational_of(pts.on_e1);
  }
  // Quadratic through the values a, b, c at 0, 1/2, 1.
  const Vec3<Exact> d0 = d[0], d1 = Exact(4) * d[1] - Exact(3) * d[0] - d[2],
                    d2 = Exact(2) * d[0] + Exact(2) * d[2] - Exact(4) * d[1];
  const Vec3<Exact> p0 = p[0], dp = p[2] - p[0];
  const Vec3<Exact> m0 = cross(p0, d0), m1 = cross(p0, d1) + cross(dp, d0), m2 = cross(p0, d2) + cross(dp, d1),
                    m3 = cross(dp, d2);
  if (!(CGAL::is_zero(m3.x) && CGAL::is_zero(m3.y) && CGAL::is_zero(m3.z)))
    throw std::logic_error("eee_line_polynomials: the moment is not quadratic");
  EeeLinePolynomials r;
  for (int k = 0; k < 3; ++k) {
    r.d[k].c = {d0[k], d1[k], d2[k]};
    r.m[k].c = {m0[k], m1[k], m2[k]};
  }
  return r;
}

QuadraticPolynomial eee_side_polynomial(const EeeLinePolynomials& l, const Vec3<Exact>& a, const Vec3<Exact>& b) {
  const Vec3<Exact> de = b - a, me = cross(a, b);
  Poly s;
  for (int j = 0; j < 3; ++j) {
    Exact c = 0;
    for (int k = 0; k < 3; ++k) c += l.d[k].c[j] * me[k] + de[k] * l.m[k].c[j];
    s.c[j] = c;
  }
  return s;
}

std::vector<EeeEndPiece> split_eee_interval(const Scene& scene, const TriangleIndex& index, const Box3& box,
                                            const EeeEvent& event, const CriticalInterval& interval,
                                            EeeSplitStats* stats) {
  const EeeLinePolynomials lines = eee_line_polynomials(scene, event);
  const IntervalLines il = interval_lines(lines);
  const RootNumber& T0 = interval.t0;
  const RootNumber& T1 = interval.t1;
  const std::vector<I> ranges = parameter_ranges(T0, T1, 8);

  // Candidates: triangles meeting the boxes of the lines' parts inside the scene box, per parameter range.
  // A point X of L(t) in the box is within diam(box) of P(t) (on E1, in the box): X in P(t) + [-1, 1] diam
  // d(t) / |d(t)|.
  const Vec3<Exact> A1 = to_rational(scene.vertices[event.edges[0][0]]);
  const Vec3<Exact> D1 = to_rational(scene.vertices[event.edges[0][1]]) - A1;
  const I diam = CGAL::sqrt(CGAL::square(I(box.hi.x) - I(box.lo.x)) + CGAL::square(I(box.hi.y) - I(box.lo.y)) +
                            CGAL::square(I(box.hi.z) - I(box.lo.z)));
  std::vector<std::int64_t> cand;
  for (const I& t : ranges) {
    std::array<I, 3> d;
    for (int k = 0; k < 3; ++k) d[k] = il.d[k][0] + t * (il.d[k][1] + t * il.d[k][2]);
    const I n2 = CGAL::square(d[0]) + CGAL::square(d[1]) + CGAL::square(d[2]);
    Box3 b = box;
    if (n2.inf() > 0) {
      const I n = CGAL::sqrt(n2);
      double lo[3], hi[3];
      for (int k = 0; k < 3; ++k) {
        const I x = interval_of(A1[k]) + t * interval_of(D1[k]) + I(-1, 1) * diam * d[k] / n;
        lo[k] = x.inf();
        hi[k] = x.sup();
      }
      b = intersection({{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}, box);
    }
    for (std::int64_t ti : index.candidates_in_box(b)) cand.push_back(ti);
  }
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  if (stats) stats->candidates += cand.size();

  // Roots of the edge polynomials strictly inside (t0, t1).
  std::vector<RootNumber> bps{T0, T1};
  auto add_roots = [&](const Poly& p, const RootNumber& lo, const RootNumber& hi, std::vector<RootNumber>& out) {
    if (stats) ++stats->polynomials;
    for (const RealRoot& r : real_roots(p))
      if (r.t > lo && r.t < hi) out.push_back(r.t);
  };
  std::vector<std::array<int, 2>> edges;  // the candidates' edges, each once
  edges.reserve(3 * cand.size());
  for (std::int64_t ti : cand) {
    const auto& t = scene.triangles[ti];
    for (int k = 0; k < 3; ++k) {
      const int a = t.v[k], b = t.v[(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const VanishFilter vf = vanish_filter(il, ranges);
  for (const auto& [a, b] : edges) {
    if (!may_vanish(vf, scene.vertices[a], scene.vertices[b])) continue;
    add_roots(eee_side_polynomial(lines, to_rational(scene.vertices[a]), to_rational(scene.vertices[b])), T0, T1, bps);
  }
  std::sort(bps.begin(), bps.end());
  bps.erase(std::unique(bps.begin(), bps.end()), bps.end());

  // Crossing lines of triangle `o` (scene index) with the candidates that cross it (each strictly on both
  // sides of the other's plane): the first hit passes from one to the other where L(t) meets that line.
  std::map<int, std::vector<Poly>> crossing_cache;
  auto crossings_of = [&](int o) -> const std::vector<Poly>& {
    auto [it, inserted] = crossing_cache.try_emplace(o);
    if (!inserted) return it->second;
    const auto& to = scene.triangles[o];
    const Point3 &o0 = scene.corner(to, 0), &o1 = scene.corner(to, 1), &o2 = scene.corner(to, 2);
    for (std::int64_t ti : cand) {
      if (ti == o) continue;
      const auto& tt = scene.triangles[ti];
      int s[3], r[3];
      for (int k = 0; k < 3; ++k) {
        s[k] = static_cast<int>(orient3d(o0, o1, o2, scene.corner(tt, k)));
        r[k] = static_cast<int>(orient3d(scene.corner(tt, 0), scene.corner(tt, 1), scene.corner(tt, 2), scene.corner(to, k)));
      }
      auto straddles = [](const int* x) {
        return (x[0] > 0 || x[1] > 0 || x[2] > 0) && (x[0] < 0 || x[1] < 0 || x[2] < 0);
      };
      if (!straddles(s) || !straddles(r)) continue;
      // Two points of tt in o's plane (tt straddles it): the planes' common line.
      const Vec3<Exact> c0 = to_rational(o0), n = cross(to_rational(o1) - c0, to_rational(o2) - c0);
      std::vector<Vec3<Exact>> pts;
      for (int k = 0; k < 3 && pts.size() < 2; ++k) {
        const Vec3<Exact> p = to_rational(scene.corner(tt, k)), q = to_rational(scene.corner(tt, (k + 1) % 3));
        const Exact hp = dot(n, p - c0), hq = dot(n, q - c0);
        if (CGAL::is_zero(hp)) {
          if (pts.empty() || !(pts.back() == p)) pts.push_back(p);
        } else if (CGAL::sign(hp) != CGAL::sign(hq) && !CGAL::is_zero(hq)) {
          pts.push_back(p + (hp / (hp - hq)) * (q - p));
        }
      }
      if (pts.size() == 2 && !(pts[0] == pts[1])) it->second.push_back(eee_side_polynomial(lines, pts[0], pts[1]));
    }
    return it->second;
  };

  auto objects_at = [&](const Exact& t) {
    if (stats) ++stats->gaps;
    const auto seg = eee_generator_segment(scene, event, t);
    if (!seg) throw std::logic_error("split_eee_interval: singular line inside a free interval");
    const RayHit f = ray_first_hit(scene, index, box, seg->front, seg->direction);
    const RayHit b = ray_first_hit(scene, index, box, seg->back, -seg->direction);
    return std::pair<int, int>{f.triangle, b.triangle};
  };

  struct Piece {
    RootNumber t0, t1;
    Exact sample;
    int front, back;
  };
  std::vector<Piece> pieces;
  for (std::size_t g = 0; g + 1 < bps.size(); ++g) {
    std::vector<std::pair<RootNumber, RootNumber>> todo{{bps[g], bps[g + 1]}};
    while (!todo.empty()) {
      const auto [lo, hi] = todo.back();
      todo.pop_back();
      const Exact q = rational_strictly_between(lo, hi);
      const auto [f, b] = objects_at(q);
      std::vector<RootNumber> more;
      for (int o : {f, b})
        if (o >= 0)
          for (const Poly& p : crossings_of(o)) add_roots(p, lo, hi, more);
      if (!more.empty()) {
        push_sub_intervals(std::move(more), lo, hi, todo);
        continue;
      }
      pieces.push_back({lo, hi, q, f, b});
    }
  }
  std::vector<EeeEndPiece> out;
  auto id = [&](int ti) { return ti >= 0 ? scene.triangles[ti].id : std::int64_t{-1}; };
  for (const Piece& p : pieces) {
    if (!out.empty() && out.back().front == id(p.front) && out.back().back == id(p.back)) {
      out.back().t1 = p.t1;
      continue;
    }
    out.push_back({p.t0, p.t1, p.sample, id(p.front), id(p.back)});
  }
  return out;
}

}  // namespace exactvis::shadows
