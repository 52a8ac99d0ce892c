#pragma once
// Small scenes shared by the events test suites: a scene from vertex/triangle lists, a random integer
// triangle soup, and the conversion to the independent oracle's mesh (tests/events/ev_oracle.hpp).
#include "kernel/predicates.hpp"
#include "kernel/scene.hpp"
#include "tests/events/ev_oracle.hpp"
#include "tests/scene_test_util.hpp"

#include <array>
#include <cstdint>
#include <algorithm>
#include <random>
#include <set>
#include <vector>

namespace exactvis::event_test {

using scene_test::make_scene;  // one object "test"; triangle ids = list order (tests/scene_test_util.hpp)

// `triangles` non-degenerate triangles with integer corners in [0, range]^3 (no shared vertex ids).
inline Scene random_soup(unsigned seed, int triangles, int range) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(0, range);
  std::vector<Point3> v;
  std::vector<std::array<int, 3>> t;
  while (static_cast<int>(t.size()) < triangles) {
    Point3 p[3];
    for (auto& q : p) q = {double(coord(rng)), double(coord(rng)), double(coord(rng))};
    if (collinear(p[0], p[1], p[2])) continue;
    const int b = static_cast<int>(v.size());
    v.insert(v.end(), {p[0], p[1], p[2]});
    t.push_back({b, b + 1, b + 2});
  }
  return make_scene(v, t);
}

// Up to `triangles` distinct non-degenerate triangles over a pool of `pool` random vertices with integer
// coordinates in [0, range]^3 (`tries` random picks): shared edges, open and non-manifold fans.
inline Scene shared_vertex_scene(unsigned seed, int pool, int range, std::size_t triangles, int tries) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(0, range);
  std::vector<Point3> v(pool);
  for (auto& p : v) p = {double(coord(rng)), double(coord(rng)), double(coord(rng))};
  std::uniform_int_distribution<int> pick(0, pool - 1);
  std::set<std::array<int, 3>> seen;
  std::vector<std::array<int, 3>> t;
  for (int k = 0; k < tries && t.size() < triangles; ++k) {
    std::array<int, 3> c{pick(rng), pick(rng), pick(rng)};
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;
    if (collinear(v[c[0]], v[c[1]], v[c[2]])) continue;
    auto key = c;
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second) continue;
    t.push_back(c);
  }
  return make_scene(v, t);
}

inline ev_oracle::Mesh to_oracle(const Scene& s) {
  ev_oracle::Mesh m;
  for (const auto& p : s.vertices) m.v.push_back({p.x, p.y, p.z});
  for (const auto& t : s.triangles) m.t.push_back(t.v);
  return m;
}

}  // namespace exactvis::event_test
