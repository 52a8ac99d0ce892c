#pragma once
// Regions of an aspect partition (docs/theory.md, "Aspect graphs of polyhedra"): from a cell complex whose
// cells carry aspects, the maximal connected sets of cells with one aspect, and the region adjacency.
//
// Cells are relatively open and pairwise disjoint; the closure of a cell is the cell and the cells reached
// from it through facets, transitively. A union of cells is connected iff its cells are connected through
// the relation "one lies in the other's closure", so a region is a class of that relation restricted to
// cells of equal aspect, and two regions are adjacent iff a cell of one lies in the closure of a cell of
// the other.
#include <array>
#include <vector>

namespace exactvis {

struct AspectCell {
  int dimension = 0;
  int aspect = 0;           // aspect id: equal ids = equal aspects
  std::vector<int> facets;  // cells of dimension - 1 in its closure (indices into the cell list)
};

struct AspectRegions {
  std::vector<int> region_of;             // per cell; -1 for cells not in `keep`
  std::vector<std::vector<int>> members;  // per region: its cells, ascending
  std::vector<int> dimension;             // per region: the largest dimension of its cells
  // Adjacent region pairs (a < b), each with one witness: cells lower (in the closure of) upper.
  struct Adjacency {
    int a = 0, b = 0;
    int lower = 0, upper = 0;
  };
  std::vector<Adjacency> adjacency;       // sorted by (a, b)
};

// Input: cells (facets point to cells of any index) and which cells are viewpoints (`keep`; a facet that is
// not kept is skipped, so are its own facets). Output: regions numbered by decreasing dimension, then by
// their first cell; adjacency. Cost: the sum over kept cells of the size of their closure.
AspectRegions aspect_regions(const std::vector<AspectCell>& cells, const std::vector<bool>& keep);

// The cell a region's aspect and sample are taken from: the first of its members (ascending) of the region's
// largest dimension. `Cell` is any cell type with a `dimension` (AspectCell, or a graph's own). Cost: the
// number of members.
template <class Cell>
int region_sample_cell(const AspectRegions& regions, std::size_t r, const std::vector<Cell>& cells) {
  int best = regions.members[r].front();
  for (int c : regions.members[r])
    if (cells[c].dimension > cells[best].dimension) best = c;
  return best;
}

}  // namespace exactvis
