#include "kernel/number_types.hpp"

#include <cerrno>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace exactvis {

std::string to_rational_string(const Exact& x) {
  const ExactInt num = x.numerator();
  const ExactInt den = x.denominator();
  char* n = mpz_get_str(nullptr, 10, num.mpz());
  std::string s = n;
  free(n);
  if (den != 1) {
    char* d = mpz_get_str(nullptr, 10, den.mpz());
    s += "/";
    s += d;
    free(d);
  }
  return s;
}

Exact parse_rational(const std::string& text) {
  if (text.empty()) throw std::invalid_argument("empty number");
  // Plain integers are read exactly too (to_rational_string writes integers without "/1"); decimal
  // literals and exponents are read as the nearest double, which is then exact.
  const bool plain_integer =
      text.find_first_not_of("0123456789", text[0] == '-' || text[0] == '+' ? 1 : 0) == std::string::npos &&
      text.size() > (text[0] == '-' || text[0] == '+' ? 1u : 0u);
  const auto slash = text.find('/');
  if (slash != std::string::npos || plain_integer) {
    mpq_t q;
    mpq_init(q);
    if (mpq_set_str(q, text.c_str() + (text[0] == '+' ? 1 : 0), 10) != 0) {
      mpq_clear(q);
      throw std::invalid_argument("not a rational number: '" + text + "'");
    }
    if (mpz_sgn(mpq_denref(q)) == 0) {
      mpq_clear(q);
      throw std::invalid_argument("zero denominator: '" + text + "'");
    }
    mpq_canonicalize(q);
    Exact r(q);
    mpq_clear(q);
    return r;
  }
  // strtod, not stod: a result that underflows (a subnormal double, or zero) is a number (ERANGE is only an
  // error on overflow). Leading white space is skipped (as stod does), trailing characters are refused.
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) throw std::invalid_argument("not a number: '" + text + "'");
  if (errno == ERANGE && std::isinf(v)) throw std::invalid_argument("not a number: '" + text + "'");
  if (!std::isfinite(v)) throw std::invalid_argument("non-finite number: '" + text + "'");
  return Exact(v);
}

std::pair<double, double> enclosing_interval(const Exact& x) {
  const double d = mpq_get_d(x.mpq());
  const double inf = std::numeric_limits<double>::infinity();
  if (!std::isfinite(d)) return {-inf, inf};
  if (mpz_cmp_ui(mpq_denref(x.mpq()), 1) == 0 && static_cast<double>(d) == d &&
      mpz_sizeinbase(mpq_numref(x.mpq()), 2) <= 53)
    return {d, d};  // small integers convert exactly
  return {std::nextafter(d, -inf), std::nextafter(d, inf)};
}

std::pair<double, double> tight_interval(const Exact& x) {
  const mpq_srcptr q = x.mpq();
  if (mpq_sgn(q) == 0) return {0.0, 0.0};
  const double d = mpq_get_d(q);  // truncated towards 0
  if (!std::isfinite(d) || std::fabs(d) < 0x1p-1021) return CGAL::to_interval(x);  // keep subnormals exact
  // x is a double iff it is a dyadic rational with at most 53 significant bits (then mpq_get_d is exact)
  const mpz_srcptr num = mpq_numref(q), den = mpq_denref(q);
  if (mpz_popcount(den) == 1 && mpz_sizeinbase(num, 2) - mpz_scan1(num, 0) <= 53) return {d, d};
  const double inf = std::numeric_limits<double>::infinity();
  return mpq_sgn(q) > 0 ? std::pair<double, double>{d, std::nextafter(d, inf)}
                        : std::pair<double, double>{std::nextafter(d, -inf), d};
}

bool exact_double(const Exact& x, double* out) {
  const double d = CGAL::to_double(x);
  if (!std::isfinite(d)) return false;
  if (Exact(d) != x) return false;
  if (out) *out = d;
  return true;
}

}  // namespace exactvis
