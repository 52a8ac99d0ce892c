#pragma once
// Number types of the exact kernel.
//
// Input coordinates are doubles and are read as the exact rationals they denote. Predicates are evaluated
// by filtered_sign: a semi-static filter in doubles, then interval arithmetic, and only when neither can
// prove the sign, exact rationals (GMP through CGAL). See docs/theory.md, "Arithmetic".
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Interval_nt.h>

#include <string>
#include <utility>

namespace exactvis {

using Exact = CGAL::Gmpq;        // exact rational
using ExactInt = CGAL::Gmpz;     // exact integer
using Interval = CGAL::Interval_nt<false>;  // needs CGAL::Protect_FPU_rounding<true> in scope

enum class Sign : int { Negative = -1, Zero = 0, Positive = 1 };

inline Sign sign_of(int s) { return s < 0 ? Sign::Negative : (s > 0 ? Sign::Positive : Sign::Zero); }
inline Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
inline Sign operator*(Sign a, Sign b) { return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b)); }
inline int to_int(Sign s) { return static_cast<int>(s); }

inline Sign exact_sign(const Exact& x) { return sign_of(CGAL::sign(x)); }
inline Sign exact_sign(const ExactInt& x) { return sign_of(CGAL::sign(x)); }

// Exact rational from a double (exact: every finite double is a dyadic rational).
inline Exact to_exact(double x) { return Exact(x); }

// "num/den" (or "num" when the denominator is 1) for JSON output of exact values.
std::string to_rational_string(const Exact& x);
// Parse "num/den", "num" or a decimal/scientific double literal (taken exactly as the double it denotes).
Exact parse_rational(const std::string& text);
// An interval of doubles containing x: mpq_get_d truncates (error < 1 ulp), widened by one ulp each way.
// Much cheaper than CGAL::to_interval(Gmpq), which goes through MPFR; the filter only needs an enclosure.
std::pair<double, double> enclosing_interval(const Exact& x);
// The smallest interval of doubles containing x ([x, x] iff x is a double): the same pair as
// CGAL::to_interval(x), computed with mpq_get_d and an exactness test instead of an MPFR rounding (several
// times faster); outside the normal range of doubles it defers to CGAL::to_interval.
std::pair<double, double> tight_interval(const Exact& x);

// True iff x is exactly a finite double; then *out receives it.
bool exact_double(const Exact& x, double* out);

}  // namespace exactvis
