#include "events/scene_adjacency.hpp"

#include <algorithm>
#include <tuple>

namespace exactvis {

int SceneAdjacency::edge_index(int a, int b) const {
  if (a > b) std::swap(a, b);
  auto it = std::lower_bound(edges.begin(), edges.end(), std::array<int, 2>{a, b},
                             [](const SceneEdge& e, const std::array<int, 2>& k) { return e.v < k; });
  if (it == edges.end() || it->v != std::array<int, 2>{a, b}) return -1;
  return static_cast<int>(it - edges.begin());
}

SceneAdjacency build_scene_adjacency(const Scene& scene) {
  SceneAdjacency adj;
  adj.vertex_triangles.resize(scene.vertices.size());
  std::vector<std::tuple<int, int, int>> half;  // (a, b, triangle) with a < b
  half.reserve(scene.triangles.size() * 3);
  for (int ti = 0; ti < static_cast<int>(scene.triangles.size()); ++ti) {
    const auto& t = scene.triangles[ti];
    for (int k = 0; k < 3; ++k) {
      adj.vertex_triangles[t.v[k]].push_back(ti);
      int a = t.v[k], b = t.v[(k + 1) % 3];
      if (a > b) std::swap(a, b);
      half.emplace_back(a, b, ti);
    }
  }
  std::sort(half.begin(), half.end());
  for (const auto& [a, b, ti] : half) {
    if (adj.edges.empty() || adj.edges.back().v != std::array<int, 2>{a, b}) adj.edges.push_back({{a, b}, {}});
    adj.edges.back().triangles.push_back(ti);
  }
  return adj;
}

EdgeIndex scene_edge_index(const Scene& scene, const SceneAdjacency& adj) {
  std::vector<std::array<int, 2>> pairs;
  pairs.reserve(adj.edges.size());
  for (const auto& e : adj.edges) pairs.push_back(e.v);
  return EdgeIndex(scene, pairs);
}

}  // namespace exactvis
