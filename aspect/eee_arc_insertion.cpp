#include "aspect/eee_arc_insertion.hpp"

#include "aspect/eee_direction_cone.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quadratic_polynomial.hpp"
#include "kernel/rational_between.hpp"

#include <algorithm>
#include <map>

namespace exactvis {
namespace {

using V3 = Vec3<Exact>;
using R3 = Vec3<RootNumber>;
using QP = QuadraticPolynomial;



// o f(t) = c0 + t c1 + t^2 c2 (from three exact values of arc_direction: the family direction is quadratic).
struct ArcPoly {
  V3 c0, c1, c2;
  V3 at(const Exact& t) const { return c0 + t * c1 + (t * t) * c2; }
};
ArcPoly arc_poly(const Scene& scene, const DirectionEventArc& arc) {
  const V3 d0 = arc_direction(scene, arc, Exact(0)), d1 = arc_direction(scene, arc, Exact(1)),
           d2 = arc_direction(scene, arc, Exact(2));
  ArcPoly p;
  p.c0 = d0;
  p.c2 = Exact(1, 2) * (d2 - Exact(2) * d1 + d0);
  p.c1 = d1 - d0 - p.c2;
  return p;
}
QP along(const V3& n, const ArcPoly& p) {
  QP q;
  q.c = {dot(n, p.c0), dot(n, p.c1), dot(n, p.c2)};
  return q;
}
RootNumber rn(const Exact& x) { return RootNumber(x); }
R3 at_root(const ArcPoly& p, const RootNumber& t) {
  R3 r;
  for (int k = 0; k < 3; ++k) r[k] = rn(p.c0[k]) + t * rn(p.c1[k]) + t * t * rn(p.c2[k]);
  return r;
}
RootNumber dot_r(const V3& n, const R3& d) { return rn(n.x) * d.x + rn(n.y) * d.y + rn(n.z) * d.z; }
R3 cross_vr(const V3& a, const R3& b) {
  return {rn(a.y) * b.z - rn(a.z) * b.y, rn(a.z) * b.x - rn(a.x) * b.z, rn(a.x) * b.y - rn(a.y) * b.x};
}
R3 cross_rv(const R3& a, const V3& b) { return {-(cross_vr(b, a).x), -(cross_vr(b, a).y), -(cross_vr(b, a).z)}; }

Exact quad_form(const std::array<std::array<Exact, 3>, 3>& q, const V3& a, const V3& b) {
  Exact v(0);
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) v += a[r] * q[r][s] * b[s];
  return v;
}

// The exact range [lo, hi] of c0 + c1 t + c2 t^2 over [a, b].
std::pair<Exact, Exact> quad_range(const QP& p, const Exact& a, const Exact& b) {
  Exact lo = p(a), hi = lo;
  auto take = [&](const Exact& t) {
    const Exact v = p(t);
    if (v < lo) lo = v;
    if (hi < v) hi = v;
  };
  take(b);
  if (CGAL::sign(p.c[2]) != 0) {
    const Exact tv = -p.c[1] / (Exact(2) * p.c[2]);
    if (a < tv && tv < b) take(tv);
  }
  return {lo, hi};
}

struct Box {
  bool ok = false;
  Exact x0, x1, y0, y1;
};

// An exact box holding the chart image (X, Y) = (d . e1, d . e2) / (d . s) of the sub-arc's directions for
// t in [a, b]; !ok when d . s is not certified positive there.
Box chart_box(const ArcPoly& p, const V3& s, const V3& e1, const V3& e2, const Exact& a, const Exact& b) {
  Box box;
  const auto den = quad_range(along(s, p), a, b);
  if (CGAL::sign(den.first) <= 0) return box;
  auto ratio = [&](const std::pair<Exact, Exact>& num, Exact& lo, Exact& hi) {
    const Exact c[4] = {num.first / den.first, num.first / den.second, num.second / den.first, num.second / den.second};
    lo = *std::min_element(c, c + 4);
    hi = *std::max_element(c, c + 4);
  };
  ratio(quad_range(along(e1, p), a, b), box.x0, box.x1);
  ratio(quad_range(along(e2, p), a, b), box.y0, box.y1);
  box.ok = true;
  return box;
}
bool boxes_disjoint(const Box& a, const Box& b) {
  return a.x1 < b.x0 || b.x1 < a.x0 || a.y1 < b.y0 || b.y1 < a.y0;
}

// Rational enclosure [lo, hi] of a parameter range [a, b] (a, b exact in Q(sqrt D)).
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

// (X(t) - X(t_e), Y(t) - Y(t_e)) = (t - t_e) (L1(t), L2(t)) / (den(t) den(t_e)) in a face chart: the linear
// factors L_i = l[i][0] + l[i][1] t (exact; the numerators are quadratics vanishing at t_e).
std::array<std::array<Exact, 2>, 2> chart_chord_factor(const ArcPoly& p, const EeeFaceChart& c, const Exact& te) {
  const QP den = along(c.s, p);
  std::array<std::array<Exact, 2>, 2> l;
  for (int i = 0; i < 2; ++i) {
    const QP num = along(i == 0 ? c.e1 : c.e2, p);
    const Exact nx = num(te), dx = den(te);
    QP q;
    for (int k = 0; k < 3; ++k) q.c[k] = num.c[k] * dx - nx * den.c[k];
    l[i] = {q.c[1] + q.c[2] * te, q.c[2]};
  }
  return l;
}
Exact cross2(const std::array<Exact, 2>& a, const std::array<Exact, 2>& b) { return a[0] * b[1] - a[1] * b[0]; }
// Is v in the closed cone of a, b (an angle below pi, or a ray when a, b are parallel)?
bool in_cone2(const std::array<Exact, 2>& v, const std::array<Exact, 2>& a, const std::array<Exact, 2>& b) {
  const int o = CGAL::sign(cross2(a, b));
  if (o == 0) return CGAL::sign(cross2(a, v)) == 0 && CGAL::sign(a[0] * v[0] + a[1] * v[1]) > 0;
  return CGAL::sign(cross2(a, v)) * o >= 0 && CGAL::sign(cross2(v, b)) * o >= 0;
}
// The directions from the common end (at parameters te on each arc) to the points of the arcs for t between
// te and the other bound o lie in the cone of the factor's values at te and o (times sign(o - te)): the
// factor is linear. Disjoint cones (each below pi) mean the two pieces meet only at the end.
bool wedges_disjoint(const ArcPoly& p, const EeeFaceChart& c, const Exact& tp, const Exact& op, const ArcPoly& q,
                     const Exact& tq, const Exact& oq) {
  auto cone = [&](const ArcPoly& a, const Exact& te, const Exact& o, std::array<Exact, 2>& g0, std::array<Exact, 2>& g1) {
    const auto l = chart_chord_factor(a, c, te);
    const Exact sg(o < te ? -1 : 1);
    g0 = {sg * (l[0][0] + l[0][1] * te), sg * (l[1][0] + l[1][1] * te)};
    g1 = {sg * (l[0][0] + l[0][1] * o), sg * (l[1][0] + l[1][1] * o)};
    const bool zero0 = CGAL::sign(g0[0]) == 0 && CGAL::sign(g0[1]) == 0, zero1 = CGAL::sign(g1[0]) == 0 && CGAL::sign(g1[1]) == 0;
    if (zero0 || zero1) return false;
    return !(CGAL::sign(cross2(g0, g1)) == 0 && CGAL::sign(g0[0] * g1[0] + g0[1] * g1[1]) < 0);
  };
  auto den_positive = [&](const ArcPoly& a, const Exact& x, const Exact& y) {
    return CGAL::sign(quad_range(along(c.s, a), x < y ? x : y, x < y ? y : x).first) > 0;
  };
  if (!den_positive(p, tp, op) || !den_positive(q, tq, oq)) return false;
  std::array<Exact, 2> a0, a1, b0, b1;
  if (!cone(p, tp, op, a0, a1) || !cone(q, tq, oq, b0, b1)) return false;
  // The chart images must also have positive denominators on both pieces (the chart is central).
  return !in_cone2(a0, b0, b1) && !in_cone2(a1, b0, b1) && !in_cone2(b0, a0, a1) && !in_cone2(b1, a0, a1);
}

}  // namespace

