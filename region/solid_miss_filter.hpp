#pragma once
// A certified cheap rejection for the convex-solid proof of the conservative PVS (docs/theory.md §5.10,
// "Fallback"): solid_blocks_box_pair (region/convex_occluder.hpp) needs all 64 corner-to-corner segments
// between the cell and the target box to meet the closed solid. This filter runs the clipping of
// segment_meets_solid on those segments in interval arithmetic (CGAL's Interval_nt; the facets and the cell
// corners converted once per cell), keeping only the facets whose signs at both ends the intervals decide:
// dropping a facet only enlarges the parameters left, so an empty parameter set (or both ends strictly
// outside one facet) proves that the segment misses the solid, and then the exact test would fail. So
// skipping the exact test on "misses" changes no answer; "may meet" says nothing (the exact test decides).
// In a forest most tried crowns fail the exact test, and they fail here first at a fraction of its cost
// (the exact test converts every rational coordinate to an interval on each call).
#include "region/convex_occluder.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace exactvis::region {

class SolidMissFilter {
 public:
  SolidMissFilter() = default;  // proves nothing
  // Input: the closed cell and the solids to be tried from it (indices into `solids`). Cost: O(F) interval
  // conversions per listed solid with F facets.
  SolidMissFilter(const std::vector<ConvexSolid>& solids, const std::vector<std::size_t>& listed, const RationalBox3& cell);

  // True proves that some segment from a corner of the cell to a corner of the box (doubles: its corners
  // are exact) misses solid `k` (one of `listed`), so solid_blocks_box_pair(solid k, cell, box) is false.
  // False: not proved. Cost: 16 F interval dot products and at most 64 F interval divisions (F facets).
  bool proves_miss(std::size_t k, const Box3& box) const;

 private:
  struct Facet {
    double nx_lo, nx_hi, ny_lo, ny_hi, nz_lo, nz_hi, d_lo, d_hi;
  };
  std::vector<std::vector<Facet>> facets_;  // per solid index (empty for solids not listed)
  std::array<std::array<double, 6>, 8> cell_corners_{};  // per corner: x, y, z enclosures (lo, hi)
};

}  // namespace exactvis::region
