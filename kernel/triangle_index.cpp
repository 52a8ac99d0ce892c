#include "kernel/triangle_index.hpp"

#include "kernel/aabb_index.hpp"

namespace exactvis {

struct TriangleIndex::Impl {
  aabb::AabbIndex<aabb::K::Triangle_3> tree;
  explicit Impl(const std::vector<aabb::K::Triangle_3>& triangles) : tree(triangles) {}
};

namespace {
std::vector<aabb::K::Triangle_3> cgal_triangles(const Scene& scene) {
  std::vector<aabb::K::Triangle_3> out;
  out.reserve(scene.triangles.size());
  for (const auto& t : scene.triangles)
    out.emplace_back(aabb::cgal_point(scene.corner(t, 0)), aabb::cgal_point(scene.corner(t, 1)),
                     aabb::cgal_point(scene.corner(t, 2)));
  return out;
}
}  // namespace

TriangleIndex::TriangleIndex() : impl_(std::make_shared<Impl>(std::vector<aabb::K::Triangle_3>{})) {}

TriangleIndex::TriangleIndex(const Scene& scene) : impl_(std::make_shared<Impl>(cgal_triangles(scene))) {}

std::int64_t TriangleIndex::size() const { return static_cast<std::int64_t>(impl_->tree.size()); }

std::vector<std::int64_t> TriangleIndex::candidates_in_box(const Box3& box) const {
  return impl_->tree.bbox_overlapping(box);
}

std::vector<std::int64_t> TriangleIndex::triangles_meeting_box(const Box3& box) const {
  if (box.empty()) return {};
  return impl_->tree.meeting(aabb::cgal_bbox(box));
}

std::vector<std::int64_t> TriangleIndex::triangles_meeting_triangle(const Point3& a, const Point3& b,
                                                                    const Point3& c) const {
  return impl_->tree.meeting(aabb::K::Triangle_3(aabb::cgal_point(a), aabb::cgal_point(b), aabb::cgal_point(c)));
}

std::vector<std::int64_t> TriangleIndex::triangles_meeting_segment(const Point3& a, const Point3& b) const {
  if (a == b) {
    // A degenerate segment is a point; CGAL's Segment_3 needs two distinct ends.
    std::vector<std::int64_t> out;
    const aabb::K::Point_3 p = aabb::cgal_point(a);
    for (std::int64_t i : candidates_in_box({a, a}))
      if (impl_->tree.item(i).has_on(p)) out.push_back(i);
    return out;
  }
  return impl_->tree.meeting(aabb::K::Segment_3(aabb::cgal_point(a), aabb::cgal_point(b)));
}

}  // namespace exactvis
