#pragma once
// Brute-force oracle for EV events (independent of events/: GMP rationals only, its own formulation).
//
// For vertex v and edge (a, b) it lists every parameter where validity can change (alignments of the line
// through v and P(t) with occluder vertices, edges, planes and fan vertices, each solved as a linear equation
// in t), decides validity exactly at each such parameter and between consecutive ones, and returns the closures
// of the valid components of positive length. Validity: the edge rule, vertex rule (a) (closed fans are not
// handled here: callers skip such vertices), and the open segment (v, P(t)) missing every closed occluder.
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

namespace ev_oracle {

using Q = mpq_class;
struct P3 {
  Q x, y, z;
};
inline P3 operator-(const P3& a, const P3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline P3 operator+(const P3& a, const P3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline P3 operator*(const Q& s, const P3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Q dotp(const P3& a, const P3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline P3 crossp(const P3& a, const P3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline int sgn_q(const Q& q) { return q > 0 ? 1 : (q < 0 ? -1 : 0); }
inline Q orient(const P3& a, const P3& b, const P3& c, const P3& d) { return dotp(crossp(b - a, c - a), d - a); }

struct Mesh {
  std::vector<P3> v;
  std::vector<std::array<int, 3>> t;
};

inline bool has(const std::array<int, 3>& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }

// Point x (in the plane of triangle a b c) inside the closed triangle.
inline bool in_closed_triangle(const P3& x, const P3& a, const P3& b, const P3& c) {
  const P3 n = crossp(b - a, c - a);
  const int s1 = sgn_q(dotp(crossp(b - a, x - a), n));
  const int s2 = sgn_q(dotp(crossp(c - b, x - b), n));
  const int s3 = sgn_q(dotp(crossp(a - c, x - c), n));
  return s1 >= 0 && s2 >= 0 && s3 >= 0;
}

// Does the open segment (p, q) meet the closed triangle (a, b, c)?
inline bool open_segment_meets_triangle(const P3& p, const P3& q, const P3& a, const P3& b, const P3& c) {
  const Q op = orient(a, b, c, p), oq = orient(a, b, c, q);
  const int sp = sgn_q(op), sq = sgn_q(oq);
  if (sp * sq > 0) return false;
  if ((sp == 0) != (sq == 0)) return false;  // only an endpoint touches the plane
  if (sp != 0) {
    const Q s = op / (op - oq);
    return in_closed_triangle(p + s * (q - p), a, b, c);
  }
  // Coplanar: clip s in [lo, hi] by the three closed half-planes, then intersect with (0, 1).
  const P3 n = crossp(b - a, c - a);
  Q lo = 0, hi = 1;
  bool lo_open = true, hi_open = true;
  const std::array<std::pair<P3, P3>, 3> edges{{{a, b}, {b, c}, {c, a}}};
  for (const auto& [u, w] : edges) {
    // f(s) = dot((w - u) x (p + s (q - p) - u), n) >= 0
    const Q f0 = dotp(crossp(w - u, p - u), n);
    const Q f1 = dotp(crossp(w - u, q - p), n);
    if (f1 == 0) {
      if (f0 < 0) return false;
      continue;
    }
    const Q r = -f0 / f1;
    if (f1 > 0) {  // s >= r
      if (r > lo) lo = r, lo_open = false;  // r <= lo: the open bound stays
    } else {       // s <= r
      if (r < hi) hi = r, hi_open = false;
    }
  }
  if (lo > hi) return false;
  if (lo == hi) return !lo_open && !hi_open;
  return true;
}

// Does the line through p and q meet the closed segment [u, w]?
inline bool line_meets_segment(const P3& p, const P3& q, const P3& u, const P3& w) {
  if (orient(p, q, u, w) != 0) return false;
  const P3 d = q - p;
  const P3 cu = crossp(d, u - p), cw = crossp(d, w - p);
  const Q s = dotp(cu, cw);  // <= 0 iff u, w on different sides of the line (or on it), in their plane
  return s <= 0;
}

// Entry parameter of the ray {p + s d : s > 0} into the closed triangle (a, b, c): the infimum of the s > 0
// where it is inside; false if none. Non-coplanar: the ratio of orientations of p and p + d.
inline bool ray_entry(const P3& p, const P3& d, const P3& a, const P3& b, const P3& c, Q* entry) {
  const P3 q = p + d;
  const Q op = orient(a, b, c, p), oq = orient(a, b, c, q);
  if (op != oq) {
    const Q s = op / (op - oq);
    if (s <= 0 || !in_closed_triangle(p + s * d, a, b, c)) return false;
    *entry = s;
    return true;
  }
  if (op != 0) return false;
  // Coplanar: scan the triangle's edges as constraints on s.
  const P3 n = crossp(b - a, c - a);
  Q lo = 0, hi = 0;
  bool has_hi = false;
  const std::array<std::pair<P3, P3>, 3> edges{{{a, b}, {b, c}, {c, a}}};
  for (const auto& [u, w] : edges) {
    const Q f0 = dotp(crossp(w - u, p - u), n), f1 = dotp(crossp(w - u, d), n);
    if (f1 == 0) {
      if (f0 < 0) return false;
      continue;
    }
    const Q r = -f0 / f1;
    if (f1 > 0) lo = std::max(lo, r);
    else if (!has_hi || r < hi) hi = r, has_hi = true;
  }
  if (has_hi && (hi < lo || hi <= 0)) return false;
  *entry = lo;
  return true;
}

// Smallest entry parameter over all triangles (false when the ray meets none).
inline bool first_entry(const Mesh& m, const P3& p, const P3& d, Q* best) {
  bool any = false;
  for (const auto& t : m.t) {
    Q s;
    if (ray_entry(p, d, m.v[t[0]], m.v[t[1]], m.v[t[2]], &s) && (!any || s < *best)) *best = s, any = true;
  }
  return any;
}

struct Interval {
  Q t0, t1;
};

inline std::vector<Interval> ev_intervals(const Mesh& m, int v, int a, int b) {
  const P3 V = m.v[v], A = m.v[a], B = m.v[b];
  if (crossp(A - V, B - V).x == 0 && crossp(A - V, B - V).y == 0 && crossp(A - V, B - V).z == 0) return {};
  // Edge rule (constant in t).
  int side = 0;
  for (const auto& t : m.t) {
    if (!(has(t, a) && has(t, b))) continue;
    int w = t[0] + t[1] + t[2] - a - b;
    const int s = sgn_q(orient(V, A, B, m.v[w]));
    if (s == 0 || (side != 0 && s != side)) return {};
    side = s;
  }
  auto point = [&](const Q& t) { return A + t * (B - A); };
  auto valid = [&](const Q& t) {
    const P3 P = point(t);
    for (const auto& tr : m.t) {
      if (has(tr, v)) {
        int k = 0;
        while (tr[k] != v) ++k;
        if (line_meets_segment(V, P, m.v[tr[(k + 1) % 3]], m.v[tr[(k + 2) % 3]])) return false;
        continue;
      }
      if (has(tr, a) && has(tr, b)) continue;
      if (open_segment_meets_triangle(V, P, m.v[tr[0]], m.v[tr[1]], m.v[tr[2]])) return false;
    }
    return true;
  };
  // Candidate parameters: each is a root of some f0 + t f1 (a scalar linear function of t).
  std::set<Q> cand{Q(0), Q(1)};
  auto root = [&](const Q& f0, const Q& f1) {
    if (f1 != 0) {
      const Q t = -f0 / f1;
      if (t > 0 && t < 1) cand.insert(t);
    }
  };
  auto through_point = [&](const P3& x) {  // line through V and P(t) passes x: V, P(t), x collinear
    const P3 c0 = crossp(A - V, x - V), c1 = crossp(B - A, x - V);
    for (const auto& [f0, f1] : {std::pair{c0.x, c1.x}, std::pair{c0.y, c1.y}, std::pair{c0.z, c1.z}}) {
      if (f1 != 0) {
        const Q t = -f0 / f1;
        const P3 c = crossp(point(t) - V, x - V);
        if (c.x == 0 && c.y == 0 && c.z == 0 && t > 0 && t < 1) cand.insert(t);
        return;
      }
    }
  };
  auto point_on_line = [&](const P3& u, const P3& w) {  // P(t) on the line u w
    const P3 c0 = crossp(A - u, w - u), c1 = crossp(B - A, w - u);
    for (const auto& [f0, f1] : {std::pair{c0.x, c1.x}, std::pair{c0.y, c1.y}, std::pair{c0.z, c1.z}}) {
      if (f1 != 0) {
        const Q t = -f0 / f1;
        const P3 c = crossp(point(t) - u, w - u);
        if (c.x == 0 && c.y == 0 && c.z == 0 && t > 0 && t < 1) cand.insert(t);
        return;
      }
    }
  };
  for (const auto& tr : m.t) {
    const P3 X = m.v[tr[0]], Y = m.v[tr[1]], Z = m.v[tr[2]];
    for (int k = 0; k < 3; ++k) {
      const P3 u = m.v[tr[k]], w = m.v[tr[(k + 1) % 3]];
      through_point(u);
      point_on_line(u, w);
      // line(V, P(t)) meets line(u, w): orient(V, P(t), u, w) = 0, linear in t.
      root(orient(V, A, u, w), orient(V, B, u, w) - orient(V, A, u, w));
    }
    // P(t) in the plane of the triangle.
    root(orient(X, Y, Z, A), orient(X, Y, Z, B) - orient(X, Y, Z, A));
  }
  std::vector<Q> c(cand.begin(), cand.end());
  std::vector<Interval> out;
  bool open = false;
  Q start;
  for (std::size_t i = 0; i + 1 < c.size(); ++i) {
    const bool piece = valid((c[i] + c[i + 1]) / 2);
    if (piece && !open) {
      open = true;
      start = c[i];
    }
    if (!piece && open) {
      out.push_back({start, c[i]});
      open = false;
    }
    if (open && i + 2 < c.size() && !valid(c[i + 1])) {
      out.push_back({start, c[i + 1]});
      open = false;
    }
  }
  if (open) out.push_back({start, c.back()});
  return out;
}

}  // namespace ev_oracle