EeeArcInsertion insert_eee_arcs(const Scene& scene, const DirectionEventArcs& events,
                                const GreatCircleArrangement& arr, const std::vector<V3>& normals,
                                const std::vector<char>& on_circle) {
  EeeArcInsertion out;
  out.cone.resize(events.arcs.size());
  out.subarcs_of_face.resize(arr.faces.size());
  auto fail = [&](const DirectionEventArc& a, const std::string& why) {
    std::string edges;
    for (int k = 0; k < 3; ++k)
      edges += std::string(k == 0 ? "" : (k == 1 ? ", " : " and ")) + std::to_string(a.edges[k][0]) + "-" +
               std::to_string(a.edges[k][1]);
    out.ok = false;
    out.problem = "a free EEE event arc (lines meeting the edges " + edges + ", by vertex index) " + why +
                  ", outside the subset of EEE arcs the orthographic aspect graph handles (docs/theory.md 10.11)";
  };
  std::vector<std::vector<int>> arcs_of_circle(normals.size());
  for (std::size_t a = 0; a < arr.arcs.size(); ++a) arcs_of_circle[arr.arcs[a].circle].push_back(static_cast<int>(a));
  std::map<std::string, int> face_of_signs;
  auto signs_of = [&](const V3& d, bool* on_circle) {
    std::string s(normals.size(), '0');
    for (std::size_t k = 0; k < normals.size(); ++k) {
      const int g = CGAL::sign(dot(normals[k], d));
      s[k] = g > 0 ? '+' : (g < 0 ? '-' : '0');
      if (g == 0 && on_circle) *on_circle = true;
    }
    return s;
  };
  for (std::size_t f = 0; f < arr.faces.size(); ++f) face_of_signs[signs_of(face_sample(arr, static_cast<int>(f)), nullptr)] = static_cast<int>(f);
  std::vector<ArcPoly> polys(events.arcs.size());

  for (std::size_t ai = 0; ai < events.arcs.size() && out.ok; ++ai) {
    const DirectionEventArc& a = events.arcs[ai];
    if (a.type != DirectionEventArc::Type::EEE || on_circle[ai]) continue;
    {
      std::array<V3, 3> pa, pu;
      for (int k = 0; k < 3; ++k) {
        pa[k] = to_rational(scene.vertices[a.edges[k][0]]);
        pu[k] = to_rational(scene.vertices[a.edges[k][1]]) - pa[k];
      }
      out.cone[ai] = eee_direction_cone(pa, pu).q;
    }
    const ArcPoly p = arc_poly(scene, a);
    polys[ai] = p;
    Exact t0, t1;
    if (!root_number_rational(a.t0, &t0) || !root_number_rational(a.t1, &t1)) {
      fail(a, "ends at an irrational parameter (its line starts or stops being blocked by grazing a fourth edge)");
      return out;
    }
    // Cut parameters: the ends and the crossings with every circle.
    std::vector<RootNumber> cuts{rn(t0), rn(t1)};
    for (std::size_t k = 0; k < normals.size(); ++k) {
      const QP q = along(normals[k], p);
      if (q.degree() < 0) {
        fail(a, "lies on a great circle of the partition");
        return out;
      }
      // A double root (the arc touching the circle, at a rational point) is a cut like a crossing: both
      // sub-arcs next to it lie in one face, their ends at one boundary point ordered by the sweep of their
      // tangents (general_orthographic_aspect_graph, docs/theory.md 10.11).
      for (const RealRoot& r : real_roots(q))
        if (!(r.t < rn(t0)) && !(rn(t1) < r.t)) cuts.push_back(r.t);
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    const int first_point = static_cast<int>(out.points.size());
    for (const RootNumber& t : cuts) {
      EeeArcPoint pt;
      pt.arc = static_cast<int>(ai);
      pt.t = t;
      pt.arc_end = t == rn(t0) || t == rn(t1);
      Exact tq;
      pt.rational = root_number_rational(t, &tq);
      const R3 d = at_root(p, t);
      if (CGAL::sign(d.x) == 0 && CGAL::sign(d.y) == 0 && CGAL::sign(d.z) == 0) {
        fail(a, "ends at a singular parameter (its family direction vanishes)");
        return out;
      }
      if (pt.rational) pt.direction = scaled_to_unit_max(p.at(tq));
      std::vector<int> on;
      for (std::size_t k = 0; k < normals.size(); ++k)
        if (CGAL::sign(dot_r(normals[k], d)) == 0) on.push_back(static_cast<int>(k));
      if (!on.empty()) pt.circle = on.front();
      if (on.size() >= 2) {
        for (std::size_t v = 0; v < arr.vertices.size() && pt.gc_vertex < 0; ++v) {
          const R3 c = cross_rv(d, arr.vertices[v]);
          if (CGAL::sign(c.x) == 0 && CGAL::sign(c.y) == 0 && CGAL::sign(c.z) == 0 &&
              CGAL::sign(dot_r(arr.vertices[v], d)) > 0)
            pt.gc_vertex = static_cast<int>(v);
        }
        if (pt.gc_vertex < 0) throw std::logic_error("insert_eee_arcs: a point on two circles is no vertex");
      } else if (on.size() == 1) {
        const V3& n = normals[pt.circle];
        for (int g : arcs_of_circle[pt.circle]) {
          const V3 &from = arr.vertices[arr.arcs[g].from], &to = arr.vertices[arr.arcs[g].to];
          if (CGAL::sign(dot_r(n, cross_vr(from, d))) > 0 && CGAL::sign(dot_r(n, cross_rv(d, to))) > 0) {
            const V3 c = cross(from, to);
            if (CGAL::sign(c.x) == 0 && CGAL::sign(c.y) == 0 && CGAL::sign(c.z) == 0) {
              fail(a, "crosses a half-circle arc of the partition");
              return out;
            }
            const RootNumber al = dot_r(c, cross_rv(d, to)), be = dot_r(c, cross_vr(from, d));
            pt.gc_arc = g;
            pt.lambda = be / (al + be);
            break;
          }
        }
        if (pt.gc_arc < 0) throw std::logic_error("insert_eee_arcs: a point on a circle is on none of its arcs");
      }
      out.points.push_back(pt);
    }
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      EeeSubArc s;
      s.arc = static_cast<int>(ai);
      s.first = first_point + static_cast<int>(k);
      s.second = s.first + 1;
      s.t = rational_strictly_between(cuts[k], cuts[k + 1]);
      s.sample = scaled_to_unit_max(p.at(s.t));
      bool on_circle = false;
      const auto it = face_of_signs.find(signs_of(s.sample, &on_circle));
      if (on_circle || it == face_of_signs.end()) throw std::logic_error("insert_eee_arcs: a sub-arc in no face");
      s.face = it->second;
      out.subarcs_of_face[s.face].push_back(static_cast<int>(out.subarcs.size()));
      out.subarcs.push_back(s);
    }
  }
  if (!out.ok) return out;
  // Cut points of different arcs are distinct unless both are rational (then they are one vertex of the
  // partition); ends inside faces are distinct; within a face the sub-arcs of one arc are pairwise disjoint but
  // for common ends (exact boxes in the face's chart, refined by bisection; near a common end, the two wedges
  // of directions from it); sub-arcs of different arcs meet at crossings (aspect/eee_crossings).
  std::vector<int> same_as(out.points.size(), -1);
  for (std::size_t i = 0; i < out.points.size(); ++i)
    for (std::size_t j = i + 1; j < out.points.size(); ++j) {
      const EeeArcPoint &x = out.points[i], &y = out.points[j];
      if (x.arc == y.arc) continue;
      bool same = false;
      if (x.circle < 0 && y.circle < 0) same = x.direction == y.direction;
      else if (x.circle >= 0 && y.circle >= 0)
        same = (x.gc_vertex >= 0 && x.gc_vertex == y.gc_vertex) ||
               (x.gc_arc >= 0 && x.gc_arc == y.gc_arc && x.lambda == y.lambda);
      if (!same) continue;
      if (x.circle < 0) {
        fail(events.arcs[x.arc], "meets another free EEE arc inside a face of the great circles");
        return out;
      }
      if (!x.rational || !y.rational) {
        fail(events.arcs[x.arc], "meets another free EEE arc at an irrational direction");
        return out;
      }
      if (same_as[j] < 0) same_as[j] = same_as[i] >= 0 ? same_as[i] : static_cast<int>(i);
    }
  auto key = [&](int p) { return same_as[p] >= 0 ? same_as[p] : p; };
  for (std::size_t f = 0; f < arr.faces.size(); ++f) {
    const auto& subs = out.subarcs_of_face[f];
    if (subs.size() < 2) continue;
    const EeeFaceChart chart = eee_face_chart(arr, static_cast<int>(f));
    for (std::size_t i = 0; i < subs.size(); ++i)
      for (std::size_t j = i + 1; j < subs.size(); ++j) {
        const EeeSubArc &u = out.subarcs[subs[i]], &w = out.subarcs[subs[j]];
        // Sub-arcs of two different arcs meet exactly where aspect/eee_crossings finds them (the roots of one
        // arc's quartic on the other's cone); only pieces of one arc are certified apart here.
        // (Two arcs on one cone, e.g. one family's two orientations, are certified apart here too.)
        if (u.arc != w.arc) {
          bool same_cone = true;
          for (int k = 0; k < 5 && same_cone; ++k) {
            const V3 d = polys[u.arc].at(Exact(k));
            same_cone = CGAL::sign(quad_form(out.cone[w.arc], d, d)) == 0;
          }
          if (!same_cone) continue;
        }
        const Exact ua = below(out.points[u.first].t), ub = above(out.points[u.second].t);
        const Exact wa = below(out.points[w.first].t), wb = above(out.points[w.second].t);
        // Common ends: (end of u, end of w) pairs at one point (0 = first, 1 = second).
        std::vector<std::array<int, 2>> common;
        for (int k = 0; k < 2; ++k)
          for (int l = 0; l < 2; ++l)
            if (key(k == 0 ? u.first : u.second) == key(l == 0 ? w.first : w.second)) common.push_back({k, l});
        struct Job {
          Exact a0, a1, b0, b1;
        };
        std::vector<Job> stack{{ua, ub, wa, wb}};
        int steps = 0;
        bool certified = true;
        while (!stack.empty()) {
          const Job job = stack.back();
          stack.pop_back();
          // Both pieces at a common end: their wedges from it must be disjoint; else boxes.
          bool at_common = false, apart = false;
          for (const auto& [k, l] : common) {
            const bool ku = k == 0 ? job.a0 == ua : job.a1 == ub, lw = l == 0 ? job.b0 == wa : job.b1 == wb;
            if (!ku || !lw) continue;
            at_common = true;
            const Exact tu = k == 0 ? ua : ub, tw = l == 0 ? wa : wb;
            const Exact ou = k == 0 ? job.a1 : job.a0, ow = l == 0 ? job.b1 : job.b0;
            apart = wedges_disjoint(polys[u.arc], chart, tu, ou, polys[w.arc], tw, ow);
          }
          if (at_common ? apart : [&] {
                const Box bu = chart_box(polys[u.arc], chart.s, chart.e1, chart.e2, job.a0, job.a1),
                          bw = chart_box(polys[w.arc], chart.s, chart.e1, chart.e2, job.b0, job.b1);
                return bu.ok && bw.ok && boxes_disjoint(bu, bw);
              }())
            continue;
          if (++steps > 20000) {
            certified = false;
            break;
          }
          if (job.a1 - job.a0 >= job.b1 - job.b0) {
            const Exact m = (job.a0 + job.a1) / 2;
            stack.push_back({job.a0, m, job.b0, job.b1});
            stack.push_back({m, job.a1, job.b0, job.b1});
          } else {
            const Exact m = (job.b0 + job.b1) / 2;
            stack.push_back({job.a0, job.a1, job.b0, m});
            stack.push_back({job.a0, job.a1, m, job.b1});
          }
        }
        if (!certified) {
          fail(events.arcs[u.arc], "meets or nearly meets another free EEE arc (not certified apart)");
          return out;
        }
      }
  }
  return out;
}

