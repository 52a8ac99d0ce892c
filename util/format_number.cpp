#include "util/format_number.hpp"

#include <cmath>
#include <cstdio>

namespace exactvis {

std::string format_count(std::int64_t n) { return std::to_string(n); }

std::string format_measure(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);  // %g already drops trailing zeros
  std::string s = buf;
  if (s == "-0") s = "0";
  return s;
}

std::string format_fraction(std::int64_t part, std::int64_t whole) {
  std::string s = format_count(part) + " of " + format_count(whole);
  if (whole != 0) s += " (" + format_measure(100.0 * static_cast<double>(part) / static_cast<double>(whole)) + "%)";
  return s;
}

}  // namespace exactvis
