#pragma once
// Float ray casting with Embree: fast *proposals* of first hits, never an exact answer.
//
// The scene's triangles are copied as float32 triangles into an Embree BVH once. Queries cast one ray and
// return the index (into Scene::triangles) of the first triangle Embree reports, or -1. Float rounding can
// make Embree miss a triangle, report one behind another, or hit through a shared edge: callers use a hit
// only as a candidate that they then re-check with exact predicates (docs/theory.md §1: floats may accept
// only through an exact re-check). Triangles with a coordinate beyond float32's range are left out of the
// BVH (counted in `skipped()`); they can never be proposed.
//
// Thread-safe: any number of threads may query one caster concurrently.
#include "kernel/scene.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <span>

namespace exactvis {

class FloatRayCaster {
 public:
  // Builds the BVH over all triangles of `scene` (O(n log n); the scene may be destroyed afterwards).
  explicit FloatRayCaster(const Scene& scene);
  ~FloatRayCaster();
  FloatRayCaster(const FloatRayCaster&) = delete;
  FloatRayCaster& operator=(const FloatRayCaster&) = delete;

  struct Hit {
    std::int64_t triangle_index = -1;  // index into Scene::triangles, -1: no hit
    float t = 0;                       // ray parameter of the hit (origin + t * direction)
    float u = 0, v = 0;                // Embree's barycentric coordinates of the hit (corner 1 and corner 2)
  };

  // First hit of the ray origin + t * direction for t in [t_near, t_far], ignoring the triangle indices in
  // `ignore` (at most a few; e.g. the source and target of a query). direction need not be normalised.
  Hit first_hit(const glm::vec3& origin, const glm::vec3& direction, float t_near, float t_far,
                std::span<const std::int64_t> ignore = {}) const;

  // True iff Embree reports some triangle (not in `ignore`) on the ray for t in [t_near, t_far]; cheaper
  // than first_hit (any hit ends the traversal).
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float t_near, float t_far,
                std::span<const std::int64_t> ignore = {}) const;

  std::int64_t size() const;     // triangles in the BVH
  std::int64_t skipped() const;  // triangles left out (coordinates beyond float32)

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace exactvis
