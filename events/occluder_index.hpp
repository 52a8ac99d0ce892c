#pragma once
// Candidate occluders for a wedge: a CGAL AABB tree over the scene's triangles (CGAL stays in the .cpp).
// The query is conservative and exact: every triangle meeting the closed query triangle is returned
// (Epick's do_intersect predicates are exact), so culling never changes a result.
#include "kernel/scene.hpp"

#include <memory>
#include <vector>

namespace exactvis {

class OccluderIndex {
 public:
  explicit OccluderIndex(const Scene& scene);
  ~OccluderIndex();
  OccluderIndex(const OccluderIndex&) = delete;
  OccluderIndex& operator=(const OccluderIndex&) = delete;
  // Indices into Scene::triangles of all triangles meeting the closed triangle (a, b, c) (not collinear),
  // in increasing order. Thread-safe.
  std::vector<int> triangles_meeting(const Point3& a, const Point3& b, const Point3& c) const;
  // Indices into Scene::triangles of all triangles meeting the closed box (lo <= hi componentwise), in
  // increasing order. Conservative and exact like triangles_meeting (the box corners are doubles). Thread-safe.
  std::vector<int> triangles_in_box(const Box3& box) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace exactvis
