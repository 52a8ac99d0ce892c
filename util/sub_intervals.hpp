#pragma once
// Splitting an interval at cut points, for the work stacks of the end-object splits (events/ev_interval_split
// over exact rationals, shadows/eee_interval_split over RootNumber).
#include <algorithm>
#include <utility>
#include <vector>

namespace exactvis {

// Pushes onto the work stack `todo` the sub-intervals of [lo, hi] between consecutive distinct values of
// `cuts` together with lo and hi (cuts must lie in [lo, hi]), the rightmost first, so that popping the stack
// visits them from left to right. T needs < and ==. Cost: O(k log k) comparisons for k cuts.
template <class T>
void push_sub_intervals(std::vector<T> cuts, const T& lo, const T& hi, std::vector<std::pair<T, T>>& todo) {
  cuts.push_back(lo);
  cuts.push_back(hi);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  for (std::size_t i = cuts.size() - 1; i > 0; --i) todo.emplace_back(cuts[i - 1], cuts[i]);
}

}  // namespace exactvis
