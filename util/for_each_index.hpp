#pragma once
// One loop over the indices 0..n-1, on oneTBB's threads or in order on the calling thread: the event
// enumerations and the per-cell visibility take `parallel = false` for reproducible single-thread runs and
// tests.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace exactvis {

// Calls f(i) for every i in [0, n); with `parallel`, in oneTBB chunks of about `grain` indices.
template <class F>
void for_each_index(std::size_t n, bool parallel, std::size_t grain, F&& f) {
  if (!parallel) {
    for (std::size_t i = 0; i < n; ++i) f(i);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
  });
}

}  // namespace exactvis
