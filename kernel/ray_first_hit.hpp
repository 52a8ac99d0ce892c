#pragma once
// The first scene triangle hit by a ray with exact rational origin and direction (docs/theory.md section 6,
// "Maximal free segments"). Used to find the objects at both ends of an event line's maximal free segment.
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"
#include "kernel/vec3.hpp"

namespace exactvis {

struct RayHit {
  int triangle = -1;  // index into Scene::triangles, or -1 when the ray leaves the scene without a hit
  Exact s;            // ray parameter of the hit (origin + s * dir), s >= 0; the hit point is at s (or, for a
                      // triangle coplanar with the ray and containing the origin, immediately after it)
};

// Input: scene, its spatial index, its bounding box (bounding_box(scene), computed once by the caller),
// origin (inside or on that box), dir != 0.
// Output: the closed triangle met first by the open ray {origin + s dir : s > 0}; ties go to the lowest index.
// Exact; candidates come from candidates_in_box over 32 outward-rounded boxes covering the ray inside the box.
RayHit ray_first_hit(const Scene& scene, const TriangleIndex& index, const Box3& box, const Vec3<Exact>& origin,
                     const Vec3<Exact>& dir);

}  // namespace exactvis
