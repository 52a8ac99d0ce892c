#include "aspect/random_convex_polytope.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <random>

namespace exactvis {

Scene convex_hull_scene(const std::vector<Point3>& points) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_3> p;
  for (const auto& q : points) p.emplace_back(q.x, q.y, q.z);
  CGAL::Surface_mesh<K::Point_3> m;
  CGAL::convex_hull_3(p.begin(), p.end(), m);
  Scene s;
  std::vector<int> id(m.number_of_vertices() + m.number_of_removed_vertices(), -1);
  for (auto x : m.vertices()) {
    id[x.idx()] = static_cast<int>(s.vertices.size());
    s.vertices.push_back({m.point(x).x(), m.point(x).y(), m.point(x).z()});
  }
  for (auto f : m.faces()) {
    std::vector<int> c;
    for (auto x : CGAL::vertices_around_face(m.halfedge(f), m)) c.push_back(id[x.idx()]);
    for (std::size_t k = 1; k + 1 < c.size(); ++k)
      s.triangles.push_back({static_cast<std::int64_t>(s.triangles.size()), {c[0], c[k], c[k + 1]}, 0});
  }
  s.objects.push_back({"hull"});
  s.faces_read = static_cast<std::int64_t>(s.triangles.size());
  return s;
}

Scene random_convex_polytope(std::uint64_t seed, int points, int range) {
  std::mt19937_64 rng(seed);
  const std::uint64_t span = 2 * static_cast<std::uint64_t>(range) + 1;
  const auto coord = [&] { return static_cast<long>(rng() % span) - range; };
  std::vector<Point3> pts;
  const long r2max = long(range) * range, r2min = r2max * 6 / 10;
  while (static_cast<int>(pts.size()) < points) {
    const long x = coord(), y = coord(), z = coord();
    const long r2 = x * x + y * y + z * z;
    if (r2 > r2max || r2 < r2min) continue;
    pts.push_back({double(x), double(y), double(z)});
  }
  return convex_hull_scene(pts);
}

}  // namespace exactvis
