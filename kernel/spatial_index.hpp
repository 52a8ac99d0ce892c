#pragma once
// Spatial index over a scene's triangles: a CGAL AABB tree (kept out of this header).
//
// Built once; queries are const and may run from several threads at once. Results are indices into
// Scene::triangles (not ids), sorted ascending. Queries are candidate filters: callers decide with exact
// predicates. The index is a cheap-to-copy value (copies share the immutable tree).
#include "kernel/scene.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace exactvis {

class SpatialIndex {
 public:
  SpatialIndex();  // empty index
  // Input: a scene (copied into the tree as double triangles; the scene may be destroyed afterwards).
  explicit SpatialIndex(const Scene& scene);

  // Every triangle whose axis-aligned bounding box meets the closed box `box` (exact comparisons of doubles).
  // An empty box (lo > hi on some axis) gives nothing.
  std::vector<std::int64_t> triangles_in_box(const Box3& box) const;

  // A superset of the triangles meeting the closed segment [a, b] (a == b: the point). Currently exactly
  // the triangles meeting it (CGAL's exactly evaluated Epick predicates), but callers must treat it as
  // candidates only.
  std::vector<std::int64_t> triangles_near_segment(const Point3& a, const Point3& b) const;

  std::int64_t size() const;  // number of triangles indexed

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace exactvis
