#pragma once
// Small helpers shared by the benchmark programs.
#include <chrono>
#include <sstream>
#include <string>
#include <vector>

namespace exactvis::bench {

// Seconds on a steady clock (differences only).
inline double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// "a,b,c" -> {"a", "b", "c"}; empty items are dropped.
inline std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace exactvis::bench
