#pragma once
// An exact parameter value t = num / den (den > 0) over CGAL::Mpzf: ring operations only (no gcd, no
// allocation for small sizes), which makes the EV constructions several times faster than GMP rationals.
// Converted to Exact only for output.
#include "kernel/number_types.hpp"

#include <CGAL/Mpzf.h>

namespace exactvis {

using Ring = CGAL::Mpzf;

struct EvParameter {
  Ring num{0}, den{1};  // den > 0
  EvParameter() = default;
  // Requires d != 0; normalises the sign of the denominator.
  EvParameter(const Ring& n, const Ring& d) : num(n), den(d) {
    if (CGAL::sign(den) < 0) num = -num, den = -den;
  }
  static EvParameter integer(int v) { return {Ring(v), Ring(1)}; }
  Exact exact() const { return Exact(static_cast<CGAL::Gmpq>(num)) / Exact(static_cast<CGAL::Gmpq>(den)); }
};

inline int compare(const EvParameter& a, const EvParameter& b) {
  const Ring l = a.num * b.den, r = b.num * a.den;
  return l < r ? -1 : (r < l ? 1 : 0);
}
inline bool operator<(const EvParameter& a, const EvParameter& b) { return compare(a, b) < 0; }
inline bool operator>(const EvParameter& a, const EvParameter& b) { return compare(a, b) > 0; }
inline bool operator<=(const EvParameter& a, const EvParameter& b) { return compare(a, b) <= 0; }
inline bool operator>=(const EvParameter& a, const EvParameter& b) { return compare(a, b) >= 0; }
inline bool operator==(const EvParameter& a, const EvParameter& b) { return compare(a, b) == 0; }
inline EvParameter midpoint(const EvParameter& a, const EvParameter& b) {
  return {a.num * b.den + b.num * a.den, Ring(2) * a.den * b.den};
}

}  // namespace exactvis
