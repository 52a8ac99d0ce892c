#include "region/exterior_sampled.hpp"

#include "region/cell_visibility.hpp"
#include "region/exterior_witness.hpp"

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>

namespace exactvis::region {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Van der Corput radical inverse in base 2 (the second coordinate of the Hammersley point set).
double radical_inverse2(std::uint32_t i) {
  std::uint32_t b = i;
  b = (b << 16) | (b >> 16);
  b = ((b & 0x00ff00ffu) << 8) | ((b & 0xff00ff00u) >> 8);
  b = ((b & 0x0f0f0f0fu) << 4) | ((b & 0xf0f0f0f0u) >> 4);
  b = ((b & 0x33333333u) << 2) | ((b & 0xccccccccu) >> 2);
  b = ((b & 0x55555555u) << 1) | ((b & 0xaaaaaaaau) >> 1);
  return static_cast<double>(b) * (1.0 / 4294967296.0);
}

double frac(double x) { return x - std::floor(x); }

double unit(std::mt19937_64& rng) { return std::ldexp(static_cast<double>(rng() >> 11), -53); }

// The seed's mapping of (u, v) in the unit square to the unit sphere (uniform area).
glm::dvec3 sphere_point(double u, double v) {
  const double z = 1.0 - 2.0 * u;
  const double rho = 2.0 * std::sqrt(std::max(0.0, u - u * u));
  return {rho * std::cos(2 * kPi * v), rho * std::sin(2 * kPi * v), z};
}

glm::vec3 to_float(const glm::dvec3& v) { return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)}; }

}  // namespace

SampledExterior sampled_exterior_visibility(const Scene& scene, const FloatRayCaster& caster,
                                            const SampledExteriorOptions& options) {
  if (scene.triangles.empty()) throw std::invalid_argument("exterior visibility needs at least one triangle");
  if (options.views < 1) throw std::invalid_argument("sampled exterior visibility: views must be >= 1");
  if (options.resolution < 1) throw std::invalid_argument("sampled exterior visibility: resolution must be >= 1");
  if (options.mc_rays < 0) throw std::invalid_argument("sampled exterior visibility: mc_rays must be >= 0");
  check_thread_count(options.threads);
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = scene.triangles.size();
  auto flags = std::make_unique<std::atomic<unsigned char>[]>(n);  // 0 removed, 1 by views, 2 by rays
  for (std::size_t i = 0; i < n; ++i) flags[i].store(0, std::memory_order_relaxed);
  std::atomic<std::int64_t> rays{0};

  const Box3 b = bounding_box(scene);
  const glm::dvec3 lo(b.lo.x, b.lo.y, b.lo.z), hi(b.hi.x, b.hi.y, b.hi.z);
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const double bound_radius = std::max(0.5 * glm::length(hi - lo), 1e-300);
  const double camera_radius = std::max(1.5 * extent, 1.01 * bound_radius);
  const double tan_half = std::tan(std::asin(std::min(1.0, bound_radius / camera_radius)));
  std::mt19937_64 rng(mix_seed(options.seed, 0));
  const double rot_u = unit(rng), rot_v = unit(rng);
  const int R = options.resolution;

  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    // 1. multi test: one image per camera, a primary ray per pixel centre.
    tbb::parallel_for(0, options.views, [&](int view) {
      const double u = frac((view + 0.5) / options.views + rot_u);
      const double v = frac(radical_inverse2(static_cast<std::uint32_t>(view)) + rot_v);
      const glm::dvec3 eye = centre + camera_radius * sphere_point(u, v);
      const glm::dvec3 forward = glm::normalize(centre - eye);
      const glm::dvec3 helper = std::abs(forward.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
      const glm::dvec3 right = glm::normalize(glm::cross(forward, helper));
      const glm::dvec3 up = glm::cross(right, forward);
      const glm::vec3 origin = to_float(eye);
      for (int py = 0; py < R; ++py)
        for (int px = 0; px < R; ++px) {
          const double x = (2.0 * (px + 0.5) / R - 1.0) * tan_half;
          const double y = (2.0 * (py + 0.5) / R - 1.0) * tan_half;
          const FloatRayCaster::Hit hit = caster.first_hit(origin, to_float(forward + x * right + y * up), 0.0f,
                                                           std::numeric_limits<float>::infinity());
          if (hit.triangle_index >= 0) flags[static_cast<std::size_t>(hit.triangle_index)].store(1, std::memory_order_relaxed);
        }
      rays.fetch_add(static_cast<std::int64_t>(R) * R, std::memory_order_relaxed);
      if (options.on_view_done) options.on_view_done();
    });
    // 2. ray tracing test for the triangles the views did not see.
    if (options.mc_rays > 0)
      tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
        if (flags[i].load(std::memory_order_relaxed) != 0) return;
        const SceneTriangle& t = scene.triangles[i];
        const glm::dvec3 A(scene.corner(t, 0).x, scene.corner(t, 0).y, scene.corner(t, 0).z);
        const glm::dvec3 B(scene.corner(t, 1).x, scene.corner(t, 1).y, scene.corner(t, 1).z);
        const glm::dvec3 C(scene.corner(t, 2).x, scene.corner(t, 2).y, scene.corner(t, 2).z);
        std::mt19937_64 trng(mix_seed(options.seed, i + 1));
        const double ru = unit(trng), rv = unit(trng), du = unit(trng), dv = unit(trng);
        const std::int64_t ignore[1] = {static_cast<std::int64_t>(i)};
        std::int64_t cast = 0;
        for (int k = 0; k < options.mc_rays; ++k) {
          // Turk's mapping of a rotated Hammersley point to the triangle; directions from a second one.
          const double u = frac((k + 0.5) / options.mc_rays + ru), v = frac(radical_inverse2(static_cast<std::uint32_t>(k)) + rv);
          const double s = std::sqrt(u);
          const glm::dvec3 origin = (1 - s) * A + (1 - v) * s * B + v * s * C;
          const glm::dvec3 dir = sphere_point(frac(radical_inverse2(static_cast<std::uint32_t>(k) * 2654435761u) + du),
                                              frac((k + 0.5) / options.mc_rays + dv));
          ++cast;
          if (!caster.occluded(to_float(origin), to_float(dir), 0.0f, std::numeric_limits<float>::infinity(), ignore)) {
            flags[i].store(2, std::memory_order_relaxed);
            break;
          }
        }
        rays.fetch_add(cast, std::memory_order_relaxed);
      });
  });
  if (options.on_view_done) options.on_view_done();

  SampledExterior out;
  out.kept.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char f = flags[i].load(std::memory_order_relaxed);
    out.kept[i] = f != 0;
    out.kept_count += f != 0 ? 1 : 0;
    out.kept_by_views += f == 1 ? 1 : 0;
    out.kept_by_rays += f == 2 ? 1 : 0;
  }
  out.rays_cast = rays.load();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace exactvis::region