EeeFaceChart eee_face_chart(const GreatCircleArrangement& arr, int face) {
  EeeFaceChart c;
  c.s = face_sample(arr, face);
  V3 axis(Exact(1), Exact(0), Exact(0));
  if (CGAL::abs(c.s.x) >= CGAL::abs(c.s.y) && CGAL::abs(c.s.x) >= CGAL::abs(c.s.z)) axis = V3(Exact(0), Exact(1), Exact(0));
  c.e1 = cross(c.s, axis);
  c.e2 = cross(c.s, c.e1);
  return c;
}

std::array<Exact, 2> chart_point(const EeeFaceChart& c, const V3& d) {
  const Exact den = dot(c.s, d);
  return {dot(c.e1, d) / den, dot(c.e2, d) / den};
}

std::array<Exact, 2> eee_end_tangent(const Scene& scene, const DirectionEventArc& arc, const EeeFaceChart& c,
                                     const Exact& t_end, int end) {
  const ArcPoly p = arc_poly(scene, arc);
  const auto l = chart_chord_factor(p, c, t_end);
  const Exact sg(end == 0 ? 1 : -1);
  return {sg * (l[0][0] + l[0][1] * t_end), sg * (l[1][0] + l[1][1] * t_end)};
}

std::optional<V3> sample_off_eee_arcs(const EeeArcInsertion& ins, const GreatCircleArrangement& arr, int face,
                                      const V3& p) {
  const V3 s = face_sample(arr, face);
  const V3 w = s - p;
  Exact eps(1);
  for (int si : ins.subarcs_of_face[face]) {
    const auto& q = ins.cone[ins.subarcs[si].arc];
    QP h;
    h.c = {quad_form(q, p, p), Exact(2) * quad_form(q, p, w), quad_form(q, w, w)};
    const int s0 = CGAL::sign(h.c[0]);
    if (s0 == 0) return std::nullopt;
    // Halve eps until h keeps the sign of h(0) on [0, eps] (at eps and at an extremum inside).
    for (;;) {
      bool ok = CGAL::sign(h(eps)) == s0;
      if (ok && CGAL::sign(h.c[2]) != 0) {
        const Exact tv = -h.c[1] / (Exact(2) * h.c[2]);
        if (CGAL::sign(tv) > 0 && tv < eps) ok = CGAL::sign(h(tv)) == s0;
      }
      if (ok) break;
      eps /= 2;
    }
  }
  return scaled_to_unit_max(p + eps * w);
}

}  // namespace exactvis
