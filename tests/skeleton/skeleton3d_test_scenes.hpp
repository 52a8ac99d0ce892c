#pragma once
// Small 3D scenes for the visibility skeleton tests, and their conversion to the independent oracle's mesh
// (tests/oracles/skeleton_oracle.hpp).
#include "kernel/predicates.hpp"
#include "kernel/scene.hpp"
#include "oracles/skeleton_oracle.hpp"

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace exactvis::skeleton_test {

// Appends a closed box [lo, hi] (12 triangles, outward orientation) as a new object.
inline void add_box(Scene& s, const Point3& lo, const Point3& hi, const std::string& name) {
  const int b = static_cast<int>(s.vertices.size());
  for (int k = 0; k < 8; ++k)
    s.vertices.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const int obj = static_cast<int>(s.objects.size());
  s.objects.push_back({name});
  for (const auto& q : quads) {
    s.triangles.push_back({s.faces_read++, {b + q[0], b + q[1], b + q[2]}, obj});
    s.triangles.push_back({s.faces_read++, {b + q[0], b + q[2], b + q[3]}, obj});
  }
}

// Appends a closed tetrahedron (4 triangles sharing 6 edges) as a new object; corners must not be coplanar.
inline void add_tetrahedron(Scene& s, const std::array<Point3, 4>& p, const std::string& name) {
  const int b = static_cast<int>(s.vertices.size());
  for (const auto& q : p) s.vertices.push_back(q);
  const int obj = static_cast<int>(s.objects.size());
  s.objects.push_back({name});
  const int faces[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}};
  for (const auto& f : faces) s.triangles.push_back({s.faces_read++, {b + f[0], b + f[1], b + f[2]}, obj});
}

// `n` random triangles with integer corners in [0, range]^3, each its own object "t<k>".
inline Scene random_soup(unsigned seed, int n, int range) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> c(0, range);
  Scene s;
  while (static_cast<int>(s.triangles.size()) < n) {
    Point3 p[3];
    for (auto& q : p) q = {double(c(rng)), double(c(rng)), double(c(rng))};
    if (collinear(p[0], p[1], p[2])) continue;
    const int b = static_cast<int>(s.vertices.size());
    s.vertices.insert(s.vertices.end(), {p[0], p[1], p[2]});
    s.objects.push_back({"t" + std::to_string(s.triangles.size())});
    s.triangles.push_back({s.faces_read++, {b, b + 1, b + 2}, static_cast<int>(s.objects.size()) - 1});
  }
  return s;
}

// `k` random tetrahedra (closed meshes with shared edges), corners in [0, range]^3.
inline Scene random_tetrahedra(unsigned seed, int k, int range) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> c(0, range);
  Scene s;
  while (static_cast<int>(s.objects.size()) < k) {
    std::array<Point3, 4> p;
    for (auto& q : p) q = {double(c(rng)), double(c(rng)), double(c(rng))};
    if (orient3d(p[0], p[1], p[2], p[3]) == Sign::Zero) continue;
    if (orient3d(p[0], p[1], p[2], p[3]) == Sign::Negative) std::swap(p[2], p[3]);
    add_tetrahedron(s, p, "tet" + std::to_string(s.objects.size()));
  }
  return s;
}

inline skeleton_oracle::Mesh to_oracle(const Scene& s) {
  skeleton_oracle::Mesh m;
  for (const auto& p : s.vertices) m.v.push_back({mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)});
  for (const auto& t : s.triangles) m.t.push_back(t.v);
  return m;
}

}  // namespace exactvis::skeleton_test
