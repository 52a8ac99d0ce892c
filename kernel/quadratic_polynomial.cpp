#include "kernel/quadratic_polynomial.hpp"

#include <gmp.h>

#include <stdexcept>

namespace exactvis {
namespace {

bool perfect_square(const ExactInt& z, ExactInt* root) {
  if (CGAL::sign(z) < 0 || !mpz_perfect_square_p(z.mpz())) return false;
  mpz_t r;
  mpz_init(r);
  mpz_sqrt(r, z.mpz());
  *root = ExactInt(r);
  mpz_clear(r);
  return true;
}

}  // namespace

QuadraticPolynomial QuadraticPolynomial::linear(const Exact& c0, const Exact& c1) {
  QuadraticPolynomial p;
  p.c[0] = c0;
  p.c[1] = c1;
  return p;
}

int QuadraticPolynomial::degree() const {
  for (int k = 2; k >= 0; --k)
    if (!CGAL::is_zero(c[k])) return k;
  return -1;
}

QuadraticPolynomial operator+(const QuadraticPolynomial& a, const QuadraticPolynomial& b) {
  QuadraticPolynomial r;
  for (int k = 0; k < 3; ++k) r.c[k] = a.c[k] + b.c[k];
  return r;
}

QuadraticPolynomial operator-(const QuadraticPolynomial& a, const QuadraticPolynomial& b) {
  QuadraticPolynomial r;
  for (int k = 0; k < 3; ++k) r.c[k] = a.c[k] - b.c[k];
  return r;
}

QuadraticPolynomial operator-(const QuadraticPolynomial& a) { return QuadraticPolynomial() - a; }

QuadraticPolynomial operator*(const QuadraticPolynomial& a, const QuadraticPolynomial& b) {
  const int da = a.degree(), db = b.degree();
  if (da < 0 || db < 0) return QuadraticPolynomial();
  if (da + db > 2) throw std::logic_error("QuadraticPolynomial: product of degree above 2");
  QuadraticPolynomial r;
  for (int i = 0; i <= da; ++i)
    for (int j = 0; j <= db; ++j) r.c[i + j] += a.c[i] * b.c[j];
  return r;
}

QuadraticPolynomial scaled(const QuadraticPolynomial& p, const Exact& s) {
  QuadraticPolynomial r;
  for (int k = 0; k < 3; ++k)
    if (!CGAL::is_zero(p.c[k])) r.c[k] = p.c[k] * s;
  return r;
}

std::vector<RealRoot> real_roots(const QuadraticPolynomial& p) {
  std::vector<RealRoot> out;
  const int deg = p.degree();
  auto rational = [&](const Exact& q) { out.push_back({RootNumber(q), true, q}); };
  if (deg == 1) {
    rational(-p.c[0] / p.c[1]);
  } else if (deg == 2) {
    const Exact disc = p.c[1] * p.c[1] - Exact(4) * p.c[2] * p.c[0];
    const int s = CGAL::sign(disc);
    const Exact a0 = -p.c[1] / (Exact(2) * p.c[2]);
    if (s == 0) {
      rational(a0);
    } else if (s > 0) {
      ExactInt rn, rd;
      if (perfect_square(disc.numerator(), &rn) && perfect_square(disc.denominator(), &rd)) {
        const Exact w = Exact(rn) / Exact(rd) / (Exact(2) * p.c[2]);
        rational(a0 - w);
        rational(a0 + w);
      } else {
        // The root is the discriminant itself: its value (not numerator * denominator) keeps CGAL's interval
        // filter finite for coefficients with large numerators and denominators.
        const Exact a1 = Exact(1) / (Exact(2) * p.c[2]);
        out.push_back({RootNumber(a0, -a1, disc), false, Exact(0)});
        out.push_back({RootNumber(a0, a1, disc), false, Exact(0)});
      }
    }
  }
  return out;
}

}  // namespace exactvis
