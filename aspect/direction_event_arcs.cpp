#include "aspect/direction_event_arcs.hpp"

#include "aspect/eee_direction_cone.hpp"
#include "events/scene_adjacency.hpp"
#include "events/tangency.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quadratic_polynomial.hpp"
#include "kernel/rational_between.hpp"
#include "util/for_each_index.hpp"

#include <algorithm>
#include <atomic>
#include <set>
#include <utility>

namespace exactvis {
namespace {

using V3 = Vec3<Exact>;
using Poly = QuadraticPolynomial;
using PV = Vec3<Poly>;

V3 ep(const Point3& p) { return {Exact(p.x), Exact(p.y), Exact(p.z)}; }

// c0 + t c1, componentwise.
PV linear(const V3& c0, const V3& c1) {
  return {Poly::linear(c0.x, c1.x), Poly::linear(c0.y, c1.y), Poly::linear(c0.z, c1.z)};
}
PV constant(const V3& c) { return PV::from(c); }

struct Tri {
  V3 c[3], n;
  std::int64_t id = -1;
};

// A line of a family at a rational parameter: {p + lambda d}, with its generator points at `gens` and, per
// generator, whether the line pierces the surface of the triangles incident to it there.
struct SampleLine {
  V3 p, d;
  std::vector<Exact> gens;
  std::vector<char> pierce;
};

// Blocked at a generator: some generator other than the farthest one (for orientation o) is pierced, so the
// incident triangles there hide the farther generators from every nearby line.
bool pierced_in_front(const SampleLine& s, int o) {
  std::size_t far = 0;
  for (std::size_t g = 1; g < s.gens.size(); ++g)
    if (o > 0 ? s.gens[g] < s.gens[far] : s.gens[g] > s.gens[far]) far = g;
  for (std::size_t g = 0; g < s.gens.size(); ++g)
    if (g != far && s.pierce[g]) return true;
  return false;
}

// The edge rule's negation at a manifold edge (exactly two incident triangles): their opposite corners lie
// strictly on both sides of the plane spanned by the edge and d. Other edges are never pierced.
bool edge_pierced(const Scene& scene, const SceneEdge& e, const V3& d) {
  if (e.triangles.size() != 2) return false;
  const V3 a = ep(scene.vertices[e.v[0]]);
  const V3 m = cross(ep(scene.vertices[e.v[1]]) - a, d);
  int s[2];
  for (int k = 0; k < 2; ++k) {
    const auto& t = scene.triangles[e.triangles[k]];
    int c = 0;
    while (t.v[c] == e.v[0] || t.v[c] == e.v[1]) ++c;
    s[k] = CGAL::sign(dot(m, ep(scene.vertices[t.v[c]]) - a));
  }
  return s[0] * s[1] < 0;
}

// Does u block the line for orientation o: the line crosses u's plane at one point X in u's relative
// interior (so X is no generator point: no edge of the model crosses a triangle's interior), and X is beyond the farthest generator towards the viewer (o = +1: at a
// position above the smallest generator position; o = -1: below the largest).
bool blocks(const Tri& u, const SampleLine& s, int o) {
  const Exact den = dot(u.n, s.d);
  if (CGAL::sign(den) == 0) return false;
  const Exact lambda = dot(u.n, u.c[0] - s.p) / den;
  if (o > 0 ? lambda <= *std::min_element(s.gens.begin(), s.gens.end())
            : lambda >= *std::max_element(s.gens.begin(), s.gens.end()))
    return false;
  const V3 x = s.p + lambda * s.d;
  for (int k = 0; k < 3; ++k)
    if (CGAL::sign(dot(cross(u.c[(k + 1) % 3] - u.c[k], x - u.c[k]), u.n)) <= 0) return false;
  return true;
}

struct Cut {
  RootNumber t;
  ArcEnd why;
};

void add_roots(std::vector<Cut>& cuts, const Poly& p, const ArcEnd& why) {
  const RootNumber zero(Exact(0)), one(Exact(1));
  for (const auto& r : real_roots(p))
    if (zero < r.t && r.t < one) cuts.push_back({r.t, why});
}

ArcEnd occluder_end(std::int64_t id) {
  ArcEnd e;
  e.cause = ArcEnd::Cause::Occluder;
  e.triangle = id;
  return e;
}

// The breakpoint sweep: between consecutive cuts (and 0, 1) every occluder's blocking and the family's
// validity are constant (each cut set holds every parameter where one of them can change), so each open
// piece is decided at one rational sample. Runs of free pieces become arcs (closures). With `probe`, only
// reports whether some piece has a line (no occluders, no arcs).
template <class LineAt>
bool sweep(std::vector<Cut> cuts, const std::vector<const Tri*>& occluders, const LineAt& line_at,
           const DirectionEventArc& proto, std::vector<DirectionEventArc>* out) {
  std::sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) { return a.t < b.t; });
  std::vector<Cut> v;
  v.push_back({RootNumber(Exact(0)), ArcEnd{}});
  for (const auto& c : cuts)
    if (!(v.back().t == c.t)) v.push_back(c);
  v.push_back({RootNumber(Exact(1)), ArcEnd{}});
  const std::size_t pieces = v.size() - 1;
  std::vector<Exact> samples(pieces);
  std::array<std::vector<char>, 2> is_free;
  is_free[0].assign(pieces, 0);
  is_free[1].assign(pieces, 0);
  bool any = false;
  for (std::size_t i = 0; i < pieces; ++i) {
    samples[i] = rational_strictly_between(v[i].t, v[i + 1].t);
    const std::optional<SampleLine> line = line_at(samples[i]);
    if (!line) continue;
    any = true;
    if (!out) return true;
    for (int oi = 0; oi < 2; ++oi) {
      const int o = oi == 0 ? 1 : -1;
      bool blocked = pierced_in_front(*line, o);
      for (const Tri* u : occluders)
        if (blocked || blocks(*u, *line, o)) {
          blocked = true;
          break;
        }
      is_free[oi][i] = !blocked;
    }
  }
  if (!out) return any;
  for (int oi = 0; oi < 2; ++oi)
    for (std::size_t i = 0; i < pieces;) {
      if (!is_free[oi][i]) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < pieces && is_free[oi][j + 1]) ++j;
      DirectionEventArc arc = proto;
      arc.orientation = oi == 0 ? 1 : -1;
      arc.t0 = v[i].t;
      arc.t1 = v[j + 1].t;
      arc.end0 = v[i].why;
      arc.end1 = v[j + 1].why;
      arc.sample_t = samples[i];
      out->push_back(std::move(arc));
      i = j + 1;
    }
  return any;
}

