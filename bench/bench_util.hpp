#pragma once
// Small helpers shared by the benchmark programs.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <sstream>
#include <string>
#include <vector>

namespace exactvis::bench {

// Seconds on a steady clock (differences only).
inline double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Wall-clock and process CPU seconds of one call (the machine may be shared: CPU seconds are the fairer
// figure; the process clock counts every thread of the call).
struct Timing {
  double wall = 0, cpu = 0;
};

template <class F>
Timing timed(F&& f) {
  const double w0 = now();
  const std::clock_t c0 = std::clock();
  f();
  return {now() - w0, static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC};
}

// "a,b,c" -> {"a", "b", "c"}; empty items are dropped.
inline std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) if (!item.empty()) out.push_back(item);
  return out;
}

// The error for an option a benchmark does not know: one line on stderr (the program's options are listed in
// the comment at the top of bench/PROGRAM.cpp); returns 2, the exit status, for `return unknown_option(...)`.
inline int unknown_option(const char* program, const std::string& name) {
  std::fprintf(stderr, "%s: unknown option %s (the options are listed at the top of bench/%s.cpp)\n", program,
               name.c_str(), program);
  return 2;
}

// Options are "--name value" pairs from argv[first] on. A lone last word (such as --help) or a name without
// the leading "--" is an unknown option: the program exits with status 2 instead of silently running its whole
// default benchmark.
inline void require_option_pairs(int argc, char** argv, int first, const char* program) {
  for (int i = first; i < argc; i += 2) {
    const std::string a = argv[i];
    if (a.size() < 3 || a.compare(0, 2, "--") != 0) std::exit(unknown_option(program, a));
    if (i + 1 >= argc) {
      std::fprintf(stderr, "%s: %s: no value (or not an option; the options are listed at the top of bench/%s.cpp)\n",
                   program, a.c_str(), program);
      std::exit(2);
    }
  }
}

}  // namespace exactvis::bench
