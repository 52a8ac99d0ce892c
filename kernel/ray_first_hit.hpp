#pragma once
// The first scene triangle hit by a ray with exact rational origin and direction (docs/theory.md section 6,
// "Maximal free segments"). Used to find the objects at both ends of an event line's maximal free segment.
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace exactvis {

struct RayHit {
  int triangle = -1;  // index into Scene::triangles, or -1 when the ray leaves the scene without a hit
  Exact s;            // ray parameter of the hit (origin + s * dir), s >= 0; the hit point is at s (or, for a
                      // triangle coplanar with the ray and containing the origin, immediately after it)
};

// What the caller knows by construction about the ray's origin: it lies on the line through scene vertices
// a and b (indices into Scene::vertices), e.g. it is A + t (B - A) for a rational t (a point of an event's
// edge). Every triangle through both vertices then holds the origin in its plane: the plane-offset sign is
// zero, which a floating-point filter can never decide, so ray_first_hit takes it from here instead of
// evaluating it exactly. a < 0: nothing known.
struct RayOriginOnEdgeLine {
  int a = -1, b = -1;
};

// Input: scene, its spatial index, its bounding box (bounding_box(scene), computed once by the caller),
// origin (inside or on that box), dir != 0, optionally the edge line the origin is known to lie on (the
// result is the same with or without it; wrong knowledge gives wrong answers).
// Output: the closed triangle met first by the open ray {origin + s dir : s > 0}; ties go to the lowest index.
// Exact; candidates come from candidates_in_box over 32 outward-rounded boxes covering the ray inside the box.
RayHit ray_first_hit(const Scene& scene, const TriangleIndex& index, const Box3& box, const Vec3<Exact>& origin,
                     const Vec3<Exact>& dir, const RayOriginOnEdgeLine& origin_on = {});

// A ray {o + s d : s > 0} known by interval enclosures of its coordinates and the exact signs of d's.
struct RayEnclosure {
  std::array<std::pair<double, double>, 3> origin, dir;  // [lo, hi] containing o_k and d_k
  std::array<Sign, 3> dir_sign{};                        // exact sign(d_k)
};

// Input: the spatial index, the scene box (bounding_box(scene)), a ray with o in or on the box, d != 0, and
// gap_sign(k, face) = the exact sign of face - o_k (called only when the enclosure of o_k cannot decide it).
// Output: the triangles (indices, unsorted, with repeats) whose boxes meet 32 boxes covering the part of the
// ray inside the scene box: a superset of the triangles the open ray meets. The exit parameter is bounded
// above by the smallest sup of (face_k - o_k) / d_k over the axes whose direction enclosure excludes 0 (a
// larger bound only adds candidates) and the piece ends o + s_i d are enclosed by interval arithmetic, so
// each piece box contains the exact segment [o + s_i d, o + s_i+1 d]; the ray leaves the box at once
// (exit <= 0: an empty vector) iff sign(face_k - o_k) != sign(d_k) on some axis with d_k != 0 (exact).
// std::nullopt: no direction enclosure excludes 0 (the caller needs another cover). No exact number is
// constructed; O(32 log n + k).
std::optional<std::vector<std::int64_t>> ray_cover_candidates(const TriangleIndex& index, const Box3& box,
                                                              const RayEnclosure& ray,
                                                              const std::function<Sign(int, double)>& gap_sign);

}  // namespace exactvis
