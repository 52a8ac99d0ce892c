#pragma once
// The spatial index over a scene's triangles: a CGAL AABB tree (kept out of this header), the one index
// every module queries (events' occluder candidates, ray casting, from-region candidates).
//
// Results are indices into Scene::triangles (not ids), in increasing order. The query names say what they
// return:
//   - candidates_in_box: triangles whose axis-aligned bounding box meets the box (a candidate filter; the
//     caller decides with exact predicates);
//   - triangles_meeting_*: exactly the closed triangles that meet the closed query object (CGAL's Epick
//     do_intersect predicates are exactly evaluated on the input doubles), so culling with them never
//     changes a result.
// Built once; every query is const and may run from several threads at once. The index is a cheap-to-copy
// value (copies share the immutable tree). Cost: O(n log n) to build, O(log n + k) per query for k results.
#include "kernel/scene.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace exactvis {

class TriangleIndex {
 public:
  TriangleIndex();  // empty index
  // Input: a scene (copied into the tree as double triangles; the scene may be destroyed afterwards).
  explicit TriangleIndex(const Scene& scene);

  // Every triangle whose axis-aligned bounding box meets the closed box `box` (exact comparisons of doubles).
  // An empty box (lo > hi on some axis) gives nothing.
  std::vector<std::int64_t> candidates_in_box(const Box3& box) const;

  // Every closed triangle meeting the closed box (exact). An empty box gives nothing.
  std::vector<std::int64_t> triangles_meeting_box(const Box3& box) const;

  // Every closed triangle meeting the closed triangle (a, b, c) (a, b, c not collinear). Exact.
  std::vector<std::int64_t> triangles_meeting_triangle(const Point3& a, const Point3& b, const Point3& c) const;

  // Every closed triangle meeting the closed segment [a, b] (a == b: the point). Exact.
  std::vector<std::int64_t> triangles_meeting_segment(const Point3& a, const Point3& b) const;

  std::int64_t size() const;  // number of triangles indexed

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace exactvis
