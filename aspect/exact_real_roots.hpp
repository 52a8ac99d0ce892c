#pragma once
// Polynomials in one variable with exact rational coefficients of small degree (the quartics of two EEE cones
// along an EEE arc, docs/theory.md 10.11 "EEE x EEE crossings"), their real roots isolated exactly by Sturm
// sequences, and the exact sign of another polynomial at such a root. Every decision is an exact rational sign;
// no floating point decides anything (doubles only report). Kept in aspect/ (its only user); the quadratic case
// with roots in Q(sqrt D) is kernel/quadratic_polynomial.
#include "kernel/number_types.hpp"
#include "kernel/root_number.hpp"

#include <vector>

namespace exactvis {

// c[0] + c[1] t + ... (no trailing zeros; the zero polynomial is empty).
struct ExactPolynomial {
  std::vector<Exact> c;
  int degree() const { return static_cast<int>(c.size()) - 1; }
  Exact operator()(const Exact& t) const;
  RootNumber operator()(const RootNumber& t) const;
};

ExactPolynomial poly_trim(ExactPolynomial p);
ExactPolynomial poly_from(const std::vector<Exact>& c);
ExactPolynomial operator+(const ExactPolynomial& a, const ExactPolynomial& b);
ExactPolynomial operator-(const ExactPolynomial& a, const ExactPolynomial& b);
ExactPolynomial operator*(const ExactPolynomial& a, const ExactPolynomial& b);
ExactPolynomial poly_scaled(const ExactPolynomial& a, const Exact& s);
ExactPolynomial poly_derivative(const ExactPolynomial& a);
// The monic greatest common divisor (empty when both are zero).
ExactPolynomial poly_gcd(ExactPolynomial a, ExactPolynomial b);
// a / b, b a divisor of a (exact division; throws std::logic_error otherwise).
ExactPolynomial poly_exact_quotient(const ExactPolynomial& a, const ExactPolynomial& b);
// The square-free part p / gcd(p, p') (same distinct roots, all simple).
ExactPolynomial poly_square_free(const ExactPolynomial& p);

// A real root of a square-free polynomial p isolated in [lo, hi]: lo == hi (an exact rational root) or lo < hi
// with p(lo), p(hi) non-zero of opposite signs and no other root of p in [lo, hi].
struct IsolatedRoot {
  Exact lo, hi;
  bool exact() const { return lo == hi; }
};

// The number of distinct real roots of p in the half-open interval (a, b] (Sturm), p non-zero.
int poly_root_count(const ExactPolynomial& p, const Exact& a, const Exact& b);

// Every real root of the square-free non-constant polynomial p in [a, b] (a < b), isolated, in increasing order.
// Cost: O(deg^2) Sturm evaluations per bisection step; a few dozen steps per root for the degrees used here.
std::vector<IsolatedRoot> isolate_roots(const ExactPolynomial& p, const Exact& a, const Exact& b);

// Halves r's interval (keeping the root of p in it); no-op for an exact root.
void refine_root(const ExactPolynomial& p, IsolatedRoot& r);

// The exact sign of g at the root r of the square-free p (r's interval may be refined). 0 iff g vanishes there
// (decided by gcd(p, g) having its root in r's interval). Cost: a gcd, then bisection until g has no root in it.
int sign_at_root(const ExactPolynomial& p, IsolatedRoot& r, const ExactPolynomial& g);

}  // namespace exactvis