struct Family3 {
  V3 a[3], u[3];
  EeeDirectionCone cone;
  const SceneEdge* se[3] = {nullptr, nullptr, nullptr};  // for the piercing tests (null: never pierced)
};

Family3 eee_family(const Scene& scene, const std::array<std::array<int, 2>, 3>& edges) {
  Family3 f;
  for (int k = 0; k < 3; ++k) {
    f.a[k] = ep(scene.vertices[edges[k][0]]);
    f.u[k] = ep(scene.vertices[edges[k][1]]) - f.a[k];
  }
  f.cone = eee_direction_cone({f.a[0], f.a[1], f.a[2]}, {f.u[0], f.u[1], f.u[2]});
  return f;
}

// The EEE line at rational t: through P(t) with direction f(t); its points on the lines of E2 and E3 at
// positions lambda_j; std::nullopt unless it meets both segments in their relative interiors.
std::optional<SampleLine> eee_line(const Scene& scene, const Family3& f, const Exact& t) {
  const V3 p = f.a[0] + t * f.u[0];
  const V3 d = cone_direction_at(f.cone, t);
  SampleLine s{p, d, {Exact(0)}, {}};
  for (int j = 1; j < 3; ++j) {
    const V3 du = cross(d, f.u[j]);
    const Exact den = dot(du, du);
    if (CGAL::sign(den) == 0) return std::nullopt;
    const V3 w = f.a[j] - p;  // lambda d - s u_j = w
    const Exact lambda = dot(cross(w, f.u[j]), du) / den;
    const Exact sj = dot(cross(w, d), du) / den;
    if (CGAL::sign(sj) <= 0 || sj >= Exact(1)) return std::nullopt;
    s.gens.push_back(lambda);
  }
  for (int g = 0; g < 3; ++g) s.pierce.push_back(f.se[g] && edge_pierced(scene, *f.se[g], d));
  return s;
}

}  // namespace

