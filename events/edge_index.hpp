#pragma once
// Candidate generator edges for EEE enumeration: a CGAL AABB tree over the scene's edges (segments), kept in
// the .cpp. Queries are exact and conservative (Epick's do_intersect predicates are exactly evaluated), so a
// query never drops an edge that meets the query region.
#include "events/scene_adjacency.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <memory>
#include <vector>

namespace exactvis {

class EdgeIndex {
 public:
  // Input: the scene and its adjacency; edge k of the index is adj.edges[k].
  EdgeIndex(const Scene& scene, const SceneAdjacency& adj);
  ~EdgeIndex();
  EdgeIndex(const EdgeIndex&) = delete;
  EdgeIndex& operator=(const EdgeIndex&) = delete;

  // Indices into adj.edges of all edges whose closed segment meets the closed tetrahedron (a, b, c, d)
  // (a non-degenerate tetrahedron: the four points not coplanar), in increasing order. Thread-safe.
  std::vector<int> edges_meeting_tetrahedron(const Point3& a, const Point3& b, const Point3& c,
                                             const Point3& d) const;
  // Indices of all edges whose closed segment meets the closed box (exact double comparisons), increasing.
  std::vector<int> edges_meeting_box(const Box3& box) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Exact: do the closed segment [p, q] and the closed tetrahedron (a, b, c, d) (not coplanar) meet?
bool segment_meets_tetrahedron(const Point3& p, const Point3& q, const Point3& a, const Point3& b,
                               const Point3& c, const Point3& d);

}  // namespace exactvis
