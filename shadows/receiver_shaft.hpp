#pragma once
// The shaft of a receiver: the scene triangles that can hide light from some point of it (docs/theory.md
// section 11, "Per-receiver blocker restriction").
//
// A light point q is hidden from p only by a triangle meeting the segment [p, q]; with p in the receiver R
// and q in a light triangle L, that segment lies in the convex hull conv(L ∪ R) of six points, the shaft.
// A triangle not meeting it can hide nothing from any point of R, so the backprojections of R's points
// need only the triangles that meet it. The test is exact and conservative: the triangles meeting the box of
// L ∪ R (exact AABB query), minus those strictly separated from the hull by one of the hull's supporting
// planes through three of its six points or by the triangle's own plane (exact filtered orient3d on the
// input doubles). A kept triangle may still miss the hull (no edge-edge separating planes are tried); a
// dropped one provably misses it.
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"

#include <cstdint>
#include <vector>

namespace exactvis::shadows {

struct ReceiverShaft {
  std::int64_t receiver = -1;  // index into Scene::triangles
  // Per light triangle (in the order of `light`): indices into Scene::triangles of the triangles that may
  // meet conv(L ∪ R), increasing, with their bounding boxes (for the per-point box filter).
  std::vector<std::vector<std::int64_t>> candidates;
  std::vector<std::vector<Box3>> boxes;
  std::uint64_t box_candidates = 0;  // triangles meeting the boxes of L ∪ R, summed over light triangles
};

// Input: scene, its index, the light (indices into Scene::triangles), a receiver (index). Output: the
// shaft's candidate blockers per light triangle (the light triangles themselves included, except L in its
// own list). Exact (see above). Cost: one box query per light triangle and at most 21 plane tests of three
// orient3d each per triangle in the box.
ReceiverShaft receiver_shaft(const Scene& scene, const TriangleIndex& index, const std::vector<int>& light,
                             std::int64_t receiver);

}  // namespace exactvis::shadows
