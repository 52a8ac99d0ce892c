#pragma once
// Progress of a run over work items that each have many steps (`exactvis pvs`: cells of triangles), on
// stderr: items done, the current item's steps, elapsed time and an estimate of the time left. Redraws at
// most ~5 times a second; thread-safe. Whether to draw at all is the caller's decision (apps/cli_util.hpp).
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace exactvis {

class CellsProgress {
 public:
  // Input: a label, the number of items, the name of an item's steps ("triangles"), whether to draw.
  CellsProgress(std::string label, std::uint64_t items, std::string step_name, bool enabled);
  ~CellsProgress();  // draws the final state and a newline if enabled
  // Starts an item of `steps` steps. Thread-safe.
  void start_item(std::uint64_t steps);
  // Steps done in the current item (the largest value reported counts). Thread-safe.
  void item_steps(std::uint64_t done);
  // One more item finished. Thread-safe.
  void finish_item();

 private:
  void maybe_draw(bool force);
  std::string label_, step_name_;
  std::uint64_t items_;
  bool enabled_;
  std::atomic<std::uint64_t> items_done_{0}, steps_{0}, steps_done_{0};
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace exactvis
