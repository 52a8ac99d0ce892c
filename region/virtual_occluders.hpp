#pragma once
// Virtual occluders of the exact PVS traversal (region/exact_pvs.hpp, docs/theory.md §5.8): hierarchy boxes
// already PROVED dark from the view cell (every line with a segment from the cell to the box whose open
// interior misses every scene triangle forms a null set), used as solids for what lies behind them. A
// target (a BVH node's box, a triangle) all of whose segments from the closed cell meet a dark box V is
// hidden: each free segment to the target would contain a free segment from the cell to V.
//
// Floats only choose (a double pass rejects; every "blocked" answer is exact: interval arithmetic, then GMP).
#include "kernel/scene.hpp"
#include "region/convex_polygon_3.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace exactvis::region {

// Input: a segment [a, b] (a exact, b a double point) and a closed box V (double corners, lo <= hi; flat
// boxes allowed). Output: true iff the closed segment meets the closed box. Exact (division-free clipping
// of t in [0, 1] by the three slabs; interval filter, GMP fallback). Cost: 3 slabs, 16 comparisons.
bool segment_meets_box(const RationalPoint3& a, const Point3& b, const Box3& v);

// Input: the closed cell, a closed box V and the corners of a target X (X = their convex hull: 8 corners of
// a box, 3 of a triangle). Output: true iff every segment from a point of the cell to a point of X meets V
// (exact: it suffices that the 8 x |corners| corner segments do, by the convexity of shadows, §5.9).
// Cost: a double pass (early exit on the first segment that clearly misses V), then up to 8 x |corners|
// exact segment tests.
bool box_blocks(const Box3& v, const RationalBox3& cell, std::span<const Point3> target_corners);

// The dark boxes of one cell, best first (larger and nearer the cell: higher diag^2 / distance^2), at most
// `cap` of them (the worst is dropped). Not thread-safe: one traversal thread adds and asks.
class VirtualOccluders {
 public:
  // Input: the cell (lo < hi) and the cap (0: never blocks).
  VirtualOccluders(const RationalBox3& cell, int cap);

  // Registers a box proved dark from the cell (by the caller's proof; a box blocked by a registered one
  // adds nothing: its shadow lies inside that one's, so do not add it).
  void add(const Box3& dark);

  // True iff a registered dark box blocks every segment from the cell to the convex hull of the corners
  // (box_blocks); the box that did is tried first next time. Cost: one double segment test per registered
  // box (segment between centres) plus box_blocks on those that pass.
  bool blocks(std::span<const Point3> target_corners);

  std::size_t size() const { return boxes_.size(); }
  std::int64_t added() const { return added_; }          // boxes registered (before the cap)
  std::int64_t exact_tests() const { return exact_tests_; }  // box_blocks calls past the centre test

 private:
  struct Entry {
    Box3 box;
    double priority = 0;
  };
  RationalBox3 cell_;
  Box3 approx_;
  Point3 centre_;
  int cap_ = 0;
  std::vector<Entry> boxes_;  // sorted by priority, highest first
  std::size_t last_ = 0;      // the box that blocked last
  std::int64_t added_ = 0, exact_tests_ = 0;
};

// The 8 corners of a double box (bit k of the index: hi on axis k).
std::array<Point3, 8> corners_of(const Box3& b);

}  // namespace exactvis::region
