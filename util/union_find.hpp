#pragma once
// Disjoint sets over the integers 0..size()-1 (union by pointing the first root at the second, path halving).
//
// Used wherever a module groups items by an equivalence it discovers pairwise: the 2D complex's face slots,
// the loader's connected components, the aspect graph's regions. Not thread-safe (find compresses paths).
#include <cstddef>
#include <vector>

namespace exactvis {

class UnionFind {
 public:
  // Input: the number of singleton sets to start with (elements 0..n-1).
  explicit UnionFind(std::size_t n = 0);

  // Adds a new singleton set; returns its element (the previous size()). Amortised O(1).
  int add();

  // The representative of x's set (0 <= x < size()). Amortised almost O(1); compresses the path.
  int find(int x);

  // Merges the sets of a and b: the root of a's set then points at the root of b's set (so find(a) returns
  // find(b)'s old representative afterwards). Both in [0, size()).
  void unite(int a, int b);

  // Number of elements.
  std::size_t size() const { return parent_.size(); }

 private:
  std::vector<int> parent_;
};

}  // namespace exactvis
