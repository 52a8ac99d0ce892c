#pragma once
// One .vtp file showing the exact check of another tool's PVS for one view cell (`exactvis validate --vtp`):
// the scene's triangles with cell arrays "id" (scene triangle id), "object", "status" (0 correctly hidden,
// 1 correctly visible, 2 false visible: listed but exactly hidden, 3 false invisible: missing but visible)
// and "kind" (0 triangle, 1 witness segment of a false invisible triangle, 2 face of the view cell box).
// The layout is write_visibility_vtp's (io/write_visibility_vtp.hpp) with an int "status" array.
#include "io/write_visibility_vtp.hpp"
#include "kernel/scene.hpp"
#include "region/convex_polygon_3.hpp"

#include <string>
#include <vector>

namespace exactvis {

inline constexpr int kStatusHidden = 0, kStatusVisible = 1, kStatusFalseVisible = 2, kStatusFalseInvisible = 3;

// Input: output path, scene, per-triangle status (parallel to scene.triangles, values above), witness
// segments (status 3 on their line cells), the cell (drawn as its 6 faces, corners rounded to doubles).
// Output: the file, written atomically (throws OutputError on failure, leaving nothing).
void write_pvs_check_vtp(const std::string& path, const Scene& scene, const std::vector<int>& status,
                         const std::vector<WitnessSegment>& witnesses, const region::RationalBox3& cell);

}  // namespace exactvis
