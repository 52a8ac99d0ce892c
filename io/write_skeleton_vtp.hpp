#pragma once
// The 3D visibility skeleton as VTK XML PolyData (.vtp) for ParaView (docs/cli.md "skeleton", --vtp):
// nodes as line cells (their spanned segments), arcs as ruled strips (the generator segments of
// `samples + 1` rational parameters across each arc, triangulated). Double coordinates, display only.
#include "io/write_skeleton_json.hpp"
#include "kernel/scene.hpp"
#include "skeleton/visibility_skeleton_3d.hpp"

#include <string>

namespace exactvis {

// Input: output path, the scene, its skeleton, the selection to write. Output: the file, written atomically,
// with cell arrays "element" (0 = node, 1 = arc), "kind" (node: ExtremalLineKind VV = 0, VEE, EEEE, FVE,
// FEE, VEF, EEEF, EEP, VEFF = 8; arc: 0 = EV, 1 = EEE), "index" (in the written lists, as in the JSON),
// "vertex" (first vertex generator or -1), "edge0".."edge7" (the vertex ids of up to four edges, -1 unused),
// "end0", "end1" (end triangle ids, -1 = none). Throws OutputError.
void write_skeleton_vtp(const std::string& path, const Scene& scene, const Skeleton3D& skeleton,
                        const SkeletonSelection& selection, int samples = 8);

}  // namespace exactvis
