#include "shadows/light_plane_2d.hpp"

#include <cmath>

namespace exactvis::shadows {

std::array<Exact, 2> PlaneChart::to_2d(const Vec3<Exact>& x) const {
  const Exact& a = x[(axis + 1) % 3];
  const Exact& b = x[(axis + 2) % 3];
  if (swapped) return {b, a};
  return {a, b};
}

Vec3<Exact> PlaneChart::to_3d(const Exact& a0, const Exact& b0) const {
  const Exact& a = swapped ? b0 : a0;
  const Exact& b = swapped ? a0 : b0;
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  Vec3<Exact> x;
  x[i] = a;
  x[j] = b;
  x[axis] = (offset - normal[i] * a - normal[j] * b) / normal[axis];
  return x;
}

double PlaneChart::area_scale() const {
  const double nx = CGAL::to_double(normal.x), ny = CGAL::to_double(normal.y), nz = CGAL::to_double(normal.z);
  return std::sqrt(nx * nx + ny * ny + nz * nz) / std::abs(CGAL::to_double(normal[axis]));
}

PlaneChart chart_of_triangle(const Vec3<Exact>& a, const Vec3<Exact>& b, const Vec3<Exact>& c) {
  PlaneChart ch;
  ch.normal = cross(b - a, c - a);
  ch.offset = dot(ch.normal, a);
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (CGAL::abs(ch.normal[i]) > CGAL::abs(ch.normal[k])) k = i;
  ch.axis = k;
  ch.swapped = ch.normal[k] < 0;
  return ch;
}

}  // namespace exactvis::shadows
