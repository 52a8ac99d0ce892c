#pragma once
// The one way numbers are printed in the command line's text output (docs/cli.md "Text output"); JSON keeps
// its own exact forms (io/json_number.hpp). Counts are plain decimal digits (no separators, so a reader can
// copy them); measured quantities (seconds, ratios, approximate coordinates) are at most 4 significant digits
// ("0.01234", "12.35", "1.235e+06"), never with trailing zeros.
#include <cstdint>
#include <string>

namespace exactvis {

// A whole count: "-3", "0", "254633".
std::string format_count(std::int64_t n);

// A measured or approximate value: %.4g without trailing zeros; "nan", "inf", "-inf" for non-finite values.
std::string format_measure(double x);

// "a of b (p%)" for a part of a whole: "12 of 40 (30%)"; p by format_measure; b = 0 gives "0 of 0".
std::string format_fraction(std::int64_t part, std::int64_t whole);

}  // namespace exactvis
