#include "region/exterior_witness.hpp"

#include "kernel/ray_blocker.hpp"
#include "kernel/segment_triangle_intersection.hpp"
#include "region/convex_polygon_3.hpp"

namespace exactvis::region {
namespace {

bool coplanar_with(const Scene& scene, const SceneTriangle& t, const SceneTriangle& o) {
  for (int k = 0; k < 3; ++k)
    if (orient3d(scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2), scene.corner(o, k)) != Sign::Zero)
      return false;
  return true;
}

Exact nearest_double(const Exact& x) { return Exact(CGAL::to_double(x)); }
RationalPoint3 nearest_doubles(const RationalPoint3& p) {
  return {nearest_double(p.x), nearest_double(p.y), nearest_double(p.z)};
}

}  // namespace

ExteriorWitnessCheck check_exterior_witness(const Scene& scene, const TriangleIndex& index, const Box3& scene_box,
                                            std::int64_t triangle_index, const ExteriorWitness& w) {
  const auto tri = triangle_points(scene, triangle_index);
  if (!in_triangle_relative_interior(w.q, tri)) return ExteriorWitnessCheck::NotInRelativeInterior;
  const Vec3<Exact> n = cross(tri[1] - tri[0], tri[2] - tri[0]);
  if (CGAL::sign(dot(n, w.d)) == 0) return ExteriorWitnessCheck::ParallelToTriangle;
  const SceneTriangle& t = scene.triangles[static_cast<std::size_t>(triangle_index)];
  for (const std::int64_t o : index.candidates_in_box(enclosing_box({w.q}))) {
    if (o == triangle_index) continue;
    const SceneTriangle& ot = scene.triangles[static_cast<std::size_t>(o)];
    if (point_in_closed_triangle(w.q, to_rational(scene.corner(ot, 0)), to_rational(scene.corner(ot, 1)),
                                 to_rational(scene.corner(ot, 2))) &&
        !coplanar_with(scene, t, ot))
      return ExteriorWitnessCheck::OnOtherTriangle;
  }
  if (open_ray_blocker(scene, index, scene_box, w.q, w.d, triangle_index) >= 0) return ExteriorWitnessCheck::Blocked;
  return ExteriorWitnessCheck::Valid;
}

ExteriorWitness round_exterior_witness(const Scene& scene, const TriangleIndex& index, const Box3& scene_box,
                                       std::int64_t triangle_index, const ExteriorWitness& w) {
  ExteriorWitness best = w;
  const Vec3<Exact> d = nearest_doubles(w.d);
  if (!(d == w.d)) {
    const ExteriorWitness r{w.q, d};
    if (check_exterior_witness(scene, index, scene_box, triangle_index, r) == ExteriorWitnessCheck::Valid) best = r;
  }
  const RationalPoint3 q = nearest_doubles(w.q);
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
