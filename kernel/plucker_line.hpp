#pragma once
// Plücker coordinates of directed lines.
//
// Convention (docs/theory.md, "Plücker coordinates"): the directed line through P then Q is the 6-vector
// (d, m) with direction d = Q - P and moment m = P x Q. It is defined up to a positive factor; a negative
// factor reverses the direction. Real lines satisfy d . m = 0 (the Plücker quadric).
//
// side(a, b) = d_a . m_b + d_b . m_a  (the permuted inner product). It is 0 iff the lines meet or are
// parallel; otherwise its sign says how they pass each other. For a through p_a and b through p_b,
// side(a, b) = (p_a - p_b) . (d_a x d_b) = d_b . ((p_a - p_b) x d_a): side(a, b) > 0 iff a turns
// counterclockwise about b by the right-hand rule (thumb along d_b), i.e. looking along b (d_b pointing away
// from the eye) a passes b clockwise. For lines through points, side(line(p1,q1), line(p2,q2)) equals
// orient3d(p1,q1,p2,q2) exactly. See docs/theory.md, section 2 (checked by tests/kernel/test_predicates.cpp).
#include "kernel/vec3.hpp"

namespace exactvis {

template <class NT>
struct PluckerLine {
  Vec3<NT> d;  // direction
  Vec3<NT> m;  // moment
  template <class Other>
  static PluckerLine from(const PluckerLine<Other>& o) { return {Vec3<NT>::from(o.d), Vec3<NT>::from(o.m)}; }
  const NT& operator[](int i) const { return i < 3 ? d[i] : m[i - 3]; }
  NT& operator[](int i) { return i < 3 ? d[i] : m[i - 3]; }
  friend bool operator==(const PluckerLine& a, const PluckerLine& b) { return a.d == b.d && a.m == b.m; }
};

// The directed line through p then q.
template <class NT>
PluckerLine<NT> line_through(const Vec3<NT>& p, const Vec3<NT>& q) {
  return {q - p, cross(p, q)};
}

// Permuted inner product (side operator).
template <class NT>
NT side(const PluckerLine<NT>& a, const PluckerLine<NT>& b) {
  return dot(a.d, b.m) + dot(b.d, a.m);
}

// The Plücker quadric form d . m (zero exactly for real lines, and for "lines at infinity" d = 0).
template <class NT>
NT quadric(const PluckerLine<NT>& a) {
  return dot(a.d, a.m);
}

template <class NT>
PluckerLine<NT> reversed(const PluckerLine<NT>& a) {
  return {-a.d, -a.m};
}

}  // namespace exactvis