DirectionEventArcs direction_event_arcs(const Scene& scene, const DirectionEventOptions& options) {
  DirectionEventArcs out;
  std::vector<Tri> tris;
  for (const auto& t : scene.triangles) {
    Tri x;
    for (int k = 0; k < 3; ++k) x.c[k] = ep(scene.corner(t, k));
    x.n = cross(x.c[1] - x.c[0], x.c[2] - x.c[0]);
    x.id = t.id;
    tris.push_back(x);
  }
  const SceneAdjacency adj = build_scene_adjacency(scene);

  // EV: the family lies in the plane of V and E; only triangles with corners strictly on both sides of it
  // meet it in their relative interior.
  // One output list per vertex (per first edge for EEE), filled on oneTBB's threads and concatenated in
  // order, so the result does not depend on the scheduling.
  std::vector<std::vector<DirectionEventArc>> ev_out(scene.vertices.size());
  std::atomic<std::uint64_t> ev_pairs{0}, eee_triples{0}, eee_valid{0};
  for_each_index(scene.vertices.size(), options.parallel, 1, [&](std::size_t vi) {
    const int vid = static_cast<int>(vi);
    if (adj.vertex_triangles[vid].empty()) return;
    const Point3& vp = scene.vertices[vid];
    const V3 vx = ep(vp);
    const VertexFan fan = build_vertex_fan(scene, adj, vid);
    for (const auto& edge : adj.edges) {
      const std::array<int, 2>& e = edge.v;
      const Point3 &ap = scene.vertices[e[0]], &bp = scene.vertices[e[1]];
      if (collinear(vp, ap, bp)) continue;  // V on E's line (an endpoint included): no plane, no family
      ++ev_pairs;
      const V3 a = ep(ap), b = ep(bp);
      std::vector<const Tri*> occ;
      std::vector<Cut> cuts;
      for (std::size_t m = 0; m < tris.size(); ++m) {
        bool pos = false, neg = false;
        for (int k = 0; k < 3; ++k) {
          const Sign s = orient3d(vp, ap, bp, scene.corner(scene.triangles[m], k));
          pos |= s == Sign::Positive;
          neg |= s == Sign::Negative;
        }
        if (!pos || !neg) continue;
        const Tri& u = tris[m];
        occ.push_back(&u);
        const PV w = linear(a - vx, b - a);  // P(t) - V
        const ArcEnd why = occluder_end(u.id);
        for (int k = 0; k < 3; ++k)  // the line meets u's edge line k: V, P(t), and the edge coplanar
          add_roots(cuts, dot(w, constant(cross(u.c[k] - vx, u.c[(k + 1) % 3] - vx))), why);
        add_roots(cuts, dot(w, constant(u.n)), why);                                   // parallel to u
        add_roots(cuts, dot(linear(a - u.c[0], b - a), constant(u.n)), why);           // P(t) in u's plane
      }
      // The vertex rule changes only where the line lies in the plane of a triangle of V's fan; the edge rule
      // is constant (the plane of the line and E is the family's plane).
      const PV w = linear(a - vx, b - a);
      for (int f : fan.triangles) {
        ArcEnd why = occluder_end(scene.triangles[f].id);
        add_roots(cuts, dot(w, constant(tris[f].n)), why);
      }
      const V3 plane_normal = cross(a - vx, b - vx);
      const bool e_pierced = edge_pierced(scene, edge, b - vx);
      DirectionEventArc proto;
      proto.type = DirectionEventArc::Type::EV;
      proto.vertex = vid;
      proto.edges[0] = e;
      const auto line_at = [&](const Exact& t) -> std::optional<SampleLine> {
        const V3 d = a + t * (b - a) - vx;
        const VertexTangency vt = line_tangent_at_vertex(scene, fan, d, plane_normal);
        return SampleLine{vx, d, {Exact(0), Exact(1)}, {char(!vt.tangent && vt.triangle < 0), char(e_pierced)}};
      };
      sweep(std::move(cuts), occ, line_at, proto, &ev_out[vid]);
    }
  });
  for (auto& v : ev_out)
    for (auto& a : v) out.arcs.push_back(std::move(a));
  out.ev_pairs = ev_pairs;
  if (!options.eee) return out;

  std::vector<const Tri*> all;
  for (const auto& u : tris) all.push_back(&u);
  const std::size_t ne = adj.edges.size();
  std::vector<std::vector<DirectionEventArc>> eee_out(ne);
  for_each_index(ne, options.parallel, 1, [&](std::size_t i) {
    for (std::size_t j = i + 1; j < ne; ++j)
      for (std::size_t k = j + 1; k < ne; ++k) {
        const std::array<std::array<int, 2>, 3> es{adj.edges[i].v, adj.edges[j].v, adj.edges[k].v};
        bool skip = false;
        for (int x = 0; x < 3 && !skip; ++x)
          for (int y = x + 1; y < 3 && !skip; ++y) {
            const auto &p = es[x], &q = es[y];
            // Coplanar pairs (a shared vertex included) give no EEE family of their own (theory §10.9).
            skip = orient3d(scene.vertices[p[0]], scene.vertices[p[1]], scene.vertices[q[0]], scene.vertices[q[1]]) ==
                   Sign::Zero;
          }
        if (skip) continue;
        ++eee_triples;
        Family3 f = eee_family(scene, es);
        f.se[0] = &adj.edges[i];
        f.se[1] = &adj.edges[j];
        f.se[2] = &adj.edges[k];
        const PV pt = linear(f.a[0], f.u[0]);  // P(t)
        const PV n2 = linear(cross(f.u[1], f.a[1] - f.a[0]), -cross(f.u[1], f.u[0]));
        const PV n3 = linear(cross(f.u[2], f.a[2] - f.a[0]), -cross(f.u[2], f.u[0]));
        const PV dt{Poly::linear(f.cone.d[0].x, f.cone.d[1].x), Poly::linear(f.cone.d[0].y, f.cone.d[1].y),
                    Poly::linear(f.cone.d[0].z, f.cone.d[1].z)};
        PV d = dt;
        for (int c = 0; c < 3; ++c) d[c].c[2] = f.cone.d[2][c];
        std::vector<Cut> cuts;
        for (int g = 1; g < 3; ++g) {
          const int other = 3 - g;  // the line through a point w of E_g meeting the other edge's line
          for (int end = 0; end < 2; ++end) {
            const V3 w = ep(scene.vertices[es[g][end]]);
            ArcEnd why;
            why.cause = ArcEnd::Cause::EdgeEndpoint;
            why.vertex = es[g][end];
            add_roots(cuts, dot(pt - constant(w), constant(cross(f.u[other], f.a[other] - w))), why);
          }
        }
        ArcEnd singular;
        singular.cause = ArcEnd::Cause::Singular;
        add_roots(cuts, dot(n3, constant(f.u[1])), singular);
        add_roots(cuts, dot(n2, constant(f.u[2])), singular);
        for (int c = 0; c < 3; ++c)
          if (d[c].degree() >= 0) {
            add_roots(cuts, d[c], singular);
            break;
          }
        // The edge rules change only where d(t) lies in the plane of an edge and an incident opposite corner.
        for (int g = 0; g < 3; ++g)
          if (f.se[g]->triangles.size() == 2)
            for (int ti : f.se[g]->triangles) {
              const auto& tr = scene.triangles[ti];
              int c = 0;
              while (tr.v[c] == es[g][0] || tr.v[c] == es[g][1]) ++c;
              add_roots(cuts, dot(cross(constant(f.u[g]), d), constant(ep(scene.vertices[tr.v[c]]) - f.a[g])),
                        occluder_end(tr.id));
            }
        const auto line_at = [&](const Exact& t) { return eee_line(scene, f, t); };
        DirectionEventArc proto;
        proto.type = DirectionEventArc::Type::EEE;
        proto.edges = es;
        if (!sweep(cuts, {}, line_at, proto, nullptr)) continue;
        ++eee_valid;
        for (const Tri& u : tris) {
          const ArcEnd why = occluder_end(u.id);
          for (int e = 0; e < 3; ++e) {  // the line meets u's edge line e: a quadratic in t
            const V3 a4 = u.c[e], u4 = u.c[(e + 1) % 3] - u.c[e];
            add_roots(cuts, dot(n2, constant(u4)) * dot(n3, constant(f.a[2] - a4)) -
                                dot(n3, constant(u4)) * dot(n2, constant(f.a[1] - a4)),
                      why);
          }
          add_roots(cuts, dot(d, constant(u.n)), why);                        // parallel to u's plane
          add_roots(cuts, dot(pt - constant(u.c[0]), constant(u.n)), why);    // P(t) in u's plane
          for (int g = 1; g < 3; ++g) {                                        // Q_g(t) in u's plane
            const Exact un = dot(u.n, f.u[g]);
            if (CGAL::sign(un) == 0) continue;
            const V3 w = f.a[g] + (dot(u.n, u.c[0] - f.a[g]) / un) * f.u[g];
            const int other = 3 - g;
            add_roots(cuts, dot(pt - constant(w), constant(cross(f.u[other], f.a[other] - w))), why);
          }
        }
        sweep(std::move(cuts), all, line_at, proto, &eee_out[i]);
      }
  });
  for (auto& v : eee_out)
    for (auto& a : v) out.arcs.push_back(std::move(a));
  out.eee_triples = eee_triples;
  out.eee_valid_triples = eee_valid;
  return out;
}

