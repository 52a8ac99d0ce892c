#include "aspect/eee_crossing_point.hpp"

#include "kernel/predicates.hpp"

#include <algorithm>
#include <set>
#include <utility>

namespace exactvis {
namespace {

using R3 = Vec3<RootNumber>;

RootNumber rn(const Exact& x) { return RootNumber(x); }
R3 rv(const Vec3<Exact>& v) { return {rn(v.x), rn(v.y), rn(v.z)}; }
R3 sub(const R3& a, const R3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
R3 crs(const R3& a, const R3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
RootNumber dt(const R3& a, const R3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
bool zero(const R3& a) { return CGAL::sign(a.x) == 0 && CGAL::sign(a.y) == 0 && CGAL::sign(a.z) == 0; }

}  // namespace

std::string eee_line_meets_only_its_edges(const Scene& scene, const DirectionEventArc& arc, const RootNumber& t) {
  // f(t) from three exact values (quadratic in t), P(t) on E1.
  const Vec3<Exact> d0 = arc_direction(scene, arc, Exact(0)), d1 = arc_direction(scene, arc, Exact(1)),
                    d2 = arc_direction(scene, arc, Exact(2));
  const Vec3<Exact> c2 = Exact(1, 2) * (d2 - Exact(2) * d1 + d0), c1 = d1 - d0 - c2;
  const R3 d = {rn(d0.x) + t * rn(c1.x) + t * t * rn(c2.x), rn(d0.y) + t * rn(c1.y) + t * t * rn(c2.y),
                rn(d0.z) + t * rn(c1.z) + t * t * rn(c2.z)};
  const R3 a1 = rv(to_rational(scene.vertices[arc.edges[0][0]]));
  const R3 u1 = sub(rv(to_rational(scene.vertices[arc.edges[0][1]])), a1);
  const R3 p = {a1.x + t * u1.x, a1.y + t * u1.y, a1.z + t * u1.z};
  std::set<std::pair<int, int>> own;
  for (const auto& e : arc.edges) own.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  std::set<std::pair<int, int>> seen;
  for (const auto& tri : scene.triangles)
    for (int k = 0; k < 3; ++k) {
      const int x = std::min(tri.v[k], tri.v[(k + 1) % 3]), y = std::max(tri.v[k], tri.v[(k + 1) % 3]);
      if (own.count({x, y}) || !seen.insert({x, y}).second) continue;
      const R3 a = rv(to_rational(scene.vertices[x])), b = rv(to_rational(scene.vertices[y]));
      if (CGAL::sign(dt(sub(a, p), crs(d, sub(b, a)))) != 0) continue;  // skew: the line misses the edge
      // Coplanar: the line meets the closed segment iff a and b are not strictly on one side of it in their
      // common plane (normal n = d x (b - a)); parallel: iff the two lines coincide.
      const R3 n = crs(d, sub(b, a));
      const bool meets = zero(n) ? zero(crs(sub(a, p), d))
                                 : CGAL::sign(dt(crs(sub(a, p), d), n)) * CGAL::sign(dt(crs(sub(b, p), d), n)) <= 0;
      if (meets)
        return "its line at an irrational crossing with a free arc of a great circle also meets the edge " + std::to_string(x) +
               "-" + std::to_string(y);
    }
  return {};
}

std::array<double, 3> eee_direction_approx(const Scene& scene, const DirectionEventArc& arc, const RootNumber& t) {
  const double x = CGAL::to_double(t);
  const Vec3<Exact> d0 = arc_direction(scene, arc, Exact(0)), d1 = arc_direction(scene, arc, Exact(1)),
                    d2 = arc_direction(scene, arc, Exact(2));
  std::array<double, 3> out{};
  for (int k = 0; k < 3; ++k) {
    const double a = CGAL::to_double(d0[k]), b = CGAL::to_double(d1[k]), e = CGAL::to_double(d2[k]);
    const double c2 = 0.5 * (e - 2 * b + a), c1 = b - a - c2;
    out[k] = a + x * (c1 + x * c2);
  }
  return out;
}

}  // namespace exactvis
