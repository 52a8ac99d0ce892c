#pragma once
// A spatial index over segments between scene vertices (the scene's edges, for EEE candidate generation):
// a CGAL AABB tree kept in the .cpp (shared boilerplate with kernel/triangle_index: kernel/aabb_index.hpp).
// Queries return exactly the closed segments meeting the closed query object (Epick's do_intersect
// predicates are exactly evaluated), so a query never drops an edge that meets the query region. Results
// are positions in the edge list given to the constructor, in increasing order. Built once; const queries
// are thread-safe; copies share the immutable tree.
#include "kernel/scene.hpp"

#include <array>
#include <memory>
#include <vector>

namespace exactvis {

class EdgeIndex {
 public:
  // Input: the scene and its edges as vertex-id pairs (e.g. SceneAdjacency::edges' v); edge k of the index
  // is edges[k].
  EdgeIndex(const Scene& scene, const std::vector<std::array<int, 2>>& edges);

  // Every edge whose closed segment meets the closed tetrahedron (a, b, c, d) (a non-degenerate
  // tetrahedron: the four points not coplanar). Exact.
  std::vector<int> edges_meeting_tetrahedron(const Point3& a, const Point3& b, const Point3& c,
                                             const Point3& d) const;
  // Every edge whose closed segment meets the closed box (exact). An empty box gives nothing.
  std::vector<int> edges_meeting_box(const Box3& box) const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace exactvis
