#pragma once
// The ray-constraint incidence sets of the double description cones (region/polyhedral_cone6): a set of
// bits 0 .. size()-1 with the few operations the double description step needs. The bits live in the
// object itself up to kInlineBits (every cone of the generated towns and forests: a cone has its pair's
// edges plus a few occluder edges), on the heap only beyond, so copying a cone, widening a set by one
// constraint and the adjacency test allocate nothing in the common case (boost::dynamic_bitset allocated
// on every copy, ~20 % of a PVS cell in perf, docs/performance.md).
#include <boost/container/small_vector.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>

namespace exactvis::region {

class IncidenceSet {
 public:
  static constexpr std::size_t kInlineBits = 128;

  IncidenceSet() = default;
  // n bits, all clear. Cost O(n / 64).
  explicit IncidenceSet(std::size_t n) : size_(n), words_(words_for(n), 0) {}

  std::size_t size() const { return size_; }
  // Bit i (requires i < size()).
  bool test(std::size_t i) const { return (words_[i >> 6] >> (i & 63)) & 1u; }
  bool operator[](std::size_t i) const { return test(i); }
  void set(std::size_t i, bool value = true) {
    const std::uint64_t m = std::uint64_t(1) << (i & 63);
    if (value) words_[i >> 6] |= m;
    else words_[i >> 6] &= ~m;
  }
  // Every bit 0 .. size()-1 set.
  void set_all() {
    for (auto& w : words_) w = ~std::uint64_t(0);
    trim();
  }
  // New bits are clear; bits beyond n are dropped.
  void resize(std::size_t n) {
    words_.resize(words_for(n), 0);
    size_ = n;
    trim();
  }
  // Number of set bits.
  std::size_t count() const {
    std::size_t c = 0;
    for (const auto w : words_) c += static_cast<std::size_t>(std::popcount(w));
    return c;
  }
  // Intersection with a set of the same size.
  IncidenceSet& operator&=(const IncidenceSet& o) {
    for (std::size_t k = 0; k < words_.size(); ++k) words_[k] &= o.words_[k];
    return *this;
  }
  // True iff every bit of this set is in o (same size).
  bool is_subset_of(const IncidenceSet& o) const {
    for (std::size_t k = 0; k < words_.size(); ++k)
      if (words_[k] & ~o.words_[k]) return false;
    return true;
  }
  friend bool operator==(const IncidenceSet& a, const IncidenceSet& b) {
    if (a.size_ != b.size_) return false;
    for (std::size_t k = 0; k < a.words_.size(); ++k)
      if (a.words_[k] != b.words_[k]) return false;
    return true;
  }

 private:
  static std::size_t words_for(std::size_t n) { return (n + 63) / 64; }
  // Clears the bits at or beyond size_ in the last word (so count and comparisons see only real bits).
  void trim() {
    if (size_ & 63) words_.back() &= (std::uint64_t(1) << (size_ & 63)) - 1;
  }
  std::size_t size_ = 0;
  boost::container::small_vector<std::uint64_t, kInlineBits / 64> words_;
};

}  // namespace exactvis::region
