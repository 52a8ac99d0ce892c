#include "aspect/aspect_regions.hpp"

#include "util/union_find.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace exactvis {

AspectRegions aspect_regions(const std::vector<AspectCell>& cells, const std::vector<bool>& keep) {
  const int n = static_cast<int>(cells.size());
  UnionFind uf(n);
  // Pairs (lower, upper) of kept cells with different aspects, lower in the closure of upper.
  std::vector<std::pair<int, int>> touching;
  std::vector<int> stamp(n, -1), stack;
  for (int b = 0; b < n; ++b) {
    if (!keep[b]) continue;
    stack.assign(1, b);
    stamp[b] = b;
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      for (int f : cells[c].facets) {
        if (!keep[f] || stamp[f] == b) continue;
        stamp[f] = b;
        stack.push_back(f);
        if (cells[f].aspect == cells[b].aspect) uf.unite(f, b);
        else touching.emplace_back(f, b);
      }
    }
  }
  AspectRegions r;
  r.region_of.assign(n, -1);
  // Regions: classes of kept cells; ordered by decreasing dimension, then first cell.
  std::map<int, std::vector<int>> classes;
  for (int c = 0; c < n; ++c)
    if (keep[c]) classes[uf.find(c)].push_back(c);
  std::vector<std::vector<int>> groups;
  for (auto& [root, m] : classes) groups.push_back(std::move(m));
  std::vector<int> dim(groups.size(), 0);
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (int c : groups[g]) dim[g] = std::max(dim[g], cells[c].dimension);
  std::vector<std::size_t> order(groups.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return dim[x] != dim[y] ? dim[x] > dim[y] : groups[x].front() < groups[y].front();
  });
  for (std::size_t id = 0; id < order.size(); ++id) {
    for (int c : groups[order[id]]) r.region_of[c] = static_cast<int>(id);
    r.members.push_back(std::move(groups[order[id]]));
    r.dimension.push_back(dim[order[id]]);
  }
  // One entry per region pair, witnessed by its first touching pair (stable sort keeps the order found).
  for (const auto& [lo, up] : touching) {
    const auto [a, b] = std::minmax(r.region_of[lo], r.region_of[up]);
    r.adjacency.push_back({a, b, lo, up});
  }
  std::stable_sort(r.adjacency.begin(), r.adjacency.end(), [](const auto& x, const auto& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  r.adjacency.erase(std::unique(r.adjacency.begin(), r.adjacency.end(),
                                [](const auto& x, const auto& y) { return x.a == y.a && x.b == y.b; }),
                    r.adjacency.end());
  return r;
}

}  // namespace exactvis
