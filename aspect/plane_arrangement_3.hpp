#pragma once
// The arrangement of finitely many planes in R^3, exactly: every cell of every dimension (vertices, edges,
// 2-faces, 3-cells), each with its sign vector, an exact sample point in its relative interior and its
// facets (the cells of one dimension less in its closure). docs/theory.md, "Aspect graphs of polyhedra".
//
// Cells are the classes of points with equal sign vectors (sigma_k = sign(n_k . x - c_k)); each class is
// convex, hence one cell. Enumeration goes upward: vertices = points on three planes with independent
// normals; on each line of two planes its vertices in order, the segments between them and the two rays
// (or the whole line if no plane crosses it); from each k-cell, the (k+1)-cells around it are found by
// moving its sample a little along the directions that leave exactly one of the planes holding it, with the
// sign vector of the moved point decided symbolically (the sign at the sample, or where that is zero the
// sign of the direction) and the step length an exact power of two below every distance to a plane not
// holding the cell. When the normals span R^3 every cell of dimension k >= 1 has a facet, so every cell is
// found. A central arrangement (all offsets 0) gives the cones whose traces on the unit sphere are the
// cells of the arrangement of great circles (the origin is its only vertex; cone dimension = 1 + dimension
// of the trace).
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"

#include <string>
#include <vector>

namespace exactvis {

// {x : normal . x = offset}; its positive side is normal . x > offset.
struct ArrangementPlane {
  Vec3<Exact> normal;
  Exact offset;
};

struct ArrangementCell {
  int dimension = 0;        // 0 .. 3
  std::string signs;        // per plane: '-', '0' or '+'
  Vec3<Exact> sample;       // a point of the cell's relative interior
  std::vector<int> facets;  // cells of dimension - 1 in this cell's closure
};

struct PlaneArrangement {
  std::vector<ArrangementCell> cells;  // vertices first, then edges, 2-faces, 3-cells
  int vertices = 0, edges = 0, faces = 0, volumes = 0;  // cells per dimension
};

// Input: distinct planes (no two with the same point set) whose normals span R^3 (else
// std::invalid_argument); optional progress callback (fraction done, 0 .. 1). Output: all cells. Cost: O(m^2) lines with O(m) crossings each, then O(m) exact
// (interval-filtered) sign evaluations per cell found, for m planes; memory O(m) per cell.
PlaneArrangement plane_arrangement(const std::vector<ArrangementPlane>& planes, void (*progress)(double) = nullptr);

}  // namespace exactvis
