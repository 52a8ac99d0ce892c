#include "region/int_vector6.hpp"

#include "kernel/filtered_predicate.hpp"
#include "kernel/predicate_counters.hpp"
#include "region/cone_vector6.hpp"

#include <cmath>
#include <limits>
#include <optional>

namespace exactvis::region {

namespace {

template <class Exact>
int counted_sign(PredicateCounter& counter, const std::optional<int>& filtered, Exact&& exact) {
  std::atomic<std::uint64_t>* counts = counter.thread_counts();
  exactvis::detail::bump(counts[0]);
  if (filtered && filter_enabled()) {
    exactvis::detail::bump(counts[1 + static_cast<int>(FilterLayer::SemiStatic)]);
    count_cone_sign(ConeLayer::Filter);
    return *filtered;
  }
  exactvis::detail::bump(counts[1 + static_cast<int>(FilterLayer::Exact)]);
  count_cone_sign(ConeLayer::Gmp);
  return sgn(exact());
}

}  // namespace

Approx6 approximate(const IntVec6& v) {
  Approx6 a;
  for (int k = 0; k < 6; ++k)
    a[k] = mpz_sizeinbase(v[k].get_mpz_t(), 2) > 1000 ? std::numeric_limits<double>::infinity()
                                                       : mpz_get_d(v[k].get_mpz_t());
  return a;
}

int dot_sign(const IntVec6& a, const Approx6& aa, const IntVec6& b, const Approx6& bb) {
  static PredicateCounter counter("cone_dot");
  return counted_sign(counter, filtered_sum_sign<6>(aa.data(), bb.data()), [&] { return dot(a, b); });
}

int side_sign(const IntVec6& a, const Approx6& aa, const IntVec6& b, const Approx6& bb) {
  static PredicateCounter counter("cone_side");
  const double x[6] = {aa[0], aa[1], aa[2], bb[0], bb[1], bb[2]}, y[6] = {bb[3], bb[4], bb[5], aa[3], aa[4], aa[5]};
  return counted_sign(counter, filtered_sum_sign<6>(x, y), [&] { return side6(a, b); });
}

int plucker_form_sign(const IntVec6& a, const Approx6& aa) {
  static PredicateCounter counter("cone_plucker_form");
  return counted_sign(counter, filtered_sum_sign<3>(aa.data(), aa.data() + 3), [&] { return plucker_form(a); });
}

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
