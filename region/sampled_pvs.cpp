#include "region/sampled_pvs.hpp"

#include "kernel/round_to_doubles.hpp"
#include "region/cell_visibility.hpp"
#include "region/ray_witness.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>
#include <unordered_set>

namespace exactvis::region {
namespace {

constexpr std::int64_t kChunk = 4096;  // rays per random stream (fixed: results do not depend on threads)

struct Confirmed {
  std::int64_t triangle;
  std::int64_t ray;  // global ray number of the first confirming ray
  Witness witness;
};

// The point a + u (b - a) + v (c - a) exactly, for Embree's barycentric coordinates taken as exact doubles;
// std::nullopt unless strictly inside (0 < u, 0 < v, u + v < 1).
std::optional<RationalPoint3> barycentric_point(const std::array<RationalPoint3, 3>& t, float u, float v) {
  if (!(u > 0 && v > 0 && static_cast<double>(u) + static_cast<double>(v) < 1)) return std::nullopt;
  const Exact eu(static_cast<double>(u)), ev(static_cast<double>(v));
  return t[0] + eu * (t[1] - t[0]) + ev * (t[2] - t[0]);
}

}  // namespace

CellPvs sampled_cell_pvs(const PvsContext& context, const RationalBox3& cell, const PvsOptions& options) {
  check_view_cell(cell);
  check_thread_count(options.threads);
  if (options.cell_rays < 0) throw std::invalid_argument("rays per cell must be >= 0");
  const auto start = std::chrono::steady_clock::now();
  const Scene& scene = context.scene();
  const Box3 approx = enclosing_box({cell.lo, cell.hi});
  const float far = static_cast<float>(4 * context.diagonal() + 4 * (approx.hi.x - approx.lo.x + approx.hi.y -
                                                                      approx.lo.y + approx.hi.z - approx.lo.z) + 1);
  const std::int64_t rays = options.cell_rays;
  const std::int64_t chunks = (rays + kChunk - 1) / kChunk;
  std::vector<std::vector<Confirmed>> found(static_cast<std::size_t>(chunks));
  auto run_chunk = [&](std::size_t c) {
    std::mt19937_64 rng(options.query.seed * 0x9E3779B97F4A7C15ull + 0x5A3D1ull * (c + 1));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::unordered_set<std::int64_t> seen;
    const std::int64_t first = static_cast<std::int64_t>(c) * kChunk, last = std::min(rays, first + kChunk);
    for (std::int64_t r = first; r < last; ++r) {
      Point3 o;
      for (int k = 0; k < 3; ++k) o[k] = approx.lo[k] + unit(rng) * (approx.hi[k] - approx.lo[k]);
      const double z = 2 * unit(rng) - 1, phi = 2 * M_PI * unit(rng), s = std::sqrt(std::max(0.0, 1 - z * z));
      const glm::vec3 origin(static_cast<float>(o.x), static_cast<float>(o.y), static_cast<float>(o.z));
      const glm::vec3 dir(static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)), static_cast<float>(z));
      const FloatRayCaster::Hit hit = context.rays().first_hit(origin, dir, 0.0f, far);
      if (hit.triangle_index < 0 || seen.count(hit.triangle_index)) continue;
      const auto tri = triangle_points(scene, hit.triangle_index);
      const auto q = barycentric_point(tri, hit.u, hit.v);
      if (!q) continue;
      // The ray starts at the float origin (exact as a point); the exact test decides.
      const Witness w{RationalPoint3{Exact(static_cast<double>(origin.x)), Exact(static_cast<double>(origin.y)),
                                     Exact(static_cast<double>(origin.z))},
                      *q};
      if (!is_robust_cell_witness(context, cell, hit.triangle_index, w)) continue;
      seen.insert(hit.triangle_index);
      const Witness rounded{w.p, round_to_doubles(w.q)};
      const bool use_rounded = options.query.round_witness && !(rounded.q == w.q) &&
                               is_robust_cell_witness(context, cell, hit.triangle_index, rounded);
      found[c].push_back({hit.triangle_index, r, use_rounded ? rounded : w});
    }
  };
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] { tbb::parallel_for(std::size_t(0), static_cast<std::size_t>(chunks), run_chunk); });

  std::vector<Confirmed> all;
  for (auto& f : found) all.insert(all.end(), f.begin(), f.end());
  std::sort(all.begin(), all.end(), [](const Confirmed& a, const Confirmed& b) {
    return a.triangle != b.triangle ? a.triangle < b.triangle : a.ray < b.ray;
  });
  CellPvs out;
  out.cell = cell;
  for (const Confirmed& c : all)
    if (out.visible.empty() || out.visible.back().index != c.triangle) out.visible.push_back({c.triangle, c.witness});
  out.stats.triangles = static_cast<std::int64_t>(scene.triangles.size());
  out.stats.visible = static_cast<std::int64_t>(out.visible.size());
  out.stats.accepted_by_rays = out.stats.visible;
  out.stats.rays_cast = rays;
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.on_progress) options.on_progress(out.stats.triangles);
  return out;
}

}  // namespace exactvis::region
