#include "util/union_find.hpp"

#include <numeric>

namespace exactvis {

UnionFind::UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }

int UnionFind::add() {
  parent_.push_back(static_cast<int>(parent_.size()));
  return parent_.back();
}

int UnionFind::find(int x) {
  while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
  return x;
}

void UnionFind::unite(int a, int b) { parent_[find(a)] = find(b); }

}  // namespace exactvis
