#pragma once
// Plücker coordinates of directed lines.
//
// Convention (docs/theory.md, "Plücker coordinates"): the directed line through P then Q is the 6-vector
// (d, m) with direction d = Q - P and moment m = P x Q. It is defined up to a positive factor; a negative
// factor reverses the direction. Real lines satisfy d . m = 0 (the Plücker quadric).
//
// side(a, b) = d_a . m_b + d_b . m_a  (the permuted inner product). It is 0 iff the lines meet or are
// parallel; otherwise its sign says how they pass each other: side(a, b) > 0 iff, looking along b, the line a
// passes b counterclockwise ("right-handed screw"), see docs/theory.md for the exact statement.
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
