#include "region/cone_vector6.hpp"

#include "kernel/filtered_predicate.hpp"
#include "kernel/predicate_counters.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <numeric>

namespace exactvis::region {

namespace {
constinit PredicateCounter sign_filter("cone_sign_filter"), sign_fixed("cone_sign_fixed"), sign_gmp("cone_sign_gmp"),
    construction_fixed("cone_construction_fixed"), construction_gmp("cone_construction_gmp");
void bump_calls(PredicateCounter& c) { exactvis::detail::bump(c.thread_counts()[0]); }
}  // namespace

void count_cone_sign(ConeLayer layer) {
  bump_calls(layer == ConeLayer::Filter ? sign_filter : (layer == ConeLayer::Fixed ? sign_fixed : sign_gmp));
}
void count_cone_construction(ConeLayer layer) {
  bump_calls(layer == ConeLayer::Fixed ? construction_fixed : construction_gmp);
}

ConeLayerCounts cone_layer_counts() {
  ConeLayerCounts out;
  for (const auto& c : predicate_counters()) {
    if (c.name == "cone_sign_filter") out.signs[0] = c.calls;
    else if (c.name == "cone_sign_fixed") out.signs[1] = c.calls;
    else if (c.name == "cone_sign_gmp") out.signs[2] = c.calls;
    else if (c.name == "cone_construction_fixed") out.constructions[1] = c.calls;
    else if (c.name == "cone_construction_gmp") out.constructions[2] = c.calls;
  }
  return out;
}

namespace {

using i128 = __int128;
using u128 = unsigned __int128;

constexpr std::int64_t kFixedMax = std::numeric_limits<std::int64_t>::max();

void count_sign(ConeLayer layer) { count_cone_sign(layer); }
void count_construction(ConeLayer layer) { count_cone_construction(layer); }

bool fits_fixed(i128 x) { return x <= kFixedMax && x >= -kFixedMax; }

u128 magnitude(i128 x) { return x < 0 ? -static_cast<u128>(x) : static_cast<u128>(x); }

int ctz128(u128 x) {
  const auto lo = static_cast<std::uint64_t>(x);
  return lo != 0 ? __builtin_ctzll(lo) : 64 + __builtin_ctzll(static_cast<std::uint64_t>(x >> 64));
}

// Binary gcd (Stein) of 128-bit magnitudes; gcd(0, b) = b.
u128 gcd128(u128 a, u128 b) {
  if (a == 0) return b;
  if (b == 0) return a;
  if ((a >> 64) == 0 && (b >> 64) == 0)
    return std::gcd(static_cast<std::uint64_t>(a), static_cast<std::uint64_t>(b));
  const int shift = ctz128(a | b);
  a >>= ctz128(a);
  do {
    b >>= ctz128(b);
    if (a > b) std::swap(a, b);
    b -= a;
  } while (b != 0);
  return a << shift;
}

// sum x[i] * y[i] in __int128; false on overflow. A product of two int64 has magnitude <= 2^126 and never
// overflows; only the additions are checked.
bool checked_sum_of_products(const std::int64_t* x, const std::int64_t* y, int n, i128& out) {
  i128 s = 0;
  for (int i = 0; i < n; ++i)
    if (__builtin_add_overflow(s, static_cast<i128>(x[i]) * y[i], &s)) return false;
  out = s;
  return true;
}

mpz_class to_mpz(i128 x) {
  const u128 m = magnitude(x);
  mpz_class hi(static_cast<unsigned long>(m >> 64)), lo(static_cast<unsigned long>(static_cast<std::uint64_t>(m)));
  mpz_class r = (hi << 64) + lo;
  return x < 0 ? mpz_class(-r) : r;
}

// Divides v by the gcd of its components; false when a quotient does not fit the fixed layer.
bool normalized_fixed(std::array<i128, 6>& v, Fixed6& out) {
  u128 g = 0;
  for (const i128 c : v) {
    g = gcd128(g, magnitude(c));
    if (g == 1) break;
  }
  if (g > 1)
    for (auto& c : v) c /= static_cast<i128>(g);
  for (const i128 c : v)
    if (!fits_fixed(c)) return false;
  for (int k = 0; k < 6; ++k) out[static_cast<std::size_t>(k)] = static_cast<std::int64_t>(v[static_cast<std::size_t>(k)]);
  return true;
}

// Sign layers: the filter on the approximations, then the fixed layer, then gmp; counted under `counter`
// (semi_static = filter, exact = fixed or gmp) and in the thread's layer counts.
template <class Fixed, class Gmp>
int layered_sign(PredicateCounter& counter, const std::optional<int>& filtered, bool both_fixed, Fixed&& fixed,
                 Gmp&& gmp) {
  std::atomic<std::uint64_t>* counts = counter.thread_counts();
  exactvis::detail::bump(counts[0]);
  if (filtered && filter_enabled()) {
    exactvis::detail::bump(counts[1 + static_cast<int>(FilterLayer::SemiStatic)]);
    count_sign(ConeLayer::Filter);
    return *filtered;
  }
  exactvis::detail::bump(counts[1 + static_cast<int>(FilterLayer::Exact)]);
  if (both_fixed) {
    i128 v;
    if (fixed(v)) {
      count_sign(ConeLayer::Fixed);
      return v > 0 ? 1 : (v < 0 ? -1 : 0);
    }
  }
  count_sign(ConeLayer::Gmp);
  return sgn(gmp());
}

}  // namespace

ConeVector6::ConeVector6(const Fixed6& v) : fixed_(v) {
  for (int k = 0; k < 6; ++k) approx_[static_cast<std::size_t>(k)] = static_cast<double>(v[static_cast<std::size_t>(k)]);
}

ConeVector6::ConeVector6(const IntVec6& v) {
  bool fits = true;
  for (const auto& c : v) fits = fits && mpz_fits_slong_p(c.get_mpz_t()) && c.get_si() != std::numeric_limits<long>::min();
  if (fits) {
    for (int k = 0; k < 6; ++k) fixed_[static_cast<std::size_t>(k)] = v[static_cast<std::size_t>(k)].get_si();
    for (int k = 0; k < 6; ++k) approx_[static_cast<std::size_t>(k)] = static_cast<double>(fixed_[static_cast<std::size_t>(k)]);
  } else {
    big_ = std::make_shared<const IntVec6>(v);
    approx_ = approximate(v);
  }
}

IntVec6 ConeVector6::to_gmp() const {
  if (big_) return *big_;
  IntVec6 v;
  for (int k = 0; k < 6; ++k) v[static_cast<std::size_t>(k)] = static_cast<long>(fixed_[static_cast<std::size_t>(k)]);
  return v;
}

bool ConeVector6::is_zero() const {
  if (big_) return region::is_zero(*big_);
  for (const auto c : fixed_)
    if (c != 0) return false;
  return true;
}

ConeVector6 ConeVector6::negated() const {
  ConeVector6 r;
  if (big_) {
    IntVec6 v = *big_;
    for (auto& c : v) c = -c;
    r.big_ = std::make_shared<const IntVec6>(std::move(v));
  } else {
    for (int k = 0; k < 6; ++k) r.fixed_[static_cast<std::size_t>(k)] = -fixed_[static_cast<std::size_t>(k)];
  }
  for (int k = 0; k < 6; ++k) r.approx_[static_cast<std::size_t>(k)] = -approx_[static_cast<std::size_t>(k)];
  return r;
}

bool operator==(const ConeVector6& a, const ConeVector6& b) {
  // A vector is fixed iff all its components fit: equal vectors share the layer.
  if (a.is_fixed() != b.is_fixed()) return false;
  return a.is_fixed() ? a.fixed_ == b.fixed_ : *a.big_ == *b.big_;
}

int dot_sign(const ConeVector6& a, const ConeVector6& b) {
  static PredicateCounter counter("cone_dot");
  return layered_sign(
      counter, filtered_sum_sign<6>(a.approx().data(), b.approx().data()), a.is_fixed() && b.is_fixed(),
      [&](i128& v) { return checked_sum_of_products(a.fixed().data(), b.fixed().data(), 6, v); },
      [&] { return dot(a.to_gmp(), b.to_gmp()); });
}

int side_sign(const ConeVector6& a, const ConeVector6& b) {
  static PredicateCounter counter("cone_side");
  const Approx6 &aa = a.approx(), &bb = b.approx();
  const double x[6] = {aa[0], aa[1], aa[2], bb[0], bb[1], bb[2]}, y[6] = {bb[3], bb[4], bb[5], aa[3], aa[4], aa[5]};
  return layered_sign(
      counter, filtered_sum_sign<6>(x, y), a.is_fixed() && b.is_fixed(),
      [&](i128& v) {
        const Fixed6 &af = a.fixed(), &bf = b.fixed();
        const std::int64_t xf[6] = {af[0], af[1], af[2], bf[0], bf[1], bf[2]},
                           yf[6] = {bf[3], bf[4], bf[5], af[3], af[4], af[5]};
        return checked_sum_of_products(xf, yf, 6, v);
      },
      [&] { return side6(a.to_gmp(), b.to_gmp()); });
}

int plucker_form_sign(const ConeVector6& a) {
  static PredicateCounter counter("cone_plucker_form");
  return layered_sign(
      counter, filtered_sum_sign<3>(a.approx().data(), a.approx().data() + 3), a.is_fixed(),
      [&](i128& v) { return checked_sum_of_products(a.fixed().data(), a.fixed().data() + 3, 3, v); },
      [&] { return plucker_form(a.to_gmp()); });
}

mpz_class dot(const ConeVector6& a, const IntVec6& x) {
  if (!a.is_fixed()) return dot(a.gmp(), x);
  mpz_class s = 0;
  for (int k = 0; k < 6; ++k) {
    const std::int64_t c = a.fixed()[static_cast<std::size_t>(k)];
    if (c >= 0) mpz_addmul_ui(s.get_mpz_t(), x[static_cast<std::size_t>(k)].get_mpz_t(), static_cast<unsigned long>(c));
    else mpz_submul_ui(s.get_mpz_t(), x[static_cast<std::size_t>(k)].get_mpz_t(), static_cast<unsigned long>(-c));
  }
  return s;
}

ConeVector6 eliminate(const ConeVector6& w, const ConeVector6& p, const ConeVector6& q) {
  if (w.is_fixed() && p.is_fixed() && q.is_fixed()) {
    i128 wp, wq;
    if (checked_sum_of_products(w.fixed().data(), p.fixed().data(), 6, wp) &&
        checked_sum_of_products(w.fixed().data(), q.fixed().data(), 6, wq)) {
      // Dividing both coefficients by their gcd scales v by a positive factor: the same normalised vector.
      const u128 g = gcd128(magnitude(wp), magnitude(wq));
      if (g > 1) {
        wp /= static_cast<i128>(g);
        wq /= static_cast<i128>(g);
      }
      std::array<i128, 6> v;
      bool ok = true;
      for (std::size_t k = 0; k < 6 && ok; ++k) {
        i128 a, b;
        ok = !__builtin_mul_overflow(wp, static_cast<i128>(q.fixed()[k]), &a) &&
             !__builtin_mul_overflow(wq, static_cast<i128>(p.fixed()[k]), &b) && !__builtin_sub_overflow(a, b, &v[k]);
      }
      if (ok) {
        Fixed6 f;
        if (normalized_fixed(v, f)) {
          count_construction(ConeLayer::Fixed);
          return ConeVector6(f);
        }
        // Exact in __int128 but beyond int64 after the gcd: store the (already normalised) value as is.
        IntVec6 big;
        for (std::size_t k = 0; k < 6; ++k) big[k] = to_mpz(v[k]);
        count_construction(ConeLayer::Gmp);
        return ConeVector6(big);
      }
    }
  }
  count_construction(ConeLayer::Gmp);
  const IntVec6 wg = w.to_gmp(), pg = p.to_gmp(), qg = q.to_gmp();
  const mpz_class vp = dot(wg, pg), vq = dot(wg, qg);
  IntVec6 v;
  for (std::size_t k = 0; k < 6; ++k) v[k] = vp * qg[k] - vq * pg[k];
  normalize(v);
  return ConeVector6(v);
}

IntVec6 sum(const std::vector<ConeVector6>& vs) {
  std::array<i128, 6> fixed_sum{};
  IntVec6 out;
  for (auto& c : out) c = 0;
  for (const auto& v : vs) {
    if (!v.is_fixed()) {
      for (std::size_t k = 0; k < 6; ++k) out[k] += v.gmp()[k];
      continue;
    }
    for (std::size_t k = 0; k < 6; ++k) {
      // |partial sums| <= (number of vectors) * 2^63: far from 2^127 for any vector count in memory.
      fixed_sum[k] += v.fixed()[k];
    }
  }
  for (std::size_t k = 0; k < 6; ++k) out[k] += to_mpz(fixed_sum[k]);
  return out;
}

namespace {

// The smallest s >= 0 with x * 2^s an integer (x finite), or -1 when that exceeds 62.
int dyadic_scale(double x) {
  if (x == 0) return 0;
  int e;
  const double f = std::frexp(x, &e);  // x = f 2^e, 0.5 <= |f| < 1
  const auto mant = static_cast<std::int64_t>(std::ldexp(f, 53));  // exact: 53-bit integer
  const int s = 53 - e - __builtin_ctzll(static_cast<std::uint64_t>(std::llabs(mant)));
  if (s > 62) return -1;
  return s < 0 ? 0 : s;
}

}  // namespace

bool side_functional_of_doubles(const Point3& a, const Point3& b, ConeVector6& out) {
  const double c[6] = {a.x, a.y, a.z, b.x, b.y, b.z};
  int s = 0;
  for (const double x : c) {
    if (!std::isfinite(x)) return false;
    const int sx = dyadic_scale(x);
    if (sx < 0) return false;
    s = std::max(s, sx);
  }
  std::int64_t A[3], B[3];
  for (int k = 0; k < 6; ++k) {
    const double scaled = std::ldexp(c[k], s);  // exact (a power-of-two scaling of an integer-valued result)
    if (!(std::fabs(scaled) < 0x1p62)) return false;
    (k < 3 ? A[k] : B[k - 3]) = static_cast<std::int64_t>(scaled);
  }
  if (A[0] == B[0] && A[1] == B[1] && A[2] == B[2]) return false;
  // (d, m) 2^(2s) = ((B - A) 2^s, A x B); the functional is (m, d). |A|, |B| < 2^62: the cross products are
  // below 2^125, and (B - A) 2^s is checked.
  std::array<i128, 6> v;
  v[0] = static_cast<i128>(A[1]) * B[2] - static_cast<i128>(A[2]) * B[1];
  v[1] = static_cast<i128>(A[2]) * B[0] - static_cast<i128>(A[0]) * B[2];
  v[2] = static_cast<i128>(A[0]) * B[1] - static_cast<i128>(A[1]) * B[0];
  for (int k = 0; k < 3; ++k) {
    const i128 d = static_cast<i128>(B[k]) - A[k];  // |d| < 2^63
    if (magnitude(d) >> (125 - s) != 0) return false;  // s <= 62: keeps |d| 2^s below 2^125
    v[static_cast<std::size_t>(3 + k)] = d * (static_cast<i128>(1) << s);
  }
  Fixed6 f;
  if (!normalized_fixed(v, f)) return false;
  count_construction(ConeLayer::Fixed);
  out = ConeVector6(f);
  return true;
}

}  // namespace exactvis::region
