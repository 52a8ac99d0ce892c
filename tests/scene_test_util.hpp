#pragma once
// A Scene from vertex and triangle lists, as the test suites build their hand-made models (any suite).
// Unlike io's scene_from_arrays it keeps every triangle (degenerate ones too) in one object.
#include "kernel/scene.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace exactvis::scene_test {

// Input: vertices, triangles as vertex indices. Output: one object "test", triangle id = list order,
// faces_read = the number of triangles.
inline Scene make_scene(const std::vector<Point3>& v, const std::vector<std::array<int, 3>>& t) {
  Scene s;
  s.vertices = v;
  for (std::size_t i = 0; i < t.size(); ++i) s.triangles.push_back({static_cast<std::int64_t>(i), t[i], 0});
  s.objects.push_back({"test"});
  s.faces_read = static_cast<std::int64_t>(t.size());
  return s;
}

}  // namespace exactvis::scene_test
