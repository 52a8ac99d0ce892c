#pragma once
// Exact numbers in JSON: a JSON number when the value is exactly a double (so ordinary readers get the exact
// value), else the string "num/den".
#include "kernel/number_types.hpp"

#include <nlohmann/json.hpp>

namespace exactvis {

// Input: an exact rational. Output: a JSON number if it is exactly a finite double, else "num/den".
nlohmann::json exact_to_json(const Exact& x);

// Input: a JSON number (taken as the exact double it is; integers exactly) or a string "num/den", "num", or a
// decimal literal. Output: the exact value. Throws std::invalid_argument for anything else.
Exact exact_from_json(const nlohmann::json& j);

}  // namespace exactvis
