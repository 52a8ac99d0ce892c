#pragma once
// Models shared by the aspect test suites: hand-made polyhedra, random convex polytopes (the CGAL hull of
// random integer points: generation only, never an oracle) and the conversion to the oracles' triangles.
#include "kernel/scene.hpp"
#include "oracles/aspect_oracle.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <array>
#include <random>
#include <vector>

namespace exactvis::aspect_test {

inline Scene make_scene(const std::vector<Point3>& v, const std::vector<std::array<int, 3>>& t) {
  Scene s;
  s.vertices = v;
  for (std::size_t i = 0; i < t.size(); ++i) s.triangles.push_back({static_cast<std::int64_t>(i), t[i], 0});
  s.objects.push_back({"test"});
  s.faces_read = static_cast<std::int64_t>(t.size());
  return s;
}

// The box [x0,x1] x [y0,y1] x [z0,z1] as 12 outward triangles, appended (vertex ids continue).
inline void add_box(std::vector<Point3>& v, std::vector<std::array<int, 3>>& t, double x0, double y0, double z0,
                    double x1, double y1, double z1) {
  const int b = static_cast<int>(v.size());
  for (int k = 0; k < 8; ++k) v.push_back({k & 1 ? x1 : x0, k & 2 ? y1 : y0, k & 4 ? z1 : z0});
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : q) {
    t.push_back({b + f[0], b + f[1], b + f[2]});
    t.push_back({b + f[0], b + f[2], b + f[3]});
  }
}

inline Scene cube() {
  std::vector<Point3> v;
  std::vector<std::array<int, 3>> t;
  add_box(v, t, -1, -1, -1, 1, 1, 1);
  return make_scene(v, t);
}

inline Scene tetrahedron() {
  return make_scene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
}

// The CGAL convex hull of points (a triangulated closed convex model).
inline Scene hull_scene(const std::vector<Point3>& pts) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_3> p;
  for (const auto& q : pts) p.emplace_back(q.x, q.y, q.z);
  CGAL::Surface_mesh<K::Point_3> m;
  CGAL::convex_hull_3(p.begin(), p.end(), m);
  std::vector<Point3> v;
  std::vector<int> id(m.number_of_vertices() + m.number_of_removed_vertices(), -1);
  for (auto x : m.vertices()) {
    id[x.idx()] = static_cast<int>(v.size());
    v.push_back({m.point(x).x(), m.point(x).y(), m.point(x).z()});
  }
  std::vector<std::array<int, 3>> t;
  for (auto f : m.faces()) {
    std::vector<int> c;
    for (auto x : CGAL::vertices_around_face(m.halfedge(f), m)) c.push_back(id[x.idx()]);
    for (std::size_t k = 1; k + 1 < c.size(); ++k) t.push_back({c[0], c[k], c[k + 1]});
  }
  return make_scene(v, t);
}

// Hull of `n` random integer points in [-range, range]^3 near a sphere of radius `range`.
inline Scene random_convex(unsigned seed, int n, int range) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> c(-range, range);
  std::vector<Point3> pts;
  while (static_cast<int>(pts.size()) < n) {
    const int x = c(rng), y = c(rng), z = c(rng);
    const long r2 = long(x) * x + long(y) * y + long(z) * z;
    if (r2 > long(range) * range || r2 < long(range) * range * 6 / 10) continue;
    pts.push_back({double(x), double(y), double(z)});
  }
  return hull_scene(pts);
}

inline std::vector<oracle::OTriangle> oracle_model(const Scene& s) {
  std::vector<oracle::OTriangle> out;
  for (const auto& t : s.triangles) {
    oracle::OTriangle o;
    for (int k = 0; k < 3; ++k) o[k] = oracle::qvec(s.corner(t, k).x, s.corner(t, k).y, s.corner(t, k).z);
    out.push_back(o);
  }
  return out;
}

}  // namespace exactvis::aspect_test
