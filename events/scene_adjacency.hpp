#pragma once
// Index-based adjacency of a Scene: its edges and the triangles around each vertex and edge.
//
// Adjacency follows vertex *ids* only (docs/theory.md section 6): two triangles are adjacent iff they share
// vertex ids. Triangle soups may have edges with 1 or more than 2 triangles (non-manifold), which OpenMesh's
// TriMesh cannot represent, so the tables are plain vectors.
#include "kernel/edge_index.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace exactvis {

struct SceneEdge {
  std::array<int, 2> v{};            // vertex ids, v[0] < v[1]; the EV parameter t runs from v[0] to v[1]
  std::vector<int> triangles;        // indices into Scene::triangles of the triangles having this edge
};

struct SceneAdjacency {
  std::vector<SceneEdge> edges;                  // sorted by (v[0], v[1])
  std::vector<std::vector<int>> vertex_triangles;  // per vertex id: indices into Scene::triangles
  // Index into `edges` of edge {a, b} (any order), or -1.
  int edge_index(int a, int b) const;
};

// Builds the edge list and incidence tables of `scene` (O(n log n)).
SceneAdjacency build_scene_adjacency(const Scene& scene);

// The spatial index of adj.edges (edge k of the index is adj.edges[k]). O(n log n).
EdgeIndex scene_edge_index(const Scene& scene, const SceneAdjacency& adj);

}  // namespace exactvis
