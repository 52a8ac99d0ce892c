#pragma once
// The sampling pipeline of seed 003 (a global PVS for CAD models), GPU-free with Embree, so that its misses
// can be measured against the exact answer (region/exterior_visibility.hpp). It only ever uses float rays,
// with no exact confirmation: exactly what the pipeline does, not an exact method.
//   1. multi test: `views` cameras on a sphere of radius 1.5 x the largest extent of the model's bounding
//      box around its centre (the seed's mapping of a 2D low-discrepancy point set (Hammersley) to the sphere),
//      each looking at the centre with a square image of `resolution`^2 pixels fitted around the model's
//      bounding sphere; the first triangle Embree hits through each pixel centre is kept;
//   2. ray tracing test: for each triangle not yet kept, `mc_rays` rays from points of the triangle (Turk's
//      mapping of a 2D point set) in directions covering the full sphere; a ray Embree sees escape keeps it.
// Everything else is removed. Kept triangles may be hidden (float rays through shared edges) and removed
// ones may be visible (through gaps narrower than the sampling): `exactvis exterior --compare sampled`.
#include "kernel/float_ray_caster.hpp"
#include "kernel/scene.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace exactvis::region {

struct SampledExteriorOptions {
  int views = 256;          // cameras of the multi test (>= 1)
  int resolution = 256;     // pixels per image side (>= 1)
  int mc_rays = 64;         // rays per remaining triangle in the ray tracing test (0 skips it)
  std::uint64_t seed = 1;   // randomises the point sets (Cranley-Patterson rotation)
  int threads = 0;          // 0 = all cores
  std::function<void()> on_view_done;  // after each view and once after the ray tracing test (views + 1 calls)
};

struct SampledExterior {
  std::vector<bool> kept;            // parallel to Scene::triangles
  std::int64_t kept_count = 0;
  std::int64_t kept_by_views = 0;    // kept by the multi test
  std::int64_t kept_by_rays = 0;     // kept by the ray tracing test
  std::int64_t rays_cast = 0;
  double seconds = 0;                // wall-clock time of both tests (the BVH not included)
};

// Input: a non-empty scene, an Embree caster built over it, options. Output: the sampler's decision per
// triangle. Deterministic for a given seed whatever the thread count. Throws std::invalid_argument for
// options out of range. Cost: views * resolution^2 + (remaining triangles) * mc_rays Embree rays.
SampledExterior sampled_exterior_visibility(const Scene& scene, const FloatRayCaster& caster,
                                            const SampledExteriorOptions& options = {});

}  // namespace exactvis::region
