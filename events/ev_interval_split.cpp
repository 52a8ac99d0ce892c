#include "events/ev_interval_split.hpp"

#include "events/ev_split_filter.hpp"
#include "events/interval_end_key.hpp"
#include "kernel/ray_first_hit.hpp"
#include "kernel/predicates.hpp"
#include "util/sub_intervals.hpp"

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace exactvis {
namespace {

using I = CGAL::Interval_nt<>;
// The hot interval tests below run unprotected intervals under one rounding-mode switch each (the
// per-operation protection of Interval_nt<true> cost more than their arithmetic); same enclosures.
using IU = Interval;  // CGAL::Interval_nt<false>: only under CGAL::Protect_FPU_rounding<true>
IU unprotected(const I& x) { return IU(x.inf(), x.sup()); }

// A point of the wedge plane in the coordinates X = V + (alpha (A - V) + beta (B - V)) / |n|^2, n = (A - V) x
// (B - V): the affine coordinates scaled by |n|^2, so that they are dot products of input differences (no
// division; their rational denominators stay those of the input). Only ratios (t = beta / (alpha + beta),
// crossing parameters) and comparisons of scaled quantities are used; sigma = alpha + beta is compared with
// |n|^2 where the affine sum is compared with 1.
struct P2 {
  Exact alpha, beta;
};

// Segment in which a candidate triangle meets the wedge plane (p == q for a touching vertex), with the
// triangle's features its ends lie on (a vertex in the plane, or an edge crossing it).
struct Seg {
  int triangle;
  P2 p, q;
  OccluderFeature pf, qf;
};

OccluderFeature vertex_feature(int v) { return {OccluderFeature::Kind::Vertex, {v}}; }

Exact cross2(const P2& u, const P2& v) { return u.alpha * v.beta - u.beta * v.alpha; }
P2 sub(const P2& u, const P2& v) { return {u.alpha - v.alpha, u.beta - v.beta}; }

// The parameter t of the line through V and X (X = V + alpha a + beta b): t = beta / (alpha + beta).
std::optional<Exact> param_of(const P2& x) {
  const Exact s = x.alpha + x.beta;
  if (CGAL::is_zero(s)) return std::nullopt;  // direction parallel to E: no t
  return x.beta / s;
}

bool has_vertex(const SceneTriangle& t, int v) { return t.v[0] == v || t.v[1] == v || t.v[2] == v; }

I enclose(const Exact& x) {
  const auto e = enclosing_interval(x);
  return I(e.first, e.second);
}

// Enclosures of a segment's ends: alpha, beta of p, then of q.
std::array<I, 4> enclose_ends(const P2& p, const P2& q) {
  return {enclose(p.alpha), enclose(p.beta), enclose(q.alpha), enclose(q.beta)};
}


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
  return intersection({{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}, box);
}

}  // namespace

std::vector<CriticalInterval> split_ev_interval(const Scene& scene, const SceneAdjacency& adj,
                                                const TriangleIndex& spatial, const Box3& box, int vertex,
                                                const std::array<int, 2>& edge, const CriticalInterval& interval_in) {
  // EV parameters are rational.
  struct RationalInterval {
    Exact t0, t1;
  } const interval{rational_parameter(interval_in.t0), rational_parameter(interval_in.t1)};
  const Point3& pv = scene.vertices[vertex];
  const Point3& pa = scene.vertices[edge[0]];
  const Point3& pb = scene.vertices[edge[1]];
  const Vec3<Exact> V = to_rational(pv);
  // Affine alpha = ((X - V) x b) . n / |n|^2 = (X - V) . (b x n) / |n|^2, beta = (X - V) . (n x a) / |n|^2,
  // a = A - V, b = B - V, n = a x b; kept scaled by |n|^2 (P2). All inputs are doubles and these are ring
  // operations, so CGAL::Mpzf (exact multiprecision floats, no allocation for small sizes) computes them
  // exactly and several times faster than Gmpq; each result converts to the same canonical rational.
  using M = CGAL::Mpzf;
  auto mvec = [](const Point3& p, const Point3& o) {
    return Vec3<M>{M(p.x) - M(o.x), M(p.y) - M(o.y), M(p.z) - M(o.z)};
  };
  const Vec3<M> ma = mvec(pa, pv), mb = mvec(pb, pv);
  const Vec3<M> mn = cross(ma, mb);
  const Vec3<M> mca = cross(mb, mn), mcb = cross(mn, ma);
  const Exact nn(dot(mn, mn));
  // A corner's wedge coordinates and its plane offset f = (X - V) . n (exact, in Mpzf).
  struct CornerCoords {
    M alpha, beta, f;
  };
  auto corner_coords = [&](const Point3& q) {
    const Vec3<M> r = mvec(q, pv);
    return CornerCoords{dot(r, mca), dot(r, mcb), dot(r, mn)};
  };

  // Interval filter (rigorous enclosures, decides nothing by rounding): the cut of T with the plane lies in
  // the image of T under the affine map X -> (alpha, beta); where sigma = alpha + beta keeps one strict sign
  // over T, t = beta / sigma is monotone along segments, so its range over T lies between the vertices' t.
  // T is skipped when that range misses [t0, t1], or when 0 < sigma < |n|^2 on all of T (inside the wedge: no
  // end object there in a free interval, and its endpoints and crossings are not on a ray).
  using IP = std::array<I, 3>;
  auto iv3 = [](const Vec3<M>& x) {
    IP r;
    for (int k = 0; k < 3; ++k) {
      const auto p = CGAL::to_interval(x[k]);
      r[k] = I(p.first, p.second);
    }
    return r;
  };
  const IP ica = iv3(mca), icb = iv3(mcb);
  const double nn_lo = CGAL::to_interval(nn).first;  // sigma < nn_lo certainly means affine sigma < 1
  const auto it0 = CGAL::to_interval(interval.t0), it1 = CGAL::to_interval(interval.t1);
  const std::array<IU, 3> uca{unprotected(ica[0]), unprotected(ica[1]), unprotected(ica[2])},
      ucb{unprotected(icb[0]), unprotected(icb[1]), unprotected(icb[2])};
  auto may_matter = [&](const SceneTriangle& tri) {
    CGAL::Protect_FPU_rounding<true> guard;
    IU sig[3], tt[3];
    for (int k = 0; k < 3; ++k) {
      const Point3& q = scene.corner(tri, k);
      const IU r[3] = {IU(q.x) - IU(pv.x), IU(q.y) - IU(pv.y), IU(q.z) - IU(pv.z)};
      const IU al = r[0] * uca[0] + r[1] * uca[1] + r[2] * uca[2];
      const IU be = r[0] * ucb[0] + r[1] * ucb[1] + r[2] * ucb[2];
      sig[k] = al + be;
      tt[k] = IU(0);
      if (sig[k].inf() > 0 || sig[k].sup() < 0) tt[k] = be / sig[k];
    }
    const bool pos = sig[0].inf() > 0 && sig[1].inf() > 0 && sig[2].inf() > 0;
    const bool neg = sig[0].sup() < 0 && sig[1].sup() < 0 && sig[2].sup() < 0;
    if (pos && sig[0].sup() < nn_lo && sig[1].sup() < nn_lo && sig[2].sup() < nn_lo) return false;  // inside the wedge
    if (pos || neg) {
      const double lo = std::min({tt[0].inf(), tt[1].inf(), tt[2].inf()});
      const double hi = std::max({tt[0].sup(), tt[1].sup(), tt[2].sup()});
      if (hi < it0.first || lo > it1.second) return false;
    }
    return true;
  };

  // Candidate triangles of both sides and their segments in the wedge plane.
  std::vector<std::int64_t> cand = spatial.candidates_in_box(swept_box(pv, pa, pb, interval.t0, interval.t1, box, true));
  for (std::int64_t ti : spatial.candidates_in_box(swept_box(pv, pa, pb, interval.t0, interval.t1, box, false)))
    cand.push_back(ti);
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  std::vector<Seg> segs;
  // Interval enclosures of the segments' ends (alpha, beta of p, then of q), for the filters below.
  std::vector<std::array<I, 4>> seg_box;
  std::map<int, std::vector<std::size_t>> segs_of;
  for (std::int64_t ti64 : cand) {
    const int ti = static_cast<int>(ti64);
    const auto& t = scene.triangles[ti];
    if (has_vertex(t, vertex) || (has_vertex(t, edge[0]) && has_vertex(t, edge[1]))) continue;
    // Side of the wedge plane: the filtered orient3d first (cheap), rationals only for triangles crossing it.
    std::array<int, 3> o;
    for (int k = 0; k < 3; ++k) o[k] = static_cast<int>(orient3d(pv, pa, pb, scene.corner(t, k)));
    if ((o[0] > 0 && o[1] > 0 && o[2] > 0) || (o[0] < 0 && o[1] < 0 && o[2] < 0)) continue;
    if (!may_matter(t)) continue;
    std::array<CornerCoords, 3> mc;
    for (int k = 0; k < 3; ++k) mc[k] = corner_coords(scene.corner(t, k));
    // A corner's rational wedge coordinates, converted only for corners in the plane.
    auto wc = [&](int k) { return P2{Exact(mc[k].alpha), Exact(mc[k].beta)}; };
    // Keep only segments whose parameter range can meet [t0, t1] (t is monotone along a segment on which
    // sigma = alpha + beta keeps its sign; otherwise keep it).
    // The ends' enclosures decide first (they are kept for the crossing filter below); exact rationals only
    // when the enclosures cannot.
    auto push = [&](const P2& p, const P2& q, const OccluderFeature& pf, const OccluderFeature& qf) {
      const std::array<I, 4> eb = enclose_ends(p, q);
      switch (segment_t_range_meets(eb, it0, it1)) {
        case FilterAnswer::No: return;
        case FilterAnswer::Yes: segs_of[ti].push_back(segs.size()); segs.push_back({ti, p, q, pf, qf}); seg_box.push_back(eb); return;
        case FilterAnswer::Unknown: break;
      }
      const int sp = CGAL::sign(p.alpha + p.beta), sq = CGAL::sign(q.alpha + q.beta);
      if (sp != 0 && sp == sq) {
        const Exact tp = p.beta / (p.alpha + p.beta), tq = q.beta / (q.alpha + q.beta);
        if (std::max(tp, tq) < interval.t0 || std::min(tp, tq) > interval.t1) return;
      }
      segs_of[ti].push_back(segs.size());
      segs.push_back({ti, p, q, pf, qf});
      seg_box.push_back(eb);
    };
    if (o[0] == 0 && o[1] == 0 && o[2] == 0) {  // coplanar: its three edges
      const std::array<P2, 3> w{wc(0), wc(1), wc(2)};
      for (int k = 0; k < 3; ++k) push(w[k], w[(k + 1) % 3], vertex_feature(t.v[k]), vertex_feature(t.v[(k + 1) % 3]));
      continue;
    }
    std::vector<P2> pts;
    std::vector<OccluderFeature> feats;
    for (int k = 0; k < 3; ++k) {
      if (o[k] == 0) {
        pts.push_back(wc(k));
        feats.push_back(vertex_feature(t.v[k]));
      }
      const int j = (k + 1) % 3;
      if (o[k] * o[j] < 0) {  // the edge crosses the plane: interpolate (coordinates are affine)
        // X = (f_k X_j - f_j X_k) / (f_k - f_j): numerators in Mpzf, one rational division per coordinate.
        const M& fk = mc[k].f;
        const M& fj = mc[j].f;
        const Exact den(fk - fj);
        pts.push_back({Exact(fk * mc[j].alpha - fj * mc[k].alpha) / den, Exact(fk * mc[j].beta - fj * mc[k].beta) / den});
        feats.push_back({OccluderFeature::Kind::Edge, {t.v[k], t.v[j]}});
      }
    }
    if (pts.empty()) continue;
    push(pts.front(), pts.back(), feats.front(), feats.back());
  }

  // (a) endpoints of all segments. Endpoints strictly between V and E (0 < sigma < |n|^2) cannot lie on a line
  // of a free interval's interior.
  struct Endpoint {
    Exact t, sigma;
    int triangle;
    const OccluderFeature* feature;
  };
  std::vector<Endpoint> eps;
  auto add_ep = [&](const P2& x, const I& ia, const I& ib, int tri, const OccluderFeature& f) {
    if (endpoint_certainly_dropped(ia, ib, nn_lo, it0, it1)) return;
    const Exact sigma = x.alpha + x.beta;
    if (!(sigma >= nn || CGAL::sign(sigma) < 0)) return;
    const Exact t = x.beta / sigma;
    if (t > interval.t0 && t < interval.t1) eps.push_back({t, sigma, tri, &f});
  };
  for (std::size_t i = 0; i < segs.size(); ++i) {
    add_ep(segs[i].p, seg_box[i][0], seg_box[i][1], segs[i].triangle, segs[i].pf);
    add_ep(segs[i].q, seg_box[i][2], seg_box[i][3], segs[i].triangle, segs[i].qf);
  }
  std::sort(eps.begin(), eps.end(), [](const Endpoint& x, const Endpoint& y) { return x.t < y.t; });
  std::vector<Exact> bps{interval.t0};
  for (const auto& e : eps)
    if (e.t != bps.back()) bps.push_back(e.t);
  bps.push_back(interval.t1);

  struct Piece {
    Exact t0, t1;
    std::int64_t front, back;
  };
  const Vec3<Exact> A = to_rational(pa), Bp = to_rational(pb);
  auto objects_at = [&](const Exact& t) {
    const Vec3<Exact> p = A + t * (Bp - A);
    const Vec3<Exact> d = p - V;
    const RayHit f = ray_first_hit(scene, spatial, box, p, d, {edge[0], edge[1]});  // p lies on E
    const RayHit g = ray_first_hit(scene, spatial, box, V, -d);
    return std::pair<int, int>{f.triangle, g.triangle};
  };
  // What the line passes through at a crossing breakpoint (the first found); endpoint breakpoints are looked
  // up in `eps` (sorted by t) when a piece ends there.
  std::map<Exact, CriticalEnd> crossing_at;
  // Interval filter of the exact crossing test: true only when the segments' parameters u, v (below) are
  // certainly outside [0, 1] (the exact test then skips the pair too); the denominator must exclude 0.
  auto certainly_apart = [&](std::size_t fi, std::size_t gi) {
    CGAL::Protect_FPU_rounding<true> guard;
    IU f[4], g[4];
    for (int k = 0; k < 4; ++k) f[k] = unprotected(seg_box[fi][k]), g[k] = unprotected(seg_box[gi][k]);
    const IU d1a = f[2] - f[0], d1b = f[3] - f[1], d2a = g[2] - g[0], d2b = g[3] - g[1];
    const IU den = d1a * d2b - d1b * d2a;
    if (!(den.inf() > 0 || den.sup() < 0)) return false;
    const IU wa = g[0] - f[0], wb = g[1] - f[1];
    const IU u = (wa * d2b - wb * d2a) / den, v = (wa * d1b - wb * d1a) / den;
    return u.sup() < 0 || u.inf() > 1 || v.sup() < 0 || v.inf() > 1;
  };
  // (b) crossings of a triangle's segments with the other segments, inside (t0, t1); cached per triangle.
  std::map<int, std::vector<Exact>> crossing_cache;
  auto crossings_of = [&](int tri) -> const std::vector<Exact>& {
    auto [it, inserted] = crossing_cache.try_emplace(tri);
    if (!inserted) return it->second;
    std::vector<Exact>& out = it->second;
    const auto sit = segs_of.find(tri);
    if (sit == segs_of.end()) return out;
    for (std::size_t fi : sit->second) {
      const Seg& f = segs[fi];
      const P2 d1 = sub(f.q, f.p);
      for (std::size_t gi = 0; gi < segs.size(); ++gi) {
        const Seg& g = segs[gi];
        if (g.triangle == tri || certainly_apart(fi, gi)) continue;
        const P2 d2 = sub(g.q, g.p);
        const Exact den = cross2(d1, d2);
        if (CGAL::is_zero(den)) continue;  // parallel or collinear: changes only at endpoints
        const P2 w = sub(g.p, f.p);
        const Exact u = cross2(w, d2) / den, v = cross2(w, d1) / den;
        if (u < 0 || u > 1 || v < 0 || v > 1) continue;
        if (const auto t = param_of(P2{f.p.alpha + u * d1.alpha, f.p.beta + u * d1.beta});
            t && *t > interval.t0 && *t < interval.t1) {
          out.push_back(*t);
          if (!crossing_at.count(*t)) {
            CriticalEnd c;
            c.cause = CriticalEnd::Cause::EndObjectChange;
            c.triangle = scene.triangles[tri].id;
            c.other_triangle = scene.triangles[g.triangle].id;
            c.feature = {OccluderFeature::Kind::Face, {}};
            crossing_at.emplace(*t, std::move(c));
          }
        }
      }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  auto crossings = [&](int tri, const Exact& lo, const Exact& hi, std::vector<Exact>& out) {
    if (tri < 0) return;
    const auto& all = crossings_of(tri);
    for (auto it = std::upper_bound(all.begin(), all.end(), lo); it != all.end() && *it < hi; ++it) out.push_back(*it);
  };
  // Position sigma where line L(t) meets the one segment of (non-coplanar) triangle `tri`, when it crosses it
  // strictly inside; std::nullopt otherwise (no such segment, coplanar triangle, an endpoint on L(t), ...).
  auto sigma_on = [&](int tri, const Exact& t) -> std::optional<Exact> {
    const auto it = segs_of.find(tri);
    if (it == segs_of.end() || it->second.size() != 1) return std::nullopt;
    const Seg& sg = segs[it->second[0]];
    const Exact gp = sg.p.beta - t * (sg.p.alpha + sg.p.beta), gq = sg.q.beta - t * (sg.q.alpha + sg.q.beta);
    if (CGAL::sign(gp) * CGAL::sign(gq) >= 0) return std::nullopt;
    const Exact sp = sg.p.alpha + sg.p.beta, sq = sg.q.alpha + sg.q.beta;
    return sp + (gp / (gp - gq)) * (sq - sp);
  };
  // Can the objects change at breakpoint t (an endpoint breakpoint), given the objects (f, g) just before it?
  // Not if every endpoint there lies strictly behind the current first hit of its side, whose segment crosses
  // L(t) strictly inside (the change would need a crossing with it: those are split separately).
  std::size_t ep_pos = 0;
  auto may_change_at = [&](const Exact& t, int f, int g) {
    while (ep_pos < eps.size() && eps[ep_pos].t < t) ++ep_pos;
    // A crossing of a current object's segment exactly at t (not inside any piece) also changes it.
    for (int tri : {f, g}) {
      if (tri < 0) continue;
      const auto& c = crossings_of(tri);
      if (std::binary_search(c.begin(), c.end(), t)) return true;
    }
    const std::optional<Exact> sf = f >= 0 ? sigma_on(f, t) : std::nullopt;
    const std::optional<Exact> sg = g >= 0 ? sigma_on(g, t) : std::nullopt;
    for (std::size_t k = ep_pos; k < eps.size() && eps[k].t == t; ++k) {
      const Endpoint& e = eps[k];
      if (CGAL::sign(e.sigma) > 0) {  // beyond E
        if (!sf || e.triangle == f || !(*sf < e.sigma)) return true;
      } else {  // behind V
        if (!sg || e.triangle == g || !(*sg > e.sigma)) return true;
      }
    }
    return false;
  };

  std::vector<Piece> pieces;
  std::vector<std::pair<int, int>> piece_objects;  // scene indices of the last piece's objects
  for (std::size_t b = 0; b + 1 < bps.size(); ++b) {
    // Sub-pieces of [bps[b], bps[b + 1]]: split at crossings of the current objects, recursively.
    std::vector<std::pair<Exact, Exact>> todo{{bps[b], bps[b + 1]}};
    bool first = true;
    while (!todo.empty()) {
      const auto [lo, hi] = todo.back();
      todo.pop_back();
      std::pair<int, int> fg;
      if (first && b > 0 && !may_change_at(lo, piece_objects.back().first, piece_objects.back().second))
        fg = piece_objects.back();
      else
        fg = objects_at((lo + hi) / 2);
      first = false;
      std::vector<Exact> more;
      crossings(fg.first, lo, hi, more);
      crossings(fg.second, lo, hi, more);
      if (!more.empty()) {
        push_sub_intervals(std::move(more), lo, hi, todo);
        continue;
      }
      pieces.push_back({lo, hi, fg.first >= 0 ? scene.triangles[fg.first].id : -1,
                        fg.second >= 0 ? scene.triangles[fg.second].id : -1});
      piece_objects.push_back(fg);
    }
  }

  // The end where the objects change at t (inner ends of the merged pieces).
  auto change_end = [&](const Exact& t) {
    CriticalEnd c;
    const auto ep = std::lower_bound(eps.begin(), eps.end(), t, [](const Endpoint& e, const Exact& x) { return e.t < x; });
    if (ep != eps.end() && ep->t == t) {  // an endpoint breakpoint (these take precedence over crossings)
      c.cause = CriticalEnd::Cause::EndObjectChange;
      c.triangle = scene.triangles[ep->triangle].id;
      c.feature = *ep->feature;
    } else {
      c = crossing_at.at(t);
    }
    c.line = ev_end_key(scene, adj, vertex, edge, t, c);
    return c;
  };
  // Merge equal neighbours; sample at the merged midpoint when the objects there are the piece's.
  std::vector<CriticalInterval> out;
  std::size_t i = 0;
  while (i < pieces.size()) {
    std::size_t j = i, widest = i;
    while (j + 1 < pieces.size() && pieces[j + 1].front == pieces[i].front && pieces[j + 1].back == pieces[i].back) {
      ++j;
      if (pieces[j].t1 - pieces[j].t0 > pieces[widest].t1 - pieces[widest].t0) widest = j;
    }
    CriticalInterval iv;
    iv.t0 = RootNumber(pieces[i].t0);
    iv.t1 = RootNumber(pieces[j].t1);
    iv.end0 = i == 0 ? interval_in.end0 : change_end(pieces[i].t0);
    iv.end1 = j + 1 == pieces.size() ? interval_in.end1 : change_end(pieces[j].t1);
    iv.front_object = pieces[i].front;
    iv.back_object = pieces[i].back;
    iv.sample_t = (pieces[i].t0 + pieces[j].t1) / 2;
    // The objects are constant on each piece's open interval (the split's invariant): a merged midpoint
    // strictly inside one of the pieces has the pieces' objects, so only a midpoint on a piece boundary
    // needs its own rays.
    bool inside_a_piece = false;
    for (std::size_t k = i; k <= j && !inside_a_piece; ++k)
      inside_a_piece = pieces[k].t0 < iv.sample_t && iv.sample_t < pieces[k].t1;
    if (j > i && !inside_a_piece) {
      const auto [f, g] = objects_at(iv.sample_t);
      const std::int64_t fid = f >= 0 ? scene.triangles[f].id : -1, gid = g >= 0 ? scene.triangles[g].id : -1;
      if (fid != iv.front_object || gid != iv.back_object)
        iv.sample_t = (pieces[widest].t0 + pieces[widest].t1) / 2;
    }
    out.push_back(std::move(iv));
    i = j + 1;
  }
  return out;
}

}  // namespace exactvis
