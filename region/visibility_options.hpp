#pragma once
// Options and counters of one from-region visibility query (region/from_region_visibility.hpp).
#include <cstdint>

namespace exactvis::region {

struct VisibilityOptions {
  int samples = 48;             // random segments cast per stabbing pair before the exact query
  std::uint64_t seed = 1;       // for sampling (results do not depend on it, only the witness may)
  bool round_witness = true;    // report the witness with double coordinates when that rounding stays a
                                // valid witness (re-checked exactly), else with exact rationals
  std::int64_t split_budget = 0;  // > 0: the CSG of one stabbing pair gives up (PairVisibility::gave_up, no
                                  // answer) once it has made this many splits; 0: no limit. Only callers for
                                  // whom "no answer" is sound may set it (the hidden-box test, §5.8).
};

struct VisibilityStats {
  std::int64_t stabbing_pairs = 0;
  std::int64_t occluders_considered = 0;   // candidates left after shaft culling and clipping
  std::int64_t effective_occluders = 0;    // occluders that split or removed at least one cone
  std::int64_t samples_cast = 0;
  std::int64_t splits = 0;                 // halfspace intersections performed
  std::int64_t cones_created = 0;
  std::int64_t cones_alive_max = 0;        // largest stack of pending cones
  std::int64_t real_line_tests = 0;
  std::int64_t face_tests = 0;             // faces examined by the exhaustive step of the real-line test
  std::int64_t exact_evaluations = 0;      // kernel predicate exact fallbacks during the query (approximate
                                           // when queries run in parallel)
  bool accepted_by_sampling = false;
};

// Adds the counters of `part` to `total` (cones_alive_max: maximum; accepted_by_sampling: or).
void accumulate(VisibilityStats& total, const VisibilityStats& part);

}  // namespace exactvis::region
