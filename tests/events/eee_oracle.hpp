#pragma once
// Brute-force validity oracle for EEE lines (independent of events/: GMP rationals only, its own formulation).
//
// For edges (a1, b1), (a2, b2), (a3, b3) (vertex ids of a mesh) and a rational t, the line L(t) through
// P = A1 + t (B1 - A1) meeting the lines of the other two edges has direction u = n2 x n3, n_k = d_k x (A_k - P)
// (the normals of the planes through P and each line). Its meeting point with line k is found from
// (P - A_k) x u = s_k (d_k x u). Valid iff 0 < t < 1, both meeting points finite with 0 < s_k < 1, the edge
// rule holds at all three edges (opposite vertices of the edge's triangles strictly on one side of the plane
// of L and the edge), and the open segment between the two outermost meeting points misses every closed
// triangle that has none of the three edges as an edge (the segment test of ev_oracle.hpp, also GMP-only).
#include "tests/events/ev_oracle.hpp"

#include <optional>

namespace eee_oracle {

using ev_oracle::crossp;
using ev_oracle::dotp;
using ev_oracle::Mesh;
using ev_oracle::P3;
using ev_oracle::Q;
using ev_oracle::sgn_q;

inline bool is_zero(const P3& v) { return v.x == 0 && v.y == 0 && v.z == 0; }

struct LineAt {
  P3 p, u;                  // L(t) = p + lambda u
  std::optional<Q> s2, s3;  // parameters along edges 2 and 3 (nullopt: parallel to that line)
  P3 q2, q3;
};

// The line of parameter t (edges given by their endpoint positions). Requires pairwise skew lines.
inline LineAt line_at(const std::array<P3, 3>& a, const std::array<P3, 3>& b, const Q& t) {
  LineAt l;
  l.p = a[0] + t * (b[0] - a[0]);
  const P3 d2 = b[1] - a[1], d3 = b[2] - a[2];
  const P3 n2 = crossp(d2, a[1] - l.p), n3 = crossp(d3, a[2] - l.p);
  l.u = crossp(n2, n3);
  auto meet = [&](const P3& A, const P3& d, P3* q) -> std::optional<Q> {
    const P3 du = crossp(d, l.u);
    if (is_zero(du)) return std::nullopt;
    const Q s = dotp(crossp(l.p - A, l.u), du) / dotp(du, du);
    *q = A + s * d;
    return s;
  };
  l.s2 = meet(a[1], d2, &l.q2);
  l.s3 = meet(a[2], d3, &l.q3);
  return l;
}

// Validity of L(t) for the edges e[k] = {vertex id, vertex id} of mesh m.
inline bool valid(const Mesh& m, const std::array<std::array<int, 2>, 3>& e, const Q& t) {
  if (t <= 0 || t >= 1) return false;
  std::array<P3, 3> a, b;
  for (int k = 0; k < 3; ++k) a[k] = m.v[e[k][0]], b[k] = m.v[e[k][1]];
  const LineAt l = line_at(a, b, t);
  if (!l.s2 || !l.s3) return false;
  if (*l.s2 <= 0 || *l.s2 >= 1 || *l.s3 <= 0 || *l.s3 >= 1) return false;
  // Sanity of the construction: both meeting points on the line.
  if (!is_zero(crossp(l.q2 - l.p, l.u)) || !is_zero(crossp(l.q3 - l.p, l.u))) return false;  // never
  // Edge rule at each edge.
  for (int k = 0; k < 3; ++k) {
    const P3 x = k == 0 ? l.p + l.u : l.p;  // a point of L off line k
    int side = 0;
    for (const auto& tr : m.t) {
      if (!(ev_oracle::has(tr, e[k][0]) && ev_oracle::has(tr, e[k][1]))) continue;
      const int w = tr[0] + tr[1] + tr[2] - e[k][0] - e[k][1];
      const int s = sgn_q(ev_oracle::orient(a[k], b[k], x, m.v[w]));
      if (s == 0 || (side != 0 && s != side)) return false;
      side = s;
    }
  }
  // Outermost meeting points along u.
  const std::array<P3, 3> pts{l.p, l.q2, l.q3};
  int lo = 0, hi = 0;
  for (int k = 1; k < 3; ++k) {
    if (dotp(pts[k], l.u) < dotp(pts[lo], l.u)) lo = k;
    if (dotp(pts[k], l.u) > dotp(pts[hi], l.u)) hi = k;
  }
  for (const auto& tr : m.t) {
    bool generator_face = false;
    for (int k = 0; k < 3; ++k) generator_face |= ev_oracle::has(tr, e[k][0]) && ev_oracle::has(tr, e[k][1]);
    if (generator_face) continue;
    if (ev_oracle::open_segment_meets_triangle(pts[lo], pts[hi], m.v[tr[0]], m.v[tr[1]], m.v[tr[2]])) return false;
  }
  return true;
}

}  // namespace eee_oracle
