#pragma once
// The canonical boundary of a union of interior-disjoint convex cells in an exact 2D chart (docs/theory.md
// section 11, "Visible part of the light without Boolean set operations"): polygons with holes whose loops
// depend only on the point set, not on how it was cut into cells.
//
// Rule. A point of a cell edge is on the boundary iff exactly one side of it is covered by cells. On each
// supporting line (lines compared exactly, after normalisation) the boundary is the symmetric difference of
// the edge intervals with the cells on the left and those with the cells on the right, in maximal runs; each
// run is a boundary edge with the covered side on its left, cut where another run ends inside it (loops
// touching there: the arrangement's vertices). Edges are linked into loops at their ends; where
// several boundary edges leave one vertex (two loops touching there), an edge arriving at the vertex goes on
// along the first outgoing edge clockwise from its own reverse direction, so that each loop bounds one
// angular sector of the region at that vertex (the face rule of a planar arrangement's boundary cycles: a
// hole touching the outer boundary at a vertex is part of that loop). Loops of positive signed area are
// outer boundaries (counterclockwise), the others holes (clockwise), each assigned to the smallest outer
// loop containing it. Canonical form: no vertex where a loop goes straight on, each loop starts at its
// lexicographically smallest vertex (x, then y; of two visits of one vertex, the one followed by the smaller
// vertex), holes and pieces sorted by their first vertex.
#include "kernel/number_types.hpp"

#include <array>
#include <vector>

namespace exactvis::shadows {

using ChartPoint = std::array<Exact, 2>;

// One connected piece of a region: its outer loop (counterclockwise) and holes (clockwise).
struct ChartPolygonWithHoles {
  std::vector<ChartPoint> outer;
  std::vector<std::vector<ChartPoint>> holes;
};

// A region as canonical polygons with holes, and its exact area.
struct ChartRegion {
  std::vector<ChartPolygonWithHoles> pieces;
  Exact area = 0;
};

// Input: convex cells, each counterclockwise with positive area (consecutive vertices distinct; collinear
// vertices allowed), interiors pairwise disjoint. Output: the canonical boundary of their union (rule
// above) and its area. Exact. Cost: O(E log E) exact comparisons for E cell edges, plus O(H P) point
// location for H holes among P outer loops when there are several outer loops.
ChartRegion cell_union_boundary(const std::vector<std::vector<ChartPoint>>& cells);

}  // namespace exactvis::shadows
