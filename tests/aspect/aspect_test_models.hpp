#pragma once
// Models shared by the aspect test suites: hand-made polyhedra, random convex polytopes (aspect/random_convex_polytope:
// generation only, never an oracle) and the conversion to the oracles' triangles.
#include "aspect/random_convex_polytope.hpp"
#include "kernel/scene.hpp"
#include "oracles/aspect_oracle.hpp"


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

inline Scene hull_scene(const std::vector<Point3>& pts) { return convex_hull_scene(pts); }
inline Scene random_convex(unsigned seed, int n, int range) { return random_convex_polytope(seed, n, range); }

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
