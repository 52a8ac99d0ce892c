#pragma once
// Helpers for the io tests: a fresh temporary directory per test (tests/cli_test_util.hpp) and small file
// readers and writers.
#include "tests/cli_test_util.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace iotest {

using cli_test::TempDir;

inline std::string write_file(const std::string& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
  return path;
}

inline std::string read_file(const std::string& path) { return cli_test::slurp(path); }

// Little-endian (this machine's order) float and 32-bit unsigned appended to `s`, for hand-made binary files.
inline void put_f32(std::string& s, float v) {
  char b[4];
  std::memcpy(b, &v, 4);
  s.append(b, 4);
}
inline void put_u32(std::string& s, std::uint32_t v) {
  char b[4];
  std::memcpy(b, &v, 4);
  s.append(b, 4);
}

// Number of entries in a directory (to check that failed writes leave nothing, not even temp files).
inline int entries(const std::filesystem::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace iotest
