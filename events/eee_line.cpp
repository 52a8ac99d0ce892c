#include "events/eee_line.hpp"

#include "kernel/predicates.hpp"

namespace exactvis {
namespace {

bool is_zero(const Vec3<Exact>& v) { return CGAL::is_zero(v.x) && CGAL::is_zero(v.y) && CGAL::is_zero(v.z); }

// Parameter s with point + s dir on the line (a, a + u), when the two lines meet in one point.
std::optional<Exact> meet_parameter(const Vec3<Exact>& point, const Vec3<Exact>& dir, const Vec3<Exact>& a,
                                    const Vec3<Exact>& u) {
  const Vec3<Exact> du = cross(dir, u), r = cross(a - point, u);
  for (int k = 0; k < 3; ++k)
    if (!CGAL::is_zero(du[k])) return r[k] / du[k];
  return std::nullopt;  // parallel
}

}  // namespace

std::optional<EeeLine> eee_line_at(const Scene& scene, const std::array<std::array<int, 2>, 3>& edges,
                                   const Exact& t) {
  std::array<Vec3<Exact>, 3> a, u;
  for (int k = 0; k < 3; ++k) {
    a[k] = to_rational(scene.vertices[edges[k][0]]);
    u[k] = to_rational(scene.vertices[edges[k][1]]) - a[k];
  }
  EeeLine line;
  line.point = a[0] + t * u[0];
  const Vec3<Exact> n2 = cross(a[1] - line.point, u[1]), n3 = cross(a[2] - line.point, u[2]);
  if (is_zero(n2) || is_zero(n3)) return std::nullopt;
  line.dir = cross(n2, n3);
  if (is_zero(line.dir)) return std::nullopt;
  line.s[0] = 0;
  for (int k = 1; k < 3; ++k) {
    const auto s = meet_parameter(line.point, line.dir, a[k], u[k]);
    if (!s) return std::nullopt;
    line.s[k] = *s;
  }
  return line;
}

}  // namespace exactvis
