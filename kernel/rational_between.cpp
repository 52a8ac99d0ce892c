#include "kernel/rational_between.hpp"

#include <gmp.h>

#include <cmath>
#include <stdexcept>

namespace exactvis {
namespace {

// floor(sqrt(r)) and ceil(sqrt(r)) bounds of sqrt(r) for a rational r >= 0, as rationals: sqrt(p/q) =
// sqrt(p q) / q with integer square roots of p q.
std::pair<Exact, Exact> sqrt_bounds(const Exact& r) {
  const ExactInt pq = r.numerator() * r.denominator();
  mpz_t s;
  mpz_init(s);
  mpz_sqrt(s, pq.mpz());
  const ExactInt fl(s);
  mpz_clear(s);
  const Exact q(r.denominator());
  return {Exact(fl) / q, (Exact(fl) + 1) / q};
}

// Rational bounds of x = a0 + a1 sqrt(R).
Exact lower_bound(const RootNumber& x) {
  if (!x.is_extended()) return x.a0();
  const auto [lo, hi] = sqrt_bounds(x.root());
  return x.a0() + x.a1() * (CGAL::sign(x.a1()) >= 0 ? lo : hi);
}
Exact upper_bound(const RootNumber& x) {
  if (!x.is_extended()) return x.a0();
  const auto [lo, hi] = sqrt_bounds(x.root());
  return x.a0() + x.a1() * (CGAL::sign(x.a1()) >= 0 ? hi : lo);
}

}  // namespace

bool root_number_rational(const RootNumber& x, Exact* q) {
  if (x.is_extended() && !CGAL::is_zero(x.a1()) && !CGAL::is_zero(x.root())) return false;
  if (q) *q = x.a0();
  return true;
}

Exact rational_strictly_between(const RootNumber& a, const RootNumber& b) {
  if (!(a < b)) throw std::invalid_argument("rational_strictly_between: need a < b");
  Exact qa, qb;
  if (root_number_rational(a, &qa) && root_number_rational(b, &qb)) return (qa + qb) / 2;
  // Exact rational bounds lo <= a and hi >= b (integer square roots bound sqrt(R)); the double enclosure of
  // to_interval is used only as a first guess when it is finite.
  const Exact lo = lower_bound(a), hi = upper_bound(b);
  const std::pair<double, double> ia = CGAL::to_interval(a), ib = CGAL::to_interval(b);
  if (std::isfinite(ia.second) && std::isfinite(ib.first) && ia.second < ib.first) {
    const Exact m = (Exact(ia.second) + Exact(ib.first)) / 2;
    const RootNumber rm(m);
    if (a < rm && rm < b) return m;
  }
  Exact l = lo, h = hi;
  for (;;) {
    const Exact m = (l + h) / 2;
    const RootNumber rm(m);
    if (rm <= a) l = m;
    else if (rm >= b) h = m;
    else return m;
  }
}

}  // namespace exactvis
