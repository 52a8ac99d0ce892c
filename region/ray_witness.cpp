#include "region/ray_witness.hpp"

#include "kernel/round_to_doubles.hpp"
#include "kernel/segment_triangle_intersection.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace exactvis::region {
namespace {

Point3 to_point(const RationalPoint3& p) { return {CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)}; }

}  // namespace

std::vector<std::int64_t> segment_candidates(const TriangleIndex& index, const RationalPoint3& p,
                                             const RationalPoint3& q, double piece_length) {
  const Point3 a = to_point(p), b = to_point(q);
  const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
  const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
  // The piece count only affects speed: the pieces' boxes cover the exact segment whatever it is.
  long pieces = 1;
  if (piece_length > 0 && std::isfinite(length / piece_length))
    pieces = std::clamp(static_cast<long>(std::ceil(length / piece_length)), 1L, 64L);
  std::vector<std::int64_t> out;
  RationalPoint3 from = p;
  for (long i = 1; i <= pieces; ++i) {
    const RationalPoint3 to = i == pieces ? q : p + (Exact(i) / Exact(pieces)) * (q - p);
    const std::vector<std::int64_t> part = index.candidates_in_box(enclosing_box({from, to}));
    out.insert(out.end(), part.begin(), part.end());
    from = to;
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool is_robust_cell_witness(const PvsContext& context, const RationalBox3& cell, std::int64_t target,
                            const Witness& w) {
  for (int k = 0; k < 3; ++k)
    if (!(cell.lo[k] < w.p[k] && w.p[k] < cell.hi[k])) return false;
  if (!in_triangle_relative_interior(w.q, triangle_points(context.scene(), target))) return false;
  for (const std::int64_t o : segment_candidates(context.index(), w.p, w.q, context.diagonal() / 32)) {
    if (o == target) continue;
    const auto t = triangle_points(context.scene(), o);
    if (segment_meets_closed_triangle(w.p, w.q, t[0], t[1], t[2])) return false;
  }
  return true;
}

std::optional<Witness> ray_witness(const PvsContext& context, const RationalBox3& cell, const Box3& cell_approx,
                                   std::int64_t target, int rays, std::mt19937_64& rng) {
  const Scene& scene = context.scene();
  const Polygon3 tri = [&] {
    const auto t = triangle_points(scene, target);
    return Polygon3{t[0], t[1], t[2]};
  }();
  const SceneTriangle& st = scene.triangles[target];
  const std::vector<Point3> tri_approx{scene.corner(st, 0), scene.corner(st, 1), scene.corner(st, 2)};
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::int64_t ignore[1] = {target};
  for (int r = 0; r < rays; ++r) {
    Point3 pd;
    for (int k = 0; k < 3; ++k) pd[k] = cell_approx.lo[k] + unit(rng) * (cell_approx.hi[k] - cell_approx.lo[k]);
    const std::vector<long> weights = random_weights(3, rng);
    const Point3 qd = weighted_point_approx(tri_approx, weights);
    const glm::vec3 origin(static_cast<float>(pd.x), static_cast<float>(pd.y), static_cast<float>(pd.z));
    const glm::vec3 dir(static_cast<float>(qd.x - pd.x), static_cast<float>(qd.y - pd.y), static_cast<float>(qd.z - pd.z));
    if (context.rays().occluded(origin, dir, 0.0f, 1.0f, ignore)) continue;
    // Embree saw a free ray: re-check the exact segment (p is the double sample, q the exact weighted point).
    const Witness w{to_rational(pd), weighted_point(tri, weights)};
    if (!is_robust_cell_witness(context, cell, target, w)) continue;
    const Witness rounded{w.p, round_to_doubles(w.q)};
    if (!(rounded.q == w.q) && is_robust_cell_witness(context, cell, target, rounded)) return rounded;
    return w;
  }
  return std::nullopt;
}

}  // namespace exactvis::region
