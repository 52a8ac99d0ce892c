#pragma once
// A process-wide observer of progress bars: every ProgressBar (drawn or not) also reports to it, at most ~5
// times a second and once at its end. How library users (the Python module's progress callbacks) follow long
// calls that report progress only through ProgressBar (e.g. the event enumerations).
#include <cstdint>
#include <string>

namespace exactvis {

class ProgressObserver {
 public:
  virtual ~ProgressObserver() = default;
  // Called from the threads that advance a bar, never concurrently for one bar.
  virtual void report(const std::string& label, std::uint64_t done, std::uint64_t total) = 0;
};

// Sets the observer (nullptr: none) and returns the previous one. Set it before the bars of interest start
// and clear it after they end: bars running while it changes may report to either.
ProgressObserver* set_progress_observer(ProgressObserver* observer);

}  // namespace exactvis
