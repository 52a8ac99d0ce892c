#include "events/ev_interval_split.hpp"

#include "events/ray_first_hit.hpp"
#include "kernel/predicates.hpp"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace exactvis {
namespace {

using I = CGAL::Interval_nt<>;

// A point of the wedge plane in the coordinates X = V + alpha (A - V) + beta (B - V).
struct P2 {
  Exact alpha, beta;
};

// Segment in which a candidate triangle meets the wedge plane (p == q for a touching vertex).
struct Seg {
  int triangle;
  P2 p, q;
};

Exact cross2(const P2& u, const P2& v) { return u.alpha * v.beta - u.beta * v.alpha; }
P2 sub(const P2& u, const P2& v) { return {u.alpha - v.alpha, u.beta - v.beta}; }

// The parameter t of the line through V and X (X = V + alpha a + beta b): t = beta / (alpha + beta).
std::optional<Exact> param_of(const P2& x) {
  const Exact s = x.alpha + x.beta;
  if (CGAL::is_zero(s)) return std::nullopt;  // direction parallel to E: no t
  return x.beta / s;
}

bool has_vertex(const SceneTriangle& t, int v) { return t.v[0] == v || t.v[1] == v || t.v[2] == v; }

// Interval enclosure of the region swept by one side's rays (front: V + s d(t), 1 <= s <= L; back:
// -L <= s <= 0) for t in [t0, t1], clipped to the scene box. L bounds |s| for points in the box:
// |s| <= diam(box) / |d(t)| and |d(t)| >= dist(V, line E) = |a x b| / |b - a|.
Box3 swept_box(const Point3& v, const Point3& a, const Point3& b, const Exact& t0, const Exact& t1, const Box3& box,
               bool front) {
  const std::array<I, 3> V{I(v.x), I(v.y), I(v.z)};
  std::array<I, 3> av, bv;
  for (int k = 0; k < 3; ++k) av[k] = I(a[k]) - V[k], bv[k] = I(b[k]) - V[k];
  const std::array<I, 3> n{av[1] * bv[2] - av[2] * bv[1], av[2] * bv[0] - av[0] * bv[2], av[0] * bv[1] - av[1] * bv[0]};
  const I n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  const I ba2 = CGAL::square(bv[0] - av[0]) + CGAL::square(bv[1] - av[1]) + CGAL::square(bv[2] - av[2]);
  const I diam2 = CGAL::square(I(box.hi.x) - I(box.lo.x)) + CGAL::square(I(box.hi.y) - I(box.lo.y)) +
                  CGAL::square(I(box.hi.z) - I(box.lo.z));
  if (!(n2.inf() > 0)) return box;
  const double big = CGAL::sqrt(diam2 * ba2 / n2).sup() + 1.0;
  if (!std::isfinite(big)) return box;
  const auto ti0 = CGAL::to_interval(t0), ti1 = CGAL::to_interval(t1);
  std::array<double, 3> lo, hi;
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = v[k];
  auto add = [&](const I& t, double s) {
    for (int k = 0; k < 3; ++k) {
      const I x = V[k] + I(s) * (av[k] + t * (bv[k] - av[k]));
      lo[k] = std::min(lo[k], x.inf());
      hi[k] = std::max(hi[k], x.sup());
    }
  };
  for (const I t : {I(ti0.first, ti0.second), I(ti1.first, ti1.second)}) {
    if (front) {
      add(t, 1.0);
      add(t, big);
    } else {
      add(t, -big);
    }
  }
  Box3 out;
  out.lo = {std::max(lo[0], box.lo.x), std::max(lo[1], box.lo.y), std::max(lo[2], box.lo.z)};
  out.hi = {std::min(hi[0], box.hi.x), std::min(hi[1], box.hi.y), std::min(hi[2], box.hi.z)};
  return out;
}

}  // namespace

