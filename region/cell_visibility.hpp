#pragma once
// Visibility of a list of scene triangles from one source (an axis-aligned view cell or a convex polygon):
// one exact from-region query per target (region/from_region_visibility.hpp), run on all cores. The unit a
// PVS is built from (one cell, all its candidate triangles).
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"
#include "region/convex_polygon_3.hpp"
#include "region/from_region_visibility.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace exactvis::region {

// The source: a view cell (lo < hi in every coordinate, exact corners) when `cell` is set, else the convex
// polygon `polygon` (validate_source_polygon).
struct VisibilitySource {
  std::optional<RationalBox3> cell;
  Polygon3 polygon;
};

struct CellVisibilityOptions {
  VisibilityOptions query;  // per target (samples, seed, witness rounding)
  int threads = 0;          // worker threads: 0 = all cores, else 1 .. kMaxThreads
  // Called once per finished target, from the worker threads (must be thread-safe), e.g. a progress bar.
  std::function<void()> on_target_done;
};

// The largest thread count CellVisibilityOptions::threads accepts.
inline constexpr int kMaxThreads = 1024;

// Throws std::invalid_argument("thread count N is outside 0 .. kMaxThreads") unless 0 <= threads <= kMaxThreads
// (0 = all cores): the one check of every region entry point that takes a thread count.
void check_thread_count(int threads);

struct CellVisibility {
  std::vector<VisibilityResult> results;  // one per target, in the order given
  VisibilityStats stats;                  // accumulated over all results (accumulate())
  std::int64_t visible = 0;               // targets found visible
  std::int64_t accepted_by_sampling = 0;  // targets whose witness came from the sampling step
};

// Input: the scene, its triangle index, the source, target triangles (indices into Scene::triangles, any
// order, repeats allowed) and options. Output: see CellVisibility; answers do not depend on the thread
// count (witnesses depend only on the seed). Throws std::invalid_argument for threads outside
// [0, kMaxThreads], a target index out of range, or an invalid cell. Cost: the sum of the per-target
// queries, divided among the threads.
CellVisibility visibility_from_source(const Scene& scene, const TriangleIndex& index, const VisibilitySource& source,
                                      const std::vector<std::int64_t>& targets, const CellVisibilityOptions& options = {});

}  // namespace exactvis::region
