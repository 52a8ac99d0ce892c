#pragma once
// One .vtp file showing a from-region visibility result: the scene's triangles with cell arrays
// "id" (scene triangle id), "object", "visible" (1 visible, 0 hidden, -1 not queried) and "kind" (0), and the
// witness segments as line cells with "id" = the triangle they prove visible, "visible" = 1 and "kind" = 1.
#include "kernel/scene.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace exactvis {

struct WitnessSegment {
  std::int64_t triangle_id;
  Point3 p, q;  // double approximations of the exact witness, for display only
};

// Input: output path, scene, per-triangle state (parallel to scene.triangles: 1, 0 or -1), witnesses.
// Output: the file, written atomically (throws OutputError on failure, leaving nothing).
void write_visibility_vtp(const std::string& path, const Scene& scene, const std::vector<int>& state,
                          const std::vector<WitnessSegment>& witnesses);

}  // namespace exactvis
