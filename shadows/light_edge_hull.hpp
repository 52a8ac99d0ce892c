#pragma once
// The convex hull of a light triangle and a blocker edge, conv(L ∪ [f0, f1]), as the union of its
// Carathéodory tetrahedra: shared by the blocker-blocker EV cull (shadows/blocker_events) and the EEE one
// (shadows/blocker_eee_events).
#include "kernel/predicates.hpp"
#include "kernel/vec3.hpp"

#include <array>

namespace exactvis::shadows {

// Calls test(t, o) for each tetrahedron t on four of the five points (l's corners, f0, f1) that is not flat,
// o its orientation (orient3d(t[0], t[1], t[2], t[3]), never Zero); the closed tetrahedra cover the closed
// hull. True as soon as one test is true; also true when all five points are coplanar (no solid tetrahedron:
// conservatively, the caller keeps the candidate). Exact; at most 5 orientation tests plus the tests.
template <class Test>
bool any_light_edge_tetrahedron(const std::array<Point3, 3>& l, const Point3& f0, const Point3& f1, Test&& test) {
  const std::array<Point3, 5> v{l[0], l[1], l[2], f0, f1};
  bool any_solid = false;
  for (int skip = 0; skip < 5; ++skip) {
    std::array<Point3, 4> t;
    int k = 0;
    for (int i = 0; i < 5; ++i)
      if (i != skip) t[k++] = v[i];
    const Sign o = orient3d(t[0], t[1], t[2], t[3]);
    if (o == Sign::Zero) continue;
    any_solid = true;
    if (test(t, o)) return true;
  }
  return !any_solid;
}

}  // namespace exactvis::shadows
