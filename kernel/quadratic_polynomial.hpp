#pragma once
// Polynomials of degree <= 2 in one variable with exact rational coefficients, and their exact real roots in
// Q(sqrt D) (RootNumber). The EEE family's quantities are such polynomials in its parameter t
// (docs/theory.md section 6, "EEE critical line sets").
#include "kernel/number_types.hpp"
#include "kernel/root_number.hpp"

#include <array>
#include <vector>

namespace exactvis {

// c[0] + c[1] t + c[2] t^2.
struct QuadraticPolynomial {
  std::array<Exact, 3> c{Exact(0), Exact(0), Exact(0)};
  QuadraticPolynomial() = default;
  QuadraticPolynomial(int v) { c[0] = Exact(v); }           // NOLINT: constants convert implicitly
  QuadraticPolynomial(const Exact& v) { c[0] = v; }         // NOLINT (Vec3<QuadraticPolynomial> needs both)
  static QuadraticPolynomial linear(const Exact& c0, const Exact& c1);
  // Degree, -1 for the zero polynomial.
  int degree() const;
  Exact operator()(const Exact& t) const { return (c[2] * t + c[1]) * t + c[0]; }
};

QuadraticPolynomial operator+(const QuadraticPolynomial& a, const QuadraticPolynomial& b);
QuadraticPolynomial operator-(const QuadraticPolynomial& a, const QuadraticPolynomial& b);
QuadraticPolynomial operator-(const QuadraticPolynomial& a);
// Product; throws std::logic_error if the degree of the result would exceed 2.
QuadraticPolynomial operator*(const QuadraticPolynomial& a, const QuadraticPolynomial& b);
// Product with a constant (cheaper than operator*).
QuadraticPolynomial scaled(const QuadraticPolynomial& p, const Exact& s);

// One real root: exact, and its rational value in q when `rational`.
struct RealRoot {
  RootNumber t;
  bool rational = true;
  Exact q;
};

// All distinct real roots of p, in no particular order (none when p is constant, including zero). Rational
// roots (linear p, zero discriminant, or a discriminant that is the square of a rational) are rational
// RootNumbers; the others are a0 ± a1 sqrt(disc) with the discriminant disc > 0 as the root.
std::vector<RealRoot> real_roots(const QuadraticPolynomial& p);

}  // namespace exactvis
