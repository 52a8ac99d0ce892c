#include "region/int_vector6.hpp"

namespace exactvis::region {

void normalize(IntVec6& v) {
  mpz_class g = 0;
  for (const auto& c : v) {
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
    if (g == 1) return;
  }
  if (g == 0) return;
  for (auto& c : v) mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
}

bool is_zero(const IntVec6& v) {
  for (const auto& c : v)
    if (sgn(c) != 0) return false;
  return true;
}

IntVec6 to_int_vector(const PluckerLine<Exact>& e) {
  RatVec6 q;
  for (int i = 0; i < 6; ++i) q[i] = mpq_class(e[i].mpq());
  return to_integer(q);
}

IntVec6 side_functional(const PluckerLine<Exact>& e) {
  IntVec6 v = to_int_vector(e);
  return {v[3], v[4], v[5], v[0], v[1], v[2]};
}

IntVec6 to_integer(const RatVec6& q) {
  mpz_class l = 1;
  for (const auto& c : q) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  IntVec6 v;
  for (int k = 0; k < 6; ++k) {
    mpq_class s = q[k] * l;
    v[k] = s.get_num();
  }
  normalize(v);
  return v;
}

PluckerLine<Exact> to_plucker(const RatVec6& v) {
  PluckerLine<Exact> l;
  for (int i = 0; i < 6; ++i) l[i] = Exact(v[i].get_mpq_t());
  return l;
}

}  // namespace exactvis::region
