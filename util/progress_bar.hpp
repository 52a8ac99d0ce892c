#pragma once
// A progress bar on stderr for long runs; thread-safe `advance` / `set_done`, redraws at most ~5 times a
// second. Whether to draw at all is the caller's decision (the command line draws only when stderr is a
// terminal and -q is not given: apps/cli_util.hpp).
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace exactvis {

class ProgressBar {
 public:
  // Input: a label, the number of steps, and whether to draw at all (disabled bars cost one atomic add).
  ProgressBar(std::string label, std::uint64_t total, bool enabled);
  ~ProgressBar();  // draws the final state and a newline if enabled
  // Adds `steps` to the steps done. Thread-safe.
  void advance(std::uint64_t steps = 1);
  // Sets the steps done to max(current, done) (for work that reports its own position). Thread-safe.
  void set_done(std::uint64_t done);

 private:
  void draw(std::uint64_t done);
  std::string label_;
  std::uint64_t total_;
  bool enabled_;
  std::atomic<std::uint64_t> done_{0};
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace exactvis
