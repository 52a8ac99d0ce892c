#pragma once
// Does an open cone K of Plücker space contain real lines (points of the Plücker quadric q(x) = d.m = 0)?
//
// Theorem used (docs/theory.md §5.3): for a non-empty open convex cone K, K meets the quadric iff q takes
// both a positive and a negative value on K, iff it does so on the closure of K. (Convexity gives a zero
// between a positive and a negative point; conversely a zero z in the open K cannot be a local extremum of q
// because the gradient of q at z != 0 is (m, d) != 0.) Points of K on the quadric with d = 0 ("lines at
// infinity") form a nowhere dense subset, so K then contains ordinary real lines, an open set of them.
//
// Deciding the two signs on the closure (a pointed polyhedral cone, rays r_i, normalised by h = sum of the
// constraints): in order, (1) lineality, (2) the signs of q at the rays, (3) the 2-dimensional cones of
// ray pairs, (4) the stationary points of q on every face (KKT): the extremum of q over the compact slice
// {h = 1} is attained in the relative interior of a face F of smallest dimension, where it is the unique
// solution of  x in span(F), S(x, y) = h(y) * const for y in span(F); faces where that system is singular
// hold no such minimal extremum. Steps (1)-(3) only shortcut (4).
#include "region/polyhedral_cone6.hpp"

#include <cstdint>

namespace exactvis::region {

struct RealLineTest {
  bool has_real_lines = false;
  // When has_real_lines: points of the closure of K with q > 0 and q < 0 (ConeVector6: the common case, a
  // ray of the cone, is a copy without GMP; to_gmp() gives the integers).
  ConeVector6 positive_point{};
  ConeVector6 negative_point{};
  // Which step decided (1 lineality, 2 rays, 3 pairs, 4 faces) and how many faces step 4 examined.
  int decided_by = 0;
  std::int64_t faces_examined = 0;
};

RealLineTest test_real_lines(const PolyhedralCone6& cone);

}  // namespace exactvis::region
