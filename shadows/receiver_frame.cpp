#include "shadows/receiver_frame.hpp"

#include "region/convex_polygon_3.hpp"

#include <cmath>

namespace exactvis::shadows {

std::array<Exact, 2> ReceiverFrame::to_uv(const Vec3<Exact>& x) const {
  const auto p = chart.to_2d(x - origin), a = chart.to_2d(e1), b = chart.to_2d(e2);
  const Exact det = a[0] * b[1] - a[1] * b[0];
  return {(p[0] * b[1] - p[1] * b[0]) / det, (a[0] * p[1] - a[1] * p[0]) / det};
}

Vec3<Exact> ReceiverFrame::to_3d(const Exact& u, const Exact& v) const { return origin + u * e1 + v * e2; }

double ReceiverFrame::area_scale() const {
  const auto n = chart.normal;
  const double x = CGAL::to_double(n.x), y = CGAL::to_double(n.y), z = CGAL::to_double(n.z);
  return std::sqrt(x * x + y * y + z * z);
}

ReceiverFrame receiver_frame(const Scene& scene, std::int64_t triangle_index) {
  const auto t = region::triangle_points(scene, triangle_index);
  ReceiverFrame f;
  f.origin = t[0];
  f.e1 = t[1] - t[0];
  f.e2 = t[2] - t[0];
  f.chart = chart_of_triangle(t[0], t[1], t[2]);
  return f;
}

}  // namespace exactvis::shadows
