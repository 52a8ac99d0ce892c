#pragma once
// Splitting and trimming option text (the command line's lists "a,b,c", the façades' specs such as
// `--pair A,B` and `--receivers IDS`).
#include <string>
#include <vector>

namespace exactvis {

// The items of s between separators, empty ones included ("a,,b" -> a, "", b; "a," -> a, ""; "" -> none).
std::vector<std::string> split(const std::string& s, char sep);

// s without leading and trailing spaces and tabs.
std::string trim(const std::string& s);

}  // namespace exactvis
