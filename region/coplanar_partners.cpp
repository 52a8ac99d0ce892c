#include "region/coplanar_partners.hpp"

#include "kernel/predicates.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <tuple>

namespace exactvis::region {
namespace {

using Key = std::tuple<double, double, double>;
Key key(const Point3& p) { return {p.x, p.y, p.z}; }

// a, c: the shared corners; b, d: the other corners of the two triangles (all four coplanar). True iff the
// quadrilateral a, b, c, d is strictly convex: b and d strictly on opposite sides of line ac and a and c
// strictly on opposite sides of line bd, in a coordinate projection in which a, b, c do not degenerate.
bool strictly_convex_quad(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  for (int axis = 0; axis < 3; ++axis) {
    const Sign abc = orient2d_projected(a, c, b, axis);
    if (abc == Sign::Zero) continue;  // this projection flattens the plane (or the triangle)
    const Sign acd = orient2d_projected(a, c, d, axis);
    const Sign bda = orient2d_projected(b, d, a, axis), bdc = orient2d_projected(b, d, c, axis);
    auto opposite = [](Sign x, Sign y) { return x != Sign::Zero && y != Sign::Zero && x != y; };
    return opposite(abc, acd) && opposite(bda, bdc);
  }
  return false;  // degenerate triangle
}

}  // namespace

std::vector<std::int64_t> coplanar_partners(const Scene& scene) {
  const std::size_t n = scene.triangles.size();
  std::vector<std::int64_t> partner(n, -1);
  // Undirected edges (the two corner keys, sorted) -> the triangles that have them.
  std::map<std::pair<Key, Key>, std::vector<std::int64_t>> edges;
  for (std::size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      Key u = key(scene.corner(scene.triangles[t], k)), v = key(scene.corner(scene.triangles[t], (k + 1) % 3));
      if (v < u) std::swap(u, v);
      edges[{u, v}].push_back(static_cast<std::int64_t>(t));
    }
  for (std::size_t t = 0; t < n; ++t) {
    if (partner[t] >= 0) continue;
    const SceneTriangle& st = scene.triangles[t];
    const std::array<Point3, 3> c{scene.corner(st, 0), scene.corner(st, 1), scene.corner(st, 2)};
    if (collinear(c[0], c[1], c[2])) continue;
    for (int k = 0; k < 3 && partner[t] < 0; ++k) {
      const Point3 &a = c[static_cast<std::size_t>(k)], &cc = c[static_cast<std::size_t>((k + 1) % 3)],
                   &b = c[static_cast<std::size_t>((k + 2) % 3)];
      Key u = key(a), v = key(cc);
      if (v < u) std::swap(u, v);
      const auto it = edges.find({u, v});
      if (it == edges.end()) continue;
      for (const std::int64_t o : it->second) {
        if (o == static_cast<std::int64_t>(t) || partner[static_cast<std::size_t>(o)] >= 0) continue;
        const SceneTriangle& so = scene.triangles[static_cast<std::size_t>(o)];
        // The corner of o that is not on the shared edge (o may repeat a corner: then it is degenerate).
        int other = -1, on_edge = 0;
        for (int j = 0; j < 3; ++j) {
          const Point3 p = scene.corner(so, j);
          if (p == a || p == cc) ++on_edge;
          else other = j;
        }
        if (on_edge != 2 || other < 0) continue;
        const Point3 d = scene.corner(so, other);
        if (orient3d(c[0], c[1], c[2], d) != Sign::Zero) continue;  // not coplanar
        if (!strictly_convex_quad(a, b, cc, d)) continue;
        partner[t] = o;
        partner[static_cast<std::size_t>(o)] = static_cast<std::int64_t>(t);
        break;
      }
    }
  }
  return partner;
}

}  // namespace exactvis::region
