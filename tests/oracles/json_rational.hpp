#pragma once
// Exact numbers as exactvis writes them in JSON (a number, read as the double it is, or a string "p/q"),
// parsed into the oracle's GMP rationals: how the CLI tests hand a command's answers to the oracles.
#include "oracles/visibility_oracle.hpp"

#include <gmpxx.h>
#include <nlohmann/json.hpp>

namespace oracle {

// Input: a JSON number or a rational string ("-3/4", "5"). Output: its exact value, canonical.
inline mpq_class json_rational(const nlohmann::json& j) {
  if (j.is_number()) return mpq_class(j.get<double>());
  mpq_class q(j.get<std::string>());
  q.canonicalize();
  return q;
}

// Input: a JSON array of three such numbers. Output: the exact point.
inline QVec json_point(const nlohmann::json& j) { return {json_rational(j[0]), json_rational(j[1]), json_rational(j[2])}; }

}  // namespace oracle
