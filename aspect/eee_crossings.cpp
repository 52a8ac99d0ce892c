#include "aspect/eee_crossings.hpp"

#include "kernel/predicates.hpp"
#include "kernel/rational_between.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace exactvis {
namespace {

using V3 = Vec3<Exact>;
using P = ExactPolynomial;
using P3 = std::array<P, 3>;
using Mat = std::array<std::array<Exact, 3>, 3>;

// o f(t) as three polynomials (from three exact values: the family direction is quadratic in t).
P3 arc_poly(const Scene& scene, const DirectionEventArc& arc) {
  const V3 d0 = arc_direction(scene, arc, Exact(0)), d1 = arc_direction(scene, arc, Exact(1)),
           d2 = arc_direction(scene, arc, Exact(2));
  const V3 c2 = Exact(1, 2) * (d2 - Exact(2) * d1 + d0), c1 = d1 - d0 - c2;
  P3 f;
  for (int k = 0; k < 3; ++k) f[k] = poly_from({d0[k], c1[k], c2[k]});
  return f;
}
P constant(const Exact& x) { return poly_from({x}); }
P dotp(const V3& n, const P3& f) { return poly_scaled(f[0], n.x) + poly_scaled(f[1], n.y) + poly_scaled(f[2], n.z); }
P3 matp(const Mat& q, const P3& f) {
  P3 r;
  for (int i = 0; i < 3; ++i) r[i] = poly_scaled(f[0], q[i][0]) + poly_scaled(f[1], q[i][1]) + poly_scaled(f[2], q[i][2]);
  return r;
}
P dotpp(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
P3 crosspp(const P3& a, const P3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
P3 derivp(const P3& a) { return {poly_derivative(a[0]), poly_derivative(a[1]), poly_derivative(a[2])}; }
P3 constp(const V3& v) { return {constant(v.x), constant(v.y), constant(v.z)}; }

Exact below(const RootNumber& x) {
  Exact q;
  if (root_number_rational(x, &q)) return q;
  return Exact(CGAL::to_interval(x).first);
}
Exact above(const RootNumber& x) {
  Exact q;
  if (root_number_rational(x, &q)) return q;
  return Exact(CGAL::to_interval(x).second);
}

// The exact range of p (degree <= 2) over [a, b].
std::pair<Exact, Exact> range2(const P& p, const Exact& a, const Exact& b) {
  Exact lo = p(a), hi = lo;
  auto take = [&](const Exact& t) {
    const Exact v = p(t);
    if (v < lo) lo = v;
    if (hi < v) hi = v;
  };
  take(b);
  if (p.degree() == 2) {
    const Exact tv = -p.c[1] / (Exact(2) * p.c[2]);
    if (a < tv && tv < b) take(tv);
  }
  return {lo, hi};
}

// Where the interval of r lies against the open range (lo, hi) (RootNumbers): 1 strictly inside, -1 strictly
// outside, 0 undecided.
int against(const IsolatedRoot& r, const RootNumber& lo, const RootNumber& hi) {
  const RootNumber a(r.lo), b(r.hi);
  if (lo < a && b < hi) return 1;
  if (b < lo || hi < a || (r.exact() && (a == lo || a == hi))) return -1;
  return 0;
}

struct ArcData {
  P3 f;            // o f(t)
  std::array<V3, 3> a, u;  // edge lines A_i + s u_i
};

std::string edges_name(const DirectionEventArc& a) {
  std::string edges;
  for (int k = 0; k < 3; ++k)
    edges += std::string(k == 0 ? "" : (k == 1 ? ", " : " and ")) + std::to_string(a.edges[k][0]) + "-" +
             std::to_string(a.edges[k][1]);
  return edges;
}

}  // namespace

Vec3<Exact> eee_left_normal(const Scene& scene, const DirectionEventArc& arc, const EeeFaceChart& chart, const Exact& t) {
  const P3 f = arc_poly(scene, arc), df = derivp(f);
  const V3 p(f[0](t), f[1](t), f[2](t)), tan(df[0](t), df[1](t), df[2](t));
  const int kappa = CGAL::sign(dot(cross(chart.e1, chart.e2), chart.s));
  const V3 w = cross(p, tan);
  return kappa > 0 ? w : -w;
}

int eee_cone_sign_after(const Scene& scene, const DirectionEventArc& arc, const Mat& q, const Exact& s_e, int sigma) {
  const P3 f = arc_poly(scene, arc);
  const P psi = dotpp(f, matp(q, f));
  if (psi.c.empty()) return 0;
  const P p = poly_square_free(psi);
  Exact delta(1);
  for (int it = 0; it < 400; ++it, delta /= 2) {
    const Exact b = sigma > 0 ? s_e + delta : s_e - delta;
    if (CGAL::sign(psi(b)) == 0) continue;
    const int inside = sigma > 0 ? poly_root_count(p, s_e, b) : poly_root_count(p, b, s_e) - (CGAL::sign(p(s_e)) == 0 ? 1 : 0);
    if (inside == 0) return CGAL::sign(psi(b));
  }
  return 0;
}

EeeCrossings find_eee_crossings(const Scene& scene, const DirectionEventArcs& events, const GreatCircleArrangement& arr,
                                const EeeArcInsertion& ins) {
  EeeCrossings out;
  out.of_subarc.resize(ins.subarcs.size());
  auto fail = [&](int arc, const std::string& why) {
    out.ok = false;
    out.problem = "a free EEE event arc (lines meeting the edges " + edges_name(events.arcs[arc]) + ", by vertex index) " +
                  why + ", outside the subset of EEE arcs the orthographic aspect graph handles (docs/theory.md 10.11)";
    return out;
  };
  std::map<int, ArcData> data;
  auto arc_data = [&](int ai) -> const ArcData& {
    auto it = data.find(ai);
    if (it != data.end()) return it->second;
    ArcData d;
    d.f = arc_poly(scene, events.arcs[ai]);
    for (int k = 0; k < 3; ++k) {
      d.a[k] = to_rational(scene.vertices[events.arcs[ai].edges[k][0]]);
      d.u[k] = to_rational(scene.vertices[events.arcs[ai].edges[k][1]]) - d.a[k];
    }
    return data.emplace(ai, std::move(d)).first->second;
  };
  // The distinct triangle planes (normals up to scale) and the scene's edges.
  std::set<std::array<Exact, 3>> plane_keys;
  std::vector<V3> planes;
  std::set<std::pair<int, int>> edges;
  for (const auto& tri : scene.triangles) {
    const V3 p0 = to_rational(scene.corner(tri, 0));
    V3 n = cross(to_rational(scene.corner(tri, 1)) - p0, to_rational(scene.corner(tri, 2)) - p0);
    for (int k = 0; k < 3; ++k)
      if (CGAL::sign(n[k]) != 0) {
        const Exact s = n[k];
        n = V3(n.x / s, n.y / s, n.z / s);
        break;
      }
    if (plane_keys.insert({n.x, n.y, n.z}).second) planes.push_back(n);
    for (int k = 0; k < 3; ++k) edges.insert({std::min(tri.v[k], tri.v[(k + 1) % 3]), std::max(tri.v[k], tri.v[(k + 1) % 3])});
  }
  // The line of an arc at parameter t meets edge (x, y)'s line iff det(x - P(t), f(t), y - x) = 0 (cubic in t).
  auto side_poly = [&](const ArcData& d, int x, int y) {
    const V3 a = to_rational(scene.vertices[x]), b = to_rational(scene.vertices[y]);
    const P3 pt{constant(d.a[0].x) + poly_from({Exact(0), d.u[0].x}), constant(d.a[0].y) + poly_from({Exact(0), d.u[0].y}),
                constant(d.a[0].z) + poly_from({Exact(0), d.u[0].z})};
    const P3 ap{constant(a.x) - pt[0], constant(a.y) - pt[1], constant(a.z) - pt[2]};
    return dotpp(ap, crosspp(d.f, constp(b - a)));
  };
  // Does it meet the closed segment? Coplanar lines (side product 0 at the root): with n = f x (y - x), iff x and
  // y are not strictly on one side of the line in their common plane (signs of ((x - P) x f) . n and
  // ((y - P) x f) . n); parallel (n = 0): iff the lines coincide ((x - P) x f = 0). Signs at the root, exact.
  auto meets_other_edge = [&](int ai, const ExactPolynomial& p, IsolatedRoot& r) {
    const ArcData& d = arc_data(ai);
    std::set<std::pair<int, int>> own;
    for (const auto& e : events.arcs[ai].edges) own.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
    const P3 pt{constant(d.a[0].x) + poly_from({Exact(0), d.u[0].x}), constant(d.a[0].y) + poly_from({Exact(0), d.u[0].y}),
                constant(d.a[0].z) + poly_from({Exact(0), d.u[0].z})};
    auto zero3 = [&](const P3& v) {
      return sign_at_root(p, r, v[0]) == 0 && sign_at_root(p, r, v[1]) == 0 && sign_at_root(p, r, v[2]) == 0;
    };
    for (const auto& [x, y] : edges) {
      if (own.count({x, y}) || sign_at_root(p, r, side_poly(d, x, y)) != 0) continue;
      const V3 a = to_rational(scene.vertices[x]), b = to_rational(scene.vertices[y]);
      const P3 ap{constant(a.x) - pt[0], constant(a.y) - pt[1], constant(a.z) - pt[2]};
      const P3 bp{constant(b.x) - pt[0], constant(b.y) - pt[1], constant(b.z) - pt[2]};
      const P3 n = crosspp(d.f, constp(b - a));
      const P3 af = crosspp(ap, d.f), bf = crosspp(bp, d.f);
      if (zero3(n)) {
        if (zero3(af)) return true;
        continue;
      }
      if (sign_at_root(p, r, dotpp(af, n)) * sign_at_root(p, r, dotpp(bf, n)) <= 0) return true;
    }
    return false;
  };

  for (std::size_t f = 0; f < ins.subarcs_of_face.size(); ++f) {
    const auto& subs = ins.subarcs_of_face[f];
    if (subs.size() < 2) continue;
    const EeeFaceChart chart = eee_face_chart(arr, static_cast<int>(f));
    const int kappa = CGAL::sign(dot(cross(chart.e1, chart.e2), chart.s));
    for (int ui : subs)
      for (int wi : subs) {
        const EeeSubArc &u = ins.subarcs[ui], &w = ins.subarcs[wi];
        if (u.arc >= w.arc) continue;
        const ArcData &da = arc_data(u.arc), &db = arc_data(w.arc);
        const P phi = dotpp(da.f, matp(ins.cone[w.arc], da.f));
        if (phi.c.empty()) continue;  // one cone: certified apart by aspect/eee_arc_insertion's boxes
        const P p = poly_square_free(phi);
        const RootNumber &u0 = ins.points[u.first].t, &u1 = ins.points[u.second].t;
        const RootNumber &w0 = ins.points[w.first].t, &w1 = ins.points[w.second].t;
        // b's parameter of a direction d: (d . kn) / (d . kd), with the second or third edge of b.
        std::array<V3, 2> kn, kd;
        for (int j = 1; j <= 2; ++j) {
          kn[j - 1] = cross(db.a[j] - db.a[0], db.u[j]);
          kd[j - 1] = cross(db.u[0], db.u[j]);
        }
        // An end of u inside the face lying on w (a T-junction of two arcs) is outside the subset.
        for (int e : {u.first, u.second}) {
          const EeeArcPoint& pt = ins.points[e];
          if (pt.circle >= 0 || !pt.rational) continue;
          Exact te;
          root_number_rational(pt.t, &te);
          if (CGAL::sign(phi(te)) != 0) continue;
          const V3& d = pt.direction;
          for (int j = 0; j < 2; ++j) {
            if (CGAL::sign(dot(d, kd[j])) == 0) continue;
            const RootNumber s(dot(d, kn[j]) / dot(d, kd[j]));
            if (w0 < s && s < w1) return fail(u.arc, "ends on another free EEE arc inside a face of the great circles");
            break;
          }
        }
        if (p.degree() < 1) continue;
        for (IsolatedRoot r : isolate_roots(p, below(u0), above(u1))) {
          // Skip the roots at u's ends (common cut points on circles, or u's end on b's cone).
          bool end = false;
          for (const RootNumber& e : {u0, u1})
            if (!(e < RootNumber(r.lo)) && !(RootNumber(r.hi) < e) && CGAL::sign(phi(e)) == 0) end = true;
          if (end) continue;
          int where = 0;
          for (int it = 0; it < 400 && (where = against(r, u0, u1)) == 0; ++it) refine_root(p, r);
          if (where == 0) return fail(u.arc, "meets another free EEE arc too close to a circle (not separated)");
          if (where < 0) continue;
          // The parameter on b: its range over r's interval, refined until inside or outside w's range.
          int j = 0;
          if (sign_at_root(p, r, dotp(kd[0], da.f)) == 0) j = 1;
          if (sign_at_root(p, r, dotp(kd[j], da.f)) == 0) return fail(u.arc, "meets the cone of another free EEE arc at a direction parallel to two of its edges");
          const P num = dotp(kn[j], da.f), den = dotp(kd[j], da.f);
          IsolatedRoot s;
          int inside = 0;
          for (int it = 0; it < 400; ++it) {
            const auto dr = range2(den, r.lo, r.hi);
            if (CGAL::sign(dr.first) * CGAL::sign(dr.second) > 0) {
              const auto nr = range2(num, r.lo, r.hi);
              const Exact c[4] = {nr.first / dr.first, nr.first / dr.second, nr.second / dr.first, nr.second / dr.second};
              s = {*std::min_element(c, c + 4), *std::max_element(c, c + 4)};
              if ((inside = against(s, w0, w1)) != 0) break;
            }
            refine_root(p, r);
          }
          if (inside == 0) return fail(u.arc, "meets another free EEE arc too close to its cut points (not separated)");
          if (inside < 0) continue;
          // A crossing X of u and w. Isolate it on b by q_a(f_b(s)).
          const P psi = dotpp(db.f, matp(ins.cone[u.arc], db.f));
          if (psi.c.empty()) return fail(w.arc, "lies on the cone of another free EEE arc");
          const P q = poly_square_free(psi);
          bool isolated = false;
          for (int it = 0; it < 400 && !isolated; ++it) {
            if (s.lo < s.hi && CGAL::sign(q(s.lo)) * CGAL::sign(q(s.hi)) < 0 && poly_root_count(q, s.lo, s.hi) == 1) {
              isolated = true;
              break;
            }
            if (s.exact() && CGAL::sign(q(s.lo)) == 0) {
              isolated = true;
              break;
            }
            refine_root(p, r);
            const auto dr = range2(den, r.lo, r.hi);
            const auto nr = range2(num, r.lo, r.hi);
            const Exact c[4] = {nr.first / dr.first, nr.first / dr.second, nr.second / dr.first, nr.second / dr.second};
            s = {*std::min_element(c, c + 4), *std::max_element(c, c + 4)};
          }
          if (!isolated) return fail(w.arc, "crosses another free EEE arc at a point not isolated on it");
          // The checks under which the crossing's aspect is that of the pieces next to it (docs/theory.md 10.11).
          if (sign_at_root(p, r, poly_derivative(phi)) == 0)
            return fail(u.arc, "touches another free EEE arc (a multiple intersection)");
          for (const V3& n : planes)
            if (sign_at_root(p, r, dotp(n, da.f)) == 0)
              return fail(u.arc, "crosses another free EEE arc on the plane of a triangle (seen edge-on there)");
          for (int gi : subs) {
            const int g = ins.subarcs[gi].arc;
            if (g == u.arc || g == w.arc) continue;
            if (sign_at_root(p, r, dotpp(da.f, matp(ins.cone[g], da.f))) == 0)
              return fail(u.arc, "crosses another free EEE arc where a third one passes");
          }
          if (meets_other_edge(u.arc, p, r) || meets_other_edge(w.arc, q, s))
            return fail(u.arc, "crosses another free EEE arc where one of the two lines meets a fourth edge");
          // Orientation: sign det(X, f_a', f_b') = sign(Phi'(r)) sign(h_b(s)), h_b = det(f_b', f_b, Q_b f_b)
          // (docs/theory.md 10.11); in the chart times sign det(e1, e2, s).
          const int dphi = sign_at_root(p, r, poly_derivative(phi));
          const P hb = dotpp(derivp(db.f), crosspp(db.f, matp(ins.cone[w.arc], db.f)));
          const int sh = sign_at_root(q, s, hb);
          if (sh == 0) return fail(w.arc, "is singular where it crosses another free EEE arc");
          EeeCrossing x;
          x.face = static_cast<int>(f);
          x.subarc = {ui, wi};
          x.poly = {p, q};
          x.t = {r, s};
          x.turn = dphi * sh * kappa;
          const double tr = CGAL::to_double((r.lo + r.hi) / 2);
          for (int k = 0; k < 3; ++k) {
            double v = 0;
            for (int i = da.f[k].degree(); i >= 0; --i) v = v * tr + CGAL::to_double(da.f[k].c[i]);
            x.direction[k] = v;
          }
          out.crossings.push_back(std::move(x));
        }
      }
  }
  // Order the crossings along each sub-arc: refine their intervals until pairwise disjoint.
  for (std::size_t c = 0; c < out.crossings.size(); ++c)
    for (int side = 0; side < 2; ++side) out.of_subarc[out.crossings[c].subarc[side]].push_back({static_cast<int>(c), side});
  for (std::size_t sa = 0; sa < out.of_subarc.size(); ++sa) {
    auto& list = out.of_subarc[sa];
    for (std::size_t i = 0; i < list.size(); ++i)
      for (std::size_t j = i + 1; j < list.size(); ++j) {
        EeeCrossing &x = out.crossings[list[i][0]], &y = out.crossings[list[j][0]];
        IsolatedRoot &rx = x.t[list[i][1]], &ry = y.t[list[j][1]];
        for (int it = 0; !(rx.hi < ry.lo || ry.hi < rx.lo); ++it) {
          if (it > 400) return fail(ins.subarcs[sa].arc, "has two crossings with other free EEE arcs not separated");
          refine_root(x.poly[list[i][1]], rx);
          refine_root(y.poly[list[j][1]], ry);
        }
      }
    std::sort(list.begin(), list.end(), [&](const std::array<int, 2>& a, const std::array<int, 2>& b) {
      return out.crossings[a[0]].t[a[1]].hi < out.crossings[b[0]].t[b[1]].lo;
    });
  }
  return out;
}

}  // namespace exactvis
