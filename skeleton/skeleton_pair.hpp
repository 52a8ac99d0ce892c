#pragma once
// Queries on one pair of objects (or triangles) of the 3D visibility skeleton (docs/theory.md section 9,
// "Lazy build of one pair" and "Queries"): the lazy build of the pair's slice of Durand's table, and the
// blockers between the two.
#include "kernel/scene.hpp"
#include "skeleton/visibility_skeleton_3d.hpp"

#include <cstdint>
#include <vector>

namespace exactvis {

// One side of a pair: a scene object, or one triangle.
struct SkeletonPairSide {
  int object = -1;             // index into Scene::objects (used when triangle < 0)
  std::int64_t triangle = -1;  // a stable triangle id, or -1
};

// Whether the end triangle `end` (stable id, -1 = none) is on `side`.
bool on_side(const Scene& scene, std::int64_t end, const SkeletonPairSide& side);

// The nodes and arcs of `skeleton` whose two end objects are on a and b (either order), indices increasing.
SkeletonPairSlice pair_slice(const Scene& scene, const Skeleton3D& skeleton, const SkeletonPairSide& a,
                             const SkeletonPairSide& b);

// The lazy build: a skeleton holding exactly the pair's slice (nodes ending on a and b, arcs ending on a
// and b, and the end nodes of those arcs), with the scene's vertex ids, edge ids and triangle ids. Equal to
// that slice of build_skeleton_3d(scene) (same keys, arcs, parameters and end objects): a maximal free
// segment ending on a and b lies in the convex hull of the two, so the build runs on the sub-scene of the
// closed triangles meeting the bounding box of a and b (vertex ids compacted in order, which keeps every
// canonical order, and mapped back); EV pairs, and EV free intervals, no line of which can meet both a and b
// (a certificate of events/ev_pencil_filter) are not enumerated (they contribute nothing to the slice:
// docs/theory.md section 9). Cost: that restricted build on the sub-scene.
Skeleton3D build_pair_skeleton(const Scene& scene, const SkeletonPairSide& a, const SkeletonPairSide& b,
                               const SkeletonOptions& options = {});

// The blockers between a and b: the objects (indices into Scene::objects, increasing, a's and b's own
// excluded) owning a generator (vertex, edge, or face of the key; an arc's vertex and edges) of a node or an
// arc of the pair's slice, i.e. the occluders whose events bound the mutual visibility of a and b.
std::vector<int> pair_blockers(const Scene& scene, const Skeleton3D& skeleton, const SkeletonPairSlice& slice,
                               const SkeletonPairSide& a, const SkeletonPairSide& b);

}  // namespace exactvis
