#pragma once
// One .vtp file showing the exact check of another tool's PVS for one view cell (`exactvis validate --vtp`):
// the scene's triangles with cell arrays "id" (scene triangle id), "object", "status" (0 correctly hidden,
// 1 correctly visible, 2 false visible: listed but exactly hidden, 3 false invisible: missing but visible)
// and "kind" (0 triangle, 1 witness segment of a false invisible triangle, 2 face of the view cell box).
#include "kernel/scene.hpp"
#include "region/convex_polygon_3.hpp"

#include <string>
#include <vector>

namespace exactvis {

inline constexpr int kStatusHidden = 0, kStatusVisible = 1, kStatusFalseVisible = 2, kStatusFalseInvisible = 3;

struct StatusSegment {
  std::int64_t triangle_id;
  Point3 p, q;  // double approximations of an exact witness, for display only
};

// Input: output path, scene, per-triangle status (parallel to scene.triangles, values above), witness
// segments (status 3 on their line cells), the cell (drawn as its 6 faces, corners rounded to doubles).
// Output: the file, written atomically (throws OutputError on failure, leaving nothing).
void write_pvs_check_vtp(const std::string& path, const Scene& scene, const std::vector<int>& status,
                         const std::vector<StatusSegment>& witnesses, const region::RationalBox3& cell);

}  // namespace exactvis
