#include "kernel/line_intersection_2d.hpp"

#include <gmp.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace exactvis {
namespace {

// GMP integers reused by one thread (initialized once; they grow as needed and keep their limbs).
struct Scratch {
  static constexpr int kCount = 16;
  mpz_t z[kCount];
  Scratch() {
    for (auto& x : z) mpz_init2(x, 256);
  }
  ~Scratch() {
    for (auto& x : z) mpz_clear(x);
  }
};

// x = m 2^e with m an integer of at most 53 bits (m = 0 for x = 0).
struct Dyadic {
  std::int64_t m = 0;
  int e = 0;
};
Dyadic decompose(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::int64_t m = static_cast<std::int64_t>(bits & ((std::uint64_t(1) << 52) - 1));
  if (biased != 0) m |= std::int64_t(1) << 52;  // normal: implicit leading bit; subnormal: exponent -1074
  if (bits >> 63) m = -m;
  return {m, (biased != 0 ? biased : 1) - 1075};
}

}  // namespace

std::array<Exact, 2> line_intersection_2d(const Double2& c, const Double2& d0, const Double2& d1, const Double2& a,
                                          const Double2& b) {
  thread_local Scratch s;
  mpz_t* z = s.z;
  // The ten coordinates as integers in units of 2^lo, lo the smallest exponent among them.
  const double in[10] = {c[0], c[1], d0[0], d0[1], d1[0], d1[1], a[0], a[1], b[0], b[1]};
  Dyadic d[10];
  int lo = INT_MAX;
  for (int i = 0; i < 10; ++i) {
    if (!std::isfinite(in[i])) throw std::invalid_argument("line_intersection_2d: non-finite coordinate");
    d[i] = decompose(in[i]);
    if (d[i].m != 0) lo = std::min(lo, d[i].e);
  }
  if (lo == INT_MAX) lo = 0;
  for (int i = 0; i < 10; ++i) {
    mpz_set_si(z[i], static_cast<long>(d[i].m));
    if (d[i].m != 0 && d[i].e != lo) mpz_mul_2exp(z[i], z[i], static_cast<mp_bitcnt_t>(d[i].e - lo));
  }
  mpz_t &cx = z[0], &cy = z[1], &dx = z[4], &dy = z[5], &ex = z[8], &ey = z[9];
  mpz_sub(dx, dx, z[2]);    // d = d1 - d0
  mpz_sub(dy, dy, z[3]);
  mpz_sub(ex, ex, z[6]);    // e = b - a
  mpz_sub(ey, ey, z[7]);
  mpz_sub(z[6], z[6], cx);  // a - c
  mpz_sub(z[7], z[7], cy);
  mpz_t &den = z[10], &num = z[11], &t1 = z[12], &nx = z[13], &ny = z[14];
  mpz_mul(den, dx, ey);  // den = cross(d, e)
  mpz_mul(t1, dy, ex);
  mpz_sub(den, den, t1);
  if (mpz_sgn(den) == 0) throw std::invalid_argument("line_intersection_2d: parallel lines");
  mpz_mul(num, z[6], ey);  // num = cross(a - c, e)
  mpz_mul(t1, z[7], ex);
  mpz_sub(num, num, t1);
  // X = c + (num / den) d = (c den + num d) / den, in units of 2^lo
  mpz_mul(nx, cx, den);
  mpz_addmul(nx, num, dx);
  mpz_mul(ny, cy, den);
  mpz_addmul(ny, num, dy);
  if (mpz_sgn(den) < 0) mpz_neg(den, den), mpz_neg(nx, nx), mpz_neg(ny, ny);
  std::array<Exact, 2> out;
  for (int k = 0; k < 2; ++k) {
    mpq_ptr q = out[k].mpq();
    mpz_swap(mpq_numref(q), k == 0 ? nx : ny);  // the scratch integers take the fresh rational's limbs
    mpz_set(mpq_denref(q), den);
    mpq_canonicalize(q);
    if (lo > 0) mpq_mul_2exp(q, q, static_cast<mp_bitcnt_t>(lo));
    else if (lo < 0) mpq_div_2exp(q, q, static_cast<mp_bitcnt_t>(-lo));
  }
  return out;
}

}  // namespace exactvis
