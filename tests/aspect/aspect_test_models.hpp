#pragma once
// Models shared by the aspect test suites: hand-made polyhedra, random convex polytopes (aspect/random_convex_polytope:
// generation only, never an oracle) and the conversion to the oracles' triangles.
#include "aspect/aspect_graph_3d.hpp"
#include "aspect/random_convex_polytope.hpp"
#include "kernel/scene.hpp"
#include "oracles/aspect_oracle.hpp"
#include "tests/scene_test_util.hpp"

#include <array>
#include <random>
#include <vector>

namespace exactvis::aspect_test {

using scene_test::make_scene;  // tests/scene_test_util.hpp

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

// The L-shaped prism: the L [0,2]x[0,1] u [0,1]x[0,2] (corners 0..5 at z = 0, 6..11 at z = 1), height 1,
// outward triangles. Ids: 0-3 bottom, 4-7 top, 8-9 wall y=0, 10-11 wall x=2, 12-13 inner wall y=1,
// 14-15 inner wall x=1 (14: (1,1,0) (1,2,0) (1,2,1); 15: (1,1,0) (1,2,1) (1,1,1)), 16-17 wall y=2, 18-19 wall x=0.
inline Scene l_prism() {
  std::vector<Point3> v{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0},
                        {0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}, {1, 2, 1}, {0, 2, 1}};
  std::vector<std::array<int, 3>> t{{0, 2, 1}, {0, 3, 2},  {0, 5, 3},  {3, 5, 4},  {6, 7, 8},  {6, 8, 9},  {6, 9, 11},
                                    {9, 10, 11}, {0, 1, 7}, {0, 7, 6},  {1, 2, 8},  {1, 8, 7},  {2, 3, 9},  {2, 9, 8},
                                    {3, 4, 10}, {3, 10, 9}, {4, 5, 11}, {4, 11, 10}, {5, 0, 6}, {5, 6, 11}};
  return make_scene(v, t);
}

// Two unit cubes [0,1]^3 and [2,3]x[0,1]x[0,1] (triangles 0-11 and 12-23; add_box's face order -z, +z, -y,
// +y, -x, +x, two triangles each).
inline Scene two_boxes() {
  std::vector<Point3> v;
  std::vector<std::array<int, 3>> t;
  add_box(v, t, 0, 0, 0, 1, 1, 1);
  add_box(v, t, 2, 0, 0, 3, 1, 1);
  return make_scene(v, t);
}

// A terrain patch: heights h[i][j] over the grid (i, j), i, j = 0..k (vertex id (k + 1) i + j), two triangles
// per square, split from (i, j) to (i + 1, j + 1): {a, b, b + 1} and {a, b + 1, a + 1} with a = (i, j),
// b = (i + 1, j). An open surface (not a closed solid).
inline Scene terrain_grid(const std::vector<std::vector<double>>& h) {
  const int n = static_cast<int>(h.size());
  std::vector<Point3> v;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) v.push_back({double(i), double(j), h[i][j]});
  std::vector<std::array<int, 3>> t;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = n * i + j, b = a + n;
      t.push_back({a, b, b + 1});
      t.push_back({a, b + 1, a + 1});
    }
  return make_scene(v, t);
}

// Three unit cubes in a row along x with gaps of 1 ([2k, 2k+1] x [0,1] x [0,1], k = 0, 1, 2; triangles 12k to
// 12k + 11 in add_box's order): outside the class of §10.5.
inline Scene three_boxes() {
  std::vector<Point3> v;
  std::vector<std::array<int, 3>> t;
  for (int k = 0; k < 3; ++k) add_box(v, t, 2 * k, 0, 0, 2 * k + 1, 1, 1);
  return make_scene(v, t);
}

// A box with a notch along one edge: [0,3]x[0,2]x[0,2] minus [2,3]x[0,2]x[1,2] (an L-shaped section
// extruded along y, with a wide base). Ids: section triangles 0-7 (even y = 0, odd y = 2), then two per
// side wall in section order: 8-9 bottom z = 0, 10-11 x = 3, 12-13 notch floor z = 1, 14-15 notch wall
// x = 2, 16-17 top z = 2, 18-19 x = 0.
inline Scene notched_box() {
  // Section in the xz-plane: (0,0) (3,0) (3,1) (2,1) (2,2) (0,2), extruded from y = 0 to y = 2.
  const double sx[6] = {0, 3, 3, 2, 2, 0}, sz[6] = {0, 0, 1, 1, 2, 2};
  std::vector<Point3> v;
  for (int k = 0; k < 6; ++k) v.push_back({sx[k], 0, sz[k]});
  for (int k = 0; k < 6; ++k) v.push_back({sx[k], 2, sz[k]});
  std::vector<std::array<int, 3>> t;
  // Section faces: the hexagon fan-free triangulated (counter-clockwise in (x, z): outward -y at y = 0),
  // mirrored at y = 2.
  const int tri[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 5}, {3, 4, 5}};
  for (const auto& q : tri) {
    t.push_back({q[0], q[1], q[2]});
    t.push_back({6 + q[0], 6 + q[2], 6 + q[1]});
  }
  for (int k = 0; k < 6; ++k) {  // side walls
    const int a = k, b = (k + 1) % 6;
    t.push_back({a, 6 + a, 6 + b});
    t.push_back({a, 6 + b, b});
  }
  return make_scene(v, t);
}

// Two scenes as one (vertex and triangle ids of b after a's).
inline Scene combined(const Scene& a, const Scene& b) {
  std::vector<Point3> v = a.vertices;
  std::vector<std::array<int, 3>> t;
  for (const auto& x : a.triangles) t.push_back(x.v);
  const int off = static_cast<int>(v.size());
  v.insert(v.end(), b.vertices.begin(), b.vertices.end());
  for (const auto& x : b.triangles) t.push_back({x.v[0] + off, x.v[1] + off, x.v[2] + off});
  return make_scene(v, t);
}

inline Scene translated(Scene s, double dx, double dy, double dz) {
  for (auto& p : s.vertices) p = {p.x + dx, p.y + dy, p.z + dz};
  return s;
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

// The number of regions of dimension 0, 1 and 2 (orthographic and plane graphs).
inline std::array<int, 3> per_dimension(const AspectGraph3& g) {
  std::array<int, 3> d{0, 0, 0};
  for (const auto& r : g.regions) ++d[r.dimension];
  return d;
}

}  // namespace exactvis::aspect_test
