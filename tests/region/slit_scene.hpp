#pragma once
// The slit scene of the `visible` and `validate` CLI tests: target 0 (x = 10) behind a wall x = 5 of two
// rectangles with a gap 1e-9 wide at y = 0, target 1 (x = 10, y in [5, 7]) behind the wall where there is no
// gap. The OBJ text, and its triangles as the oracle's rationals.
#include "oracles/visibility_oracle.hpp"

#include <vector>

namespace region_test_slit {

inline constexpr const char* kSlitObj =
    "v 10 -1 -1\nv 10 1 -1\nv 10 0 1\n"                         // 1-3 target (id 0)
    "v 10 5 -1\nv 10 7 -1\nv 10 6 1\n"                          // 4-6 hidden target (id 1)
    "v 5 -10 -10\nv 5 -5e-10 -10\nv 5 -5e-10 10\nv 5 -10 10\n"  // 7-10 left wall
    "v 5 5e-10 -10\nv 5 10 -10\nv 5 10 10\nv 5 5e-10 10\n"      // 11-14 right wall
    "f 1 2 3\nf 4 5 6\nf 7 8 9 10\nf 11 12 13 14\n";

// kSlitObj fan-triangulated from each face's first vertex (ids 0, 1, 2-3, 4-5), as exactvis loads it.
inline std::vector<oracle::Triangle> slit_scene() {
  auto v = [](double x, double y, double z) { return oracle::qvec(x, y, z); };
  return {{v(10, -1, -1), v(10, 1, -1), v(10, 0, 1)},
          {v(10, 5, -1), v(10, 7, -1), v(10, 6, 1)},
          {v(5, -10, -10), v(5, -5e-10, -10), v(5, -5e-10, 10)},
          {v(5, -10, -10), v(5, -5e-10, 10), v(5, -10, 10)},
          {v(5, 5e-10, -10), v(5, 10, -10), v(5, 10, 10)},
          {v(5, 5e-10, -10), v(5, 10, 10), v(5, 5e-10, 10)}};
}

}  // namespace region_test_slit