Vec3<Exact> arc_direction(const Scene& scene, const DirectionEventArc& arc, const Exact& t) {
  Vec3<Exact> f;
  if (arc.type == DirectionEventArc::Type::EV) {
    const V3 a = ep(scene.vertices[arc.edges[0][0]]), b = ep(scene.vertices[arc.edges[0][1]]);
    f = a + t * (b - a) - ep(scene.vertices[arc.vertex]);
  } else {
    f = cone_direction_at(eee_family(scene, arc.edges).cone, t);
  }
  return arc.orientation > 0 ? f : -f;
}

std::optional<ArcLine> arc_line(const Scene& scene, const DirectionEventArc& arc, const Exact& t) {
  std::optional<SampleLine> s;
  if (arc.type == DirectionEventArc::Type::EV) {
    const V3 v = ep(scene.vertices[arc.vertex]);
    const V3 a = ep(scene.vertices[arc.edges[0][0]]), b = ep(scene.vertices[arc.edges[0][1]]);
    s = SampleLine{v, a + t * (b - a) - v, {Exact(0), Exact(1)}, {0, 0}};
  } else {
    s = eee_line(scene, eee_family(scene, arc.edges), t);
  }
  if (!s) return std::nullopt;
  const Exact far = arc.orientation > 0 ? *std::min_element(s->gens.begin(), s->gens.end())
                                        : *std::max_element(s->gens.begin(), s->gens.end());
  const V3 dir = arc.orientation > 0 ? s->d : -s->d;
  return ArcLine{s->p + far * s->d, dir};
}

}  // namespace exactvis
