#pragma once
// Exact meeting test of a closed segment and a closed tetrahedron (input doubles, CGAL Epick's exactly
// evaluated predicates).
#include "kernel/vec3.hpp"

namespace exactvis {

// Do the closed segment [p, q] (p == q: the point) and the closed tetrahedron (a, b, c, d) (not coplanar)
// meet? Exact.
bool segment_meets_tetrahedron(const Point3& p, const Point3& q, const Point3& a, const Point3& b,
                               const Point3& c, const Point3& d);

}  // namespace exactvis
