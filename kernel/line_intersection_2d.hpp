#pragma once
// Exact intersection of two planar lines whose defining points have double coordinates (docs/theory.md
// section 3): every double is an integer times a power of two, so with all coordinates scaled to their
// smallest common power of two the intersection is a quotient of integer polynomials, computed in GMP
// integers (reused per thread: no allocation once warm) and canonicalized once per coordinate.
#include "kernel/number_types.hpp"

#include <array>

namespace exactvis {

using Double2 = std::array<double, 2>;

// The point c + t (d1 - d0) on the line through c with direction d1 - d0 that also lies on the line
// through a and b: t = cross(a - c, b - a) / cross(d1 - d0, b - a). Inputs must be finite, the lines not
// parallel (cross(d1 - d0, b - a) != 0; std::invalid_argument otherwise). Returns the exact coordinates.
// Cost: O(1) multiplications of integers of about 100-300 bits, two gcds.
std::array<Exact, 2> line_intersection_2d(const Double2& c, const Double2& d0, const Double2& d1, const Double2& a,
                                          const Double2& b);

}  // namespace exactvis
