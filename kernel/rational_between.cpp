#include "kernel/rational_between.hpp"

#include <cmath>
#include <stdexcept>

namespace exactvis {

bool root_number_rational(const RootNumber& x, Exact* q) {
  if (x.is_extended() && !CGAL::is_zero(x.a1()) && !CGAL::is_zero(x.root())) return false;
  if (q) *q = x.a0();
  return true;
}

Exact rational_strictly_between(const RootNumber& a, const RootNumber& b) {
  if (!(a < b)) throw std::invalid_argument("rational_strictly_between: need a < b");
  Exact qa, qb;
  if (root_number_rational(a, &qa) && root_number_rational(b, &qb)) return (qa + qb) / 2;
  // Enclosures: to_interval is guaranteed to contain the exact value.
  const std::pair<double, double> ia = CGAL::to_interval(a), ib = CGAL::to_interval(b);
  Exact lo(std::floor(ia.first) - 1), hi(std::ceil(ib.second) + 1);  // lo < a, hi > b
  if (ia.second < ib.first) {
    const Exact m = (Exact(ia.second) + Exact(ib.first)) / 2;
    const RootNumber rm(m);
    if (a < rm && rm < b) return m;
  }
  for (;;) {
    const Exact m = (lo + hi) / 2;
    const RootNumber rm(m);
    if (rm <= a) lo = m;
    else if (rm >= b) hi = m;
    else return m;
  }
}

}  // namespace exactvis
