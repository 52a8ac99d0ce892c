#pragma once
// Exact tests of a ray against a scene's closed triangles: which triangles a ray with exact rational origin
// and direction can meet (candidates along it), and whether its open part {origin + s dir : s > 0} meets
// any closed triangle at all (a blocker), with an early exit at the first one found.
//
// Unlike ray_first_hit (the nearest hit, its parameter constructed exactly), these are "any hit" tests made
// of predicates only (kernel/segment_triangle_intersection.hpp): the ray is cut where it leaves a box just
// larger than the scene's, which no triangle reaches, so the open ray meets a triangle iff the open segment
// from the origin to that point does. Used to re-check proposed escaping rays (region/exterior_*).
#include "kernel/predicates.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace exactvis {

// The closed ray from `origin` along `dir`, cut to the scene: `near` = origin + s_near dir is where it enters
// the closed scene box (the origin itself when inside), `far` = origin + s_far dir lies outside the closed
// scene box, and so does every point of the ray beyond it. `empty` when the ray never meets the closed scene
// box at a parameter s >= 0 (then nothing of the scene is on it).
struct RaySpan {
  bool empty = true;
  RationalPoint3 origin, near, far;
  Vec3<Exact> dir;
};

// Input: the closed box of the scene (bounding_box(scene)), origin, dir != 0 (throws std::invalid_argument
// for dir = 0). Output: the span (exact). Cost: O(1) rational operations.
RaySpan ray_span(const Box3& scene_box, const RationalPoint3& origin, const Vec3<Exact>& dir);

// Every triangle (index into Scene::triangles) whose bounding box meets the span's segment [near, far],
// visited piece by piece from the origin outwards: the segment is halved
// while a piece's box has more than 16 candidates (at most 12 times), and `visit(index)` is called once per
// candidate, in order of the first piece that reaches it. Stops as soon as visit returns false. Outward-
// rounded boxes: no triangle meeting the segment is ever left out. Cost: O(pieces * log n + candidates).
void visit_ray_candidates(const TriangleIndex& index, const RaySpan& span,
                          const std::function<bool(std::int64_t)>& visit);

// Input: scene, its index, bounding_box(scene), origin, dir != 0, and a triangle index to skip (-1: none).
// Output: the index of a closed triangle other than `skip` that meets the open ray {origin + s dir : s > 0},
// or -1 when there is none (the ray escapes to infinity). The first blocker found along the ray is returned
// (not necessarily the nearest). Exact: interval arithmetic discards the candidates it can, the others are
// decided by open_segment_meets_closed_triangle on exact rationals. Thread-safe.
std::int64_t open_ray_blocker(const Scene& scene, const TriangleIndex& index, const Box3& scene_box,
                              const RationalPoint3& origin, const Vec3<Exact>& dir, std::int64_t skip = -1);

}  // namespace exactvis
