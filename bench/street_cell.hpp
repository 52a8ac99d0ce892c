#pragma once
// The view cell the PVS benchmarks share (bench_pvs, bench_pvs_methods, bench_cone_layers): a street-level
// box near the scene's (-x, -y) corner, as in the region tests, so their rows are about the same cell.
#include "kernel/scene.hpp"
#include "region/convex_polygon_3.hpp"

namespace exactvis::bench {

// [lo.x + 1/4, lo.x + 3/2] x [lo.y + 1/4, lo.y + 3/2] x [1, 2] for the scene's bounding box lo (exact).
inline region::RationalBox3 street_cell(const Scene& scene) {
  const Box3 b = bounding_box(scene);
  return region::exact_box({{b.lo.x + 0.25, b.lo.y + 0.25, 1}, {b.lo.x + 1.5, b.lo.y + 1.5, 2}});
}

}  // namespace exactvis::bench