std::vector<EvInterval> split_ev_interval(const Scene& scene, const SpatialIndex& spatial, const Box3& box,
                                          int vertex, const std::array<int, 2>& edge, const EvInterval& interval) {
  const Point3& pv = scene.vertices[vertex];
  const Point3& pa = scene.vertices[edge[0]];
  const Point3& pb = scene.vertices[edge[1]];
  const Vec3<Exact> V = to_rational(pv);
  const Vec3<Exact> a = to_rational(pa) - V, b = to_rational(pb) - V;
  const Vec3<Exact> n = cross(a, b);
  const Exact nn = dot(n, n);
  auto coords = [&](const Vec3<Exact>& x) {
    const Vec3<Exact> r = x - V;
    return P2{dot(cross(r, b), n) / nn, dot(cross(a, r), n) / nn};
  };

  // Candidate triangles of both sides and their segments in the wedge plane.
  std::vector<std::int64_t> cand = spatial.triangles_in_box(swept_box(pv, pa, pb, interval.t0, interval.t1, box, true));
  for (std::int64_t ti : spatial.triangles_in_box(swept_box(pv, pa, pb, interval.t0, interval.t1, box, false)))
    cand.push_back(ti);
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  std::vector<Seg> segs;
  std::map<int, std::vector<std::size_t>> segs_of;
  for (std::int64_t ti64 : cand) {
    const int ti = static_cast<int>(ti64);
    const auto& t = scene.triangles[ti];
    if (has_vertex(t, vertex) || (has_vertex(t, edge[0]) && has_vertex(t, edge[1]))) continue;
    std::array<Vec3<Exact>, 3> w;
    std::array<int, 3> o;
    for (int k = 0; k < 3; ++k) {
      w[k] = to_rational(scene.corner(t, k));
      o[k] = CGAL::sign(dot(w[k] - V, n));
    }
    if ((o[0] > 0 && o[1] > 0 && o[2] > 0) || (o[0] < 0 && o[1] < 0 && o[2] < 0)) continue;
    auto push = [&](const P2& p, const P2& q) {
      segs_of[ti].push_back(segs.size());
      segs.push_back({ti, p, q});
    };
    if (o[0] == 0 && o[1] == 0 && o[2] == 0) {  // coplanar: its three edges
      for (int k = 0; k < 3; ++k) push(coords(w[k]), coords(w[(k + 1) % 3]));
      continue;
    }
    std::vector<Vec3<Exact>> pts;
    for (int k = 0; k < 3; ++k) {
      if (o[k] == 0) pts.push_back(w[k]);
      const int j = (k + 1) % 3;
      if (o[k] * o[j] < 0) {
        const Exact fk = dot(w[k] - V, n), fj = dot(w[j] - V, n);
        pts.push_back(w[k] + (fk / (fk - fj)) * (w[j] - w[k]));
      }
    }
    if (pts.empty()) continue;
    push(coords(pts.front()), coords(pts.back()));
  }

  // (a) endpoints of all segments.
  std::vector<Exact> bps{interval.t0, interval.t1};
  auto add_bp = [&](std::vector<Exact>& out, const P2& x, const Exact& lo, const Exact& hi) {
    if (const auto t = param_of(x); t && *t > lo && *t < hi) out.push_back(*t);
  };
  for (const auto& s : segs) {
    add_bp(bps, s.p, interval.t0, interval.t1);
    add_bp(bps, s.q, interval.t0, interval.t1);
  }
  std::sort(bps.begin(), bps.end());
  bps.erase(std::unique(bps.begin(), bps.end()), bps.end());

  struct Piece {
    Exact t0, t1;
    std::int64_t front, back;
  };
  const Vec3<Exact> A = to_rational(pa), Bp = to_rational(pb);
  auto objects_at = [&](const Exact& t) {
    const Vec3<Exact> p = A + t * (Bp - A);
    const Vec3<Exact> d = p - V;
    const RayHit f = ray_first_hit(scene, spatial, box, p, d);
    const RayHit g = ray_first_hit(scene, spatial, box, V, -d);
    return std::pair<int, int>{f.triangle, g.triangle};
  };
  // (b) crossings of the end objects' segments with other segments, inside (lo, hi).
  auto crossings = [&](int tri, const Exact& lo, const Exact& hi, std::vector<Exact>& out) {
    const auto it = segs_of.find(tri);
    if (it == segs_of.end()) return;
    for (std::size_t fi : it->second) {
      const Seg& f = segs[fi];
      const P2 d1 = sub(f.q, f.p);
      for (const Seg& g : segs) {
        if (g.triangle == tri) continue;
        const P2 d2 = sub(g.q, g.p);
        const Exact den = cross2(d1, d2);
        if (CGAL::is_zero(den)) continue;  // parallel or collinear: changes only at endpoints
        const P2 w = sub(g.p, f.p);
        const Exact u = cross2(w, d2) / den, v = cross2(w, d1) / den;
        if (u < 0 || u > 1 || v < 0 || v > 1) continue;
        add_bp(out, P2{f.p.alpha + u * d1.alpha, f.p.beta + u * d1.beta}, lo, hi);
      }
    }
  };
  std::vector<Piece> pieces;
  std::vector<std::pair<Exact, Exact>> todo;
  for (std::size_t i = bps.size() - 1; i > 0; --i) todo.emplace_back(bps[i - 1], bps[i]);  // stack: in order
  while (!todo.empty()) {
    const auto [lo, hi] = todo.back();
    todo.pop_back();
    const Exact mid = (lo + hi) / 2;
    const auto [f, g] = objects_at(mid);
    std::vector<Exact> more;
    if (f >= 0) crossings(f, lo, hi, more);
    if (g >= 0) crossings(g, lo, hi, more);
    if (!more.empty()) {
      more.push_back(lo);
      more.push_back(hi);
      std::sort(more.begin(), more.end());
      more.erase(std::unique(more.begin(), more.end()), more.end());
      for (std::size_t i = more.size() - 1; i > 0; --i) todo.emplace_back(more[i - 1], more[i]);
      continue;
    }
    pieces.push_back({lo, hi, f >= 0 ? scene.triangles[f].id : -1, g >= 0 ? scene.triangles[g].id : -1});
  }

  // Merge equal neighbours; sample at the merged midpoint when the objects there are the piece's.
  std::vector<EvInterval> out;
  std::size_t i = 0;
  while (i < pieces.size()) {
    std::size_t j = i, widest = i;
    while (j + 1 < pieces.size() && pieces[j + 1].front == pieces[i].front && pieces[j + 1].back == pieces[i].back) {
      ++j;
      if (pieces[j].t1 - pieces[j].t0 > pieces[widest].t1 - pieces[widest].t0) widest = j;
    }
    EvInterval iv;
    iv.t0 = pieces[i].t0;
    iv.t1 = pieces[j].t1;
    iv.end0 = i == 0 ? interval.end0 : EventEnd{EventEnd::Cause::EndObjectChange, -1, {}};
    iv.end1 = j + 1 == pieces.size() ? interval.end1 : EventEnd{EventEnd::Cause::EndObjectChange, -1, {}};
    iv.beyond_edge = pieces[i].front;
    iv.behind_vertex = pieces[i].back;
    iv.sample_t = (iv.t0 + iv.t1) / 2;
    if (j > i) {
      const auto [f, g] = objects_at(iv.sample_t);
      const std::int64_t fid = f >= 0 ? scene.triangles[f].id : -1, gid = g >= 0 ? scene.triangles[g].id : -1;
      if (fid != iv.beyond_edge || gid != iv.behind_vertex)
        iv.sample_t = (pieces[widest].t0 + pieces[widest].t1) / 2;
    }
    out.push_back(std::move(iv));
    i = j + 1;
  }
  return out;
}

}  // namespace exactvis
