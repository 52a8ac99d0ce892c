#include "region/exterior_witness.hpp"

#include "kernel/ray_blocker.hpp"
#include "kernel/segment_triangle_intersection.hpp"
#include "region/convex_polygon_3.hpp"

#include <cmath>

namespace exactvis::region {

bool coplanar_triangles(const Scene& scene, std::int64_t t, std::int64_t other) {
  const SceneTriangle& a = scene.triangles[static_cast<std::size_t>(t)];
  const SceneTriangle& b = scene.triangles[static_cast<std::size_t>(other)];
  for (int k = 0; k < 3; ++k)
    if (orient3d(scene.corner(a, 0), scene.corner(a, 1), scene.corner(a, 2), scene.corner(b, k)) != Sign::Zero)
      return false;
  return true;
}

ExteriorWitnessCheck check_exterior_witness(const Scene& scene, const TriangleIndex& index, const Box3& scene_box,
                                            std::int64_t triangle_index, const ExteriorWitness& w) {
  const auto tri = triangle_points(scene, triangle_index);
  if (!in_triangle_relative_interior(w.q, tri)) return ExteriorWitnessCheck::NotInRelativeInterior;
  const Vec3<Exact> n = cross(tri[1] - tri[0], tri[2] - tri[0]);
  if (CGAL::sign(dot(n, w.d)) == 0) return ExteriorWitnessCheck::ParallelToTriangle;
  for (const std::int64_t o : index.candidates_in_box(enclosing_box({w.q}))) {
    if (o == triangle_index) continue;
    const SceneTriangle& ot = scene.triangles[static_cast<std::size_t>(o)];
    if (point_in_closed_triangle(w.q, to_rational(scene.corner(ot, 0)), to_rational(scene.corner(ot, 1)),
                                 to_rational(scene.corner(ot, 2))) &&
        !coplanar_triangles(scene, triangle_index, o))
      return ExteriorWitnessCheck::OnOtherTriangle;
  }
  if (open_ray_blocker(scene, index, scene_box, w.q, w.d, triangle_index) >= 0) return ExteriorWitnessCheck::Blocked;
  return ExteriorWitnessCheck::Valid;
}

ExteriorWitness round_exterior_witness(const Scene& scene, const TriangleIndex& index, const Box3& scene_box,
                                       std::int64_t triangle_index, const ExteriorWitness& w) {
  ExteriorWitness best = w;
  const Vec3<Exact> d = round_to_doubles(w.d);
  if (!(d == w.d)) {
    const ExteriorWitness r{w.q, d};
    if (check_exterior_witness(scene, index, scene_box, triangle_index, r) == ExteriorWitnessCheck::Valid) best = r;
  }
  const RationalPoint3 q = round_to_doubles(w.q);
  if (!(q == w.q)) {
    const ExteriorWitness r{q, best.d};
    if (check_exterior_witness(scene, index, scene_box, triangle_index, r) == ExteriorWitnessCheck::Valid) best = r;
  }
  return best;
}

ExteriorWitness witness_from_segment(const RationalPoint3& p_on_box, const RationalPoint3& q) {
  return {q, p_on_box - q};
}

}  // namespace exactvis::region
