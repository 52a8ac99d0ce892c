#include "region/visibility_options.hpp"

#include <algorithm>

namespace exactvis::region {

void accumulate(VisibilityStats& s, const VisibilityStats& f) {
  s.stabbing_pairs += f.stabbing_pairs;
  s.occluders_considered += f.occluders_considered;
  s.effective_occluders += f.effective_occluders;
  s.samples_cast += f.samples_cast;
  s.splits += f.splits;
  s.cones_created += f.cones_created;
  s.cones_alive_max = std::max(s.cones_alive_max, f.cones_alive_max);
  s.real_line_tests += f.real_line_tests;
  s.face_tests += f.face_tests;
  s.exact_evaluations += f.exact_evaluations;
  s.accepted_by_sampling |= f.accepted_by_sampling;
}

}  // namespace exactvis::region
