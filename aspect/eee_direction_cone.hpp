#pragma once
// The directions of the lines meeting three given lines: the curve an EEE event traces on the viewing
// sphere (docs/theory.md §10.7). For the orthographic aspect graph of a general polyhedron, the directions
// of the lines of an EEE event (three edges whose images become concurrent) bound regions; this is the
// exact description of that curve: a quadratic cone through the origin, with a rational parametrisation
// by the point of the line on the first edge (so the curve has dense rational points, and each of its arcs
// has rational samples).
//
// Lines l_i = {A_i + s u_i}, i = 1, 2, 3, with linearly independent directions (not all three parallel to
// one plane). With w_1 = u_2 x u_3, w_2 = u_3 x u_1, w_3 = u_1 x u_2 and the moments m_i = A_i x u_i,
//   q(d) = sum_i (w_i . d) (m_i . d),
// and some line of direction d != 0 meets each l_i or is parallel to it iff q(d) = 0 (proof in theory).
// Through P(t) = A_1 + t u_1, the line meeting l_2 and l_3 lies in the planes through P(t) and l_2, l_3,
// of normals n_j(t) = u_j x (A_j - P(t)) (linear in t); its direction is d(t) = n_2(t) x n_3(t), a
// quadratic polynomial in t (zero only where the two planes coincide).
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"

#include <array>

namespace exactvis {

struct EeeDirectionCone {
  bool degenerate = false;                 // the directions u_i are linearly dependent: q is not the answer
  std::array<std::array<Exact, 3>, 3> q;   // symmetric: q(d) = d^T q d
  std::array<Vec3<Exact>, 3> d;            // d(t) = d[0] + t d[1] + t^2 d[2]
};

// Input: a point A_i and a non-zero direction u_i of each line (exact). Output: the cone and the
// parametrisation. Exact, O(1).
EeeDirectionCone eee_direction_cone(const std::array<Vec3<Exact>, 3>& points,
                                    const std::array<Vec3<Exact>, 3>& directions);

// q(d), exactly.
Exact cone_value(const EeeDirectionCone& cone, const Vec3<Exact>& d);

// d(t), exactly.
Vec3<Exact> cone_direction_at(const EeeDirectionCone& cone, const Exact& t);

}  // namespace exactvis
