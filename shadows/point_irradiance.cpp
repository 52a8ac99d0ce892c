#include "shadows/point_irradiance.hpp"

#include <cmath>
#include <numbers>

namespace exactvis::shadows {
namespace {

Point3 to_double(const RationalPoint3& v) {
  return {CGAL::to_double(v.x), CGAL::to_double(v.y), CGAL::to_double(v.z)};
}

}  // namespace

double lambert_loop_sum(const Point3& p, const Point3& n, const std::vector<RationalPoint3>& loop) {
  double sum = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Point3 ri = to_double(loop[i]) - p;
    const Point3 rj = to_double(loop[(i + 1) % loop.size()]) - p;
    const Point3 g = cross(ri, rj);
    const double gl = std::sqrt(dot(g, g));
    if (gl == 0) continue;  // an edge pointing at p (or a repeated vertex) contributes nothing
    const double theta = std::atan2(gl, dot(ri, rj));
    sum += theta * dot(n, g) / gl;
  }
  return sum;
}

double point_irradiance(const Scene& scene, const RationalPoint3& p, const Vec3<Exact>& receiver_normal,
                        const Backprojection& bp) {
  // Orient the receiver's normal towards the light's vertex centroid.
  RationalPoint3 c{0, 0, 0};
  int count = 0;
  for (const auto& part : bp.parts)
    for (const auto& v : region::triangle_points(scene, part.light_triangle)) c = c + v, ++count;
  c = Exact(1, count) * c;
  Vec3<Exact> nr = receiver_normal;
  if (dot(nr, c - p) < 0) nr = -nr;
  const region::Plane3 front{nr, dot(nr, p)};  // value >= 0 in front of the receiver
  const Point3 nd = to_double(nr);
  const double nl = std::sqrt(dot(nd, nd));
  const Point3 n{nd.x / nl, nd.y / nl, nd.z / nl};
  const Point3 pd = to_double(p);
  double total = 0;
  for (const auto& part : bp.parts) {
    double sum = 0;
    for (const auto& piece : part.pieces) {
      // Loops clipped one by one: the edges the clipping adds along the plane cancel between loops of one
      // region except on its true horizon, so the contour sum is that of the clipped region.
      sum += lambert_loop_sum(pd, n, region::clip_polygon(piece.outer, front));
      for (const auto& h : piece.holes) sum += lambert_loop_sum(pd, n, region::clip_polygon(h, front));
    }
    total += std::abs(sum);
  }
  return total / (2 * std::numbers::pi);
}

}  // namespace exactvis::shadows
