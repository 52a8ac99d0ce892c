#pragma once
// Exact integer vectors of R^6 (Plücker space) used by the line-set polytopes of region/.
//
// A point x = (d, m) of R^6 is a "6-vector" (a real line when d . m = 0 and d != 0). The constraint
// "x passes the directed line e on the positive side", side(x, e) > 0, is the linear functional
// w . x with w = (m_e, d_e) (the halves of e swapped): side(x, e) = d_x . m_e + m_x . d_e.
#include "kernel/number_types.hpp"
#include "kernel/plucker_line.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <optional>

namespace exactvis::region {

using IntVec6 = std::array<mpz_class, 6>;
using RatVec6 = std::array<mpq_class, 6>;

inline mpz_class dot(const IntVec6& a, const IntVec6& b) {
  mpz_class s = 0;
  for (int i = 0; i < 6; ++i) s += a[i] * b[i];
  return s;
}

// Double approximations of the components (docs/theory.md §5.3, "Float filter of the cone signs"): each
// component truncated toward zero (mpz_get_d: relative error below 2^-52), +infinity for a component of more
// than 1000 bits (the filter then falls through to the exact layer). They only propose: every sign below is
// certified by an error bound or recomputed exactly.
using Approx6 = std::array<double, 6>;
Approx6 approximate(const IntVec6& v);

// Exact signs (-1, 0, +1) of a . b, side6(a, b) and plucker_form(a), given the vectors and their
// approximations (approximate(a), approximate(b)): a semi-static filter (the sum of products in doubles,
// certified when |sum| > 2^-49 * sum of |products|), the exact GMP evaluation when it cannot decide or when
// kernel/filtered_predicate's filter is disabled. Counted as the predicates "cone_dot", "cone_side" and
// "cone_plucker_form" (kernel/predicate_counters.hpp). Cost: a few flops; malloc-free unless exact.
// The semi-static filter itself: sign(sum x[i] * y[i]) over N <= 6 terms of such approximations when the
// error bound certifies it, else std::nullopt (docs/theory.md §5.4). N is a compile-time length so that the
// loop unrolls into the cone signs, the hottest code of a PVS cell (region/cone_vector6 uses it too).
// Error: each approximation is x~ = x (1 + d), |d| < 2^-52 = 2u; each product is off by < 5u (1 + 2^-40)
// |x~ y~| (two input errors and one rounding), the recursive sum adds <= 5u (1 + 2^-40) of the sum of
// |products|, and the computed m underestimates that sum by a factor >= 1 - 6u: |error| < 11u m, so
// |s| > 16u m = 2^-49 m certifies the sign. No underflow: a non-zero product has both factors of magnitude
// >= 1; m == 0 means every term has an exact zero factor. A non-finite m (huge components) is not certified.
template <int N>
inline std::optional<int> filtered_sum_sign(const double* x, const double* y) {
  static_assert(N >= 1 && N <= 6, "the error bound is proved for at most 6 terms");
  double s = 0, m = 0;
  for (int i = 0; i < N; ++i) {
    const double p = x[i] * y[i];
    s += p;
    m += std::fabs(p);
  }
  if (!std::isfinite(m)) return std::nullopt;
  if (m == 0) return 0;
  const double bound = 0x1p-49 * m;
  if (s > bound) return 1;
  if (s < -bound) return -1;
  return std::nullopt;
}

int dot_sign(const IntVec6& a, const Approx6& aa, const IntVec6& b, const Approx6& bb);
int side_sign(const IntVec6& a, const Approx6& aa, const IntVec6& b, const Approx6& bb);
int plucker_form_sign(const IntVec6& a, const Approx6& aa);

// Divide by the gcd of the components (keeps direction; the zero vector is left as is).
void normalize(IntVec6& v);
bool is_zero(const IntVec6& v);

// Plücker form q(x) = d . m (x[0..2] = d, x[3..5] = m) and its polar bilinear form B(x, y) = (side(x,y))/2;
// we use S(x, y) = side(x, y) = 2 B(x, y) so everything stays integral: q(x) = S(x, x) / 2.
inline mpz_class plucker_form(const IntVec6& x) { return x[0] * x[3] + x[1] * x[4] + x[2] * x[5]; }
inline mpz_class side6(const IntVec6& x, const IntVec6& y) {
  return x[0] * y[3] + x[1] * y[4] + x[2] * y[5] + y[0] * x[3] + y[1] * x[4] + y[2] * x[5];
}

// The functional w with w . x = side(x, e) for the line e (exact rational Plücker coordinates), scaled by a
// positive integer to clear denominators.
IntVec6 side_functional(const PluckerLine<Exact>& e);

// Integer 6-vector proportional (positive factor) to the rational Plücker vector of a line.
IntVec6 to_int_vector(const PluckerLine<Exact>& e);
PluckerLine<Exact> to_plucker(const RatVec6& v);
// Integer vector proportional (positive factor) to a rational one, gcd-normalised.
IntVec6 to_integer(const RatVec6& q);

}  // namespace exactvis::region
