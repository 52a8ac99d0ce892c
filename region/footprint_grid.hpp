#pragma once
// A uniform 2D grid over the xy bounding boxes of occluders (wall footprints, convex solids' boxes), so that
// single-occluder culling (region/single_occluder_culling.hpp) tries only the occluders near the top view
// of the cell-to-target shaft instead of all of them (docs/theory.md §5.10, "Which walls are tried").
//
// A filter only: it never decides anything. Its one promise is completeness: visit_hull reports every item
// whose box meets the convex hull of the query points (in exact arithmetic), because both the items' boxes
// and the hull are widened by a margin far larger than the rounding of the double computations below; it
// may also report items that are a little farther away.
#include "kernel/scene.hpp"

#include <cstdint>
#include <vector>

namespace exactvis::region {

struct XyPoint {
  double x = 0, y = 0;
};

class FootprintGrid {
 public:
  FootprintGrid() = default;
  // Input: one xy box per item (lo <= hi; z ignored). About one item per grid cell, at most 2048 x 2048 cells.
  // Cost: O(items + sum over items of the cells their box covers).
  explicit FootprintGrid(const std::vector<Box3>& boxes);

  std::size_t size() const { return items_; }

  // Calls f(item) once for every item whose box may meet conv(points) (every item whose box does meet it is
  // reported), until f returns true; returns whether some call returned true. Items come roughly nearest to
  // `origin` first (rows from the origin's row outwards, columns likewise), a speed heuristic only.
  // Not reentrant on one thread (a per-thread visit stamp is shared by all grids); thread-safe otherwise.
  // Cost: O(k log k) for the hull of k points, plus O(1) per grid cell the widened hull covers and per item
  // listed in those cells.
  template <class F>
  bool visit_hull(const std::vector<XyPoint>& points, XyPoint origin, F&& f) const {
    if (items_ == 0 || points.empty()) return false;
    std::vector<Span> rows;
    const int origin_row = covered_rows(points, origin, rows);
    const Visit v = begin_visit();
    std::uint32_t* const stamp = v.stamp;
    const std::uint32_t gen = v.generation;
    const int oc = column_of(origin.x);
    // Rows from the origin's outwards: r = o, o+1, o-1, o+2, ...
    const int n_rows = static_cast<int>(rows.size());
    for (int step = 0; step < 2 * n_rows + 2; ++step) {
      const int r = origin_row + ((step % 2 == 0) ? step / 2 : -(step + 1) / 2);
      if (r < 0 || r >= n_rows || rows[static_cast<std::size_t>(r)].c0 > rows[static_cast<std::size_t>(r)].c1) continue;
      const Span& s = rows[static_cast<std::size_t>(r)];
      const int start = oc < s.c0 ? s.c0 : (oc > s.c1 ? s.c1 : oc);
      for (int k = 0; k <= 2 * (s.c1 - s.c0); ++k) {
        const int c = start + ((k % 2 == 0) ? k / 2 : -(k + 1) / 2);
        if (c < s.c0 || c > s.c1) continue;
        const std::size_t cell = static_cast<std::size_t>(s.row) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(c);
        for (std::uint32_t i = first_[cell]; i < first_[cell + 1]; ++i) {
          const std::uint32_t item = list_[i];
          if (stamp[item] == gen) continue;
          stamp[item] = gen;
          if (f(static_cast<std::size_t>(item))) return true;
        }
      }
    }
    return false;
  }

 private:
  struct Span {
    int row = 0, c0 = 0, c1 = -1;  // grid row and its covered columns [c0, c1]
  };
  // The grid rows the widened hull covers, each with its column range (rows[k].row = first row + k); returns
  // the index in `rows` of the origin's row (clamped).
  int covered_rows(const std::vector<XyPoint>& points, XyPoint origin, std::vector<Span>& rows) const;
  int column_of(double x) const;
  struct Visit {
    std::uint32_t* stamp;     // the calling thread's stamps, at least items_ entries
    std::uint32_t generation;  // fresh: no stamp equals it yet
  };
  Visit begin_visit() const;

  std::size_t items_ = 0;
  int nx_ = 0, ny_ = 0;
  double x0_ = 0, y0_ = 0, hx_ = 1, hy_ = 1, margin_ = 0;
  std::vector<std::uint32_t> first_, list_;  // CSR: items of cell c are list_[first_[c] .. first_[c + 1])
};

}  // namespace exactvis::region
