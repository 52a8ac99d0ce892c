#pragma once
// Independent slow oracle for convex polyhedra given by half-spaces: plain GMP rationals, no exactvis header.
// Vertices by brute force over every triple of planes (Cramer's rule), volume by the divergence theorem.
#include "oracles/rational_geometry.hpp"

#include <array>
#include <vector>

namespace oracle {

// The closed half-space {x : n . x >= d}.
struct QHalfspace {
  QVec n;
  mpq_class d;
};

// The vertices of the intersection of the half-spaces (assumed bounded): every point where three planes
// with independent normals meet and that satisfies all half-spaces, without repeats. O(k^4) for k planes.
std::vector<QVec> halfspace_vertices(const std::vector<QHalfspace>& halfspaces);

// True iff the points are not all on one plane (the hull has volume).
bool spans_3d(const std::vector<QVec>& points);

// The volume enclosed by a closed surface of triangles oriented outward: sum of det(a, b, c) / 6.
mpq_class enclosed_volume(const std::vector<std::array<QVec, 3>>& triangles);

}  // namespace oracle
