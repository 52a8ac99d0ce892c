#include "aspect/exact_real_roots.hpp"

#include <stdexcept>

namespace exactvis {
namespace {

// a = q b + r (b non-zero).
void divide(const ExactPolynomial& a, const ExactPolynomial& b, ExactPolynomial& q, ExactPolynomial& r) {
  if (b.c.empty()) throw std::logic_error("ExactPolynomial: division by zero");
  r = a;
  q.c.assign(a.degree() >= b.degree() ? a.degree() - b.degree() + 1 : 0, Exact(0));
  while (r.degree() >= b.degree() && !r.c.empty()) {
    const int k = r.degree() - b.degree();
    const Exact f = r.c.back() / b.c.back();
    q.c[k] = f;
    for (int i = 0; i <= b.degree(); ++i) r.c[k + i] -= f * b.c[i];
    r.c.pop_back();
    r = poly_trim(r);
  }
  q = poly_trim(q);
}

std::vector<ExactPolynomial> sturm(const ExactPolynomial& p) {
  std::vector<ExactPolynomial> s{p, poly_derivative(p)};
  while (!s.back().c.empty() && s.back().degree() > 0) {
    ExactPolynomial q, r;
    divide(s[s.size() - 2], s.back(), q, r);
    if (r.c.empty()) break;
    s.push_back(poly_scaled(r, Exact(-1)));
  }
  if (s.back().c.empty()) s.pop_back();
  return s;
}

int variations(const std::vector<ExactPolynomial>& s, const Exact& x) {
  int v = 0, last = 0;
  for (const auto& p : s) {
    const int g = CGAL::sign(p(x));
    if (g == 0) continue;
    if (last != 0 && g != last) ++v;
    last = g;
  }
  return v;
}

void isolate(const ExactPolynomial& p, const std::vector<ExactPolynomial>& s, const Exact& lo, const Exact& hi, int n,
             std::vector<IsolatedRoot>& out) {
  if (n <= 0) return;
  const int slo = CGAL::sign(p(lo)), shi = CGAL::sign(p(hi));
  if (n == 1 && shi == 0) {
    out.push_back({hi, hi});
    return;
  }
  if (n == 1 && slo != 0) {
    out.push_back({lo, hi});
    return;
  }
  const Exact m = (lo + hi) / 2;
  const int nl = variations(s, lo) - variations(s, m);
  isolate(p, s, lo, m, nl, out);
  isolate(p, s, m, hi, n - nl, out);
}

}  // namespace

Exact ExactPolynomial::operator()(const Exact& t) const {
  Exact v(0);
  for (auto it = c.rbegin(); it != c.rend(); ++it) v = v * t + *it;
  return v;
}
RootNumber ExactPolynomial::operator()(const RootNumber& t) const {
  RootNumber v(Exact(0));
  for (auto it = c.rbegin(); it != c.rend(); ++it) v = v * t + RootNumber(*it);
  return v;
}

ExactPolynomial poly_trim(ExactPolynomial p) {
  while (!p.c.empty() && CGAL::sign(p.c.back()) == 0) p.c.pop_back();
  return p;
}
ExactPolynomial poly_from(const std::vector<Exact>& c) { return poly_trim(ExactPolynomial{c}); }
ExactPolynomial operator+(const ExactPolynomial& a, const ExactPolynomial& b) {
  ExactPolynomial r;
  r.c.assign(std::max(a.c.size(), b.c.size()), Exact(0));
  for (std::size_t i = 0; i < a.c.size(); ++i) r.c[i] += a.c[i];
  for (std::size_t i = 0; i < b.c.size(); ++i) r.c[i] += b.c[i];
  return poly_trim(r);
}
ExactPolynomial operator-(const ExactPolynomial& a, const ExactPolynomial& b) { return a + poly_scaled(b, Exact(-1)); }
ExactPolynomial operator*(const ExactPolynomial& a, const ExactPolynomial& b) {
  if (a.c.empty() || b.c.empty()) return {};
  ExactPolynomial r;
  r.c.assign(a.c.size() + b.c.size() - 1, Exact(0));
  for (std::size_t i = 0; i < a.c.size(); ++i)
    for (std::size_t j = 0; j < b.c.size(); ++j) r.c[i + j] += a.c[i] * b.c[j];
  return poly_trim(r);
}
ExactPolynomial poly_scaled(const ExactPolynomial& a, const Exact& s) {
  ExactPolynomial r = a;
  for (auto& x : r.c) x *= s;
  return poly_trim(r);
}
ExactPolynomial poly_derivative(const ExactPolynomial& a) {
  ExactPolynomial r;
  for (std::size_t i = 1; i < a.c.size(); ++i) r.c.push_back(Exact(static_cast<int>(i)) * a.c[i]);
  return poly_trim(r);
}
ExactPolynomial poly_gcd(ExactPolynomial a, ExactPolynomial b) {
  a = poly_trim(a);
  b = poly_trim(b);
  while (!b.c.empty()) {
    ExactPolynomial q, r;
    divide(a, b, q, r);
    a = b;
    b = r;
  }
  if (!a.c.empty()) a = poly_scaled(a, Exact(1) / a.c.back());
  return a;
}
ExactPolynomial poly_exact_quotient(const ExactPolynomial& a, const ExactPolynomial& b) {
  ExactPolynomial q, r;
  divide(a, b, q, r);
  if (!r.c.empty()) throw std::logic_error("poly_exact_quotient: not a divisor");
  return q;
}
ExactPolynomial poly_square_free(const ExactPolynomial& p) {
  if (p.degree() < 1) return p;
  return poly_exact_quotient(p, poly_gcd(p, poly_derivative(p)));
}

int poly_root_count(const ExactPolynomial& p, const Exact& a, const Exact& b) {
  if (p.degree() < 1) return 0;
  const auto s = sturm(p);
  return variations(s, a) - variations(s, b);
}

std::vector<IsolatedRoot> isolate_roots(const ExactPolynomial& p, const Exact& a, const Exact& b) {
  std::vector<IsolatedRoot> out;
  if (p.degree() < 1) return out;
  if (CGAL::sign(p(a)) == 0) out.push_back({a, a});
  const auto s = sturm(p);
  isolate(p, s, a, b, variations(s, a) - variations(s, b), out);
  return out;
}

void refine_root(const ExactPolynomial& p, IsolatedRoot& r) {
  if (r.exact()) return;
  const Exact m = (r.lo + r.hi) / 2;
  const int sm = CGAL::sign(p(m));
  if (sm == 0) r = {m, m};
  else if (sm == CGAL::sign(p(r.lo))) r.lo = m;
  else r.hi = m;
}

int sign_at_root(const ExactPolynomial& p, IsolatedRoot& r, const ExactPolynomial& g) {
  if (g.c.empty()) return 0;
  if (r.exact()) return CGAL::sign(g(r.lo));
  if (g.degree() == 0) return CGAL::sign(g.c[0]);
  const ExactPolynomial h = poly_gcd(p, g);
  if (h.degree() >= 1 && poly_root_count(h, r.lo, r.hi) > 0) return 0;
  const auto s = sturm(g);
  for (;;) {
    if (CGAL::sign(g(r.lo)) != 0 && variations(s, r.lo) == variations(s, r.hi)) return CGAL::sign(g(r.lo));
    refine_root(p, r);
    if (r.exact()) return CGAL::sign(g(r.lo));
  }
}

}  // namespace exactvis
