#include "io/json_number.hpp"

#include <stdexcept>

namespace exactvis {

nlohmann::json exact_to_json(const Exact& x) {
  double d = 0;
  if (exact_double(x, &d)) return d;
  return to_rational_string(x);
}

Exact exact_from_json(const nlohmann::json& j) {
  if (j.is_number_integer()) {
    // Integers beyond 2^53 must not go through a double.
    return parse_rational(j.dump() + "/1");
  }
  if (j.is_number_float()) return Exact(j.get<double>());
  if (j.is_string()) return parse_rational(j.get<std::string>());
  throw std::invalid_argument("expected a number or a \"num/den\" string, got " + j.dump());
}

}  // namespace exactvis
