#include "kernel/edge_index.hpp"

#include "kernel/aabb_index.hpp"

namespace exactvis {

struct EdgeIndex::Impl {
  aabb::AabbIndex<aabb::K::Segment_3> tree;
  explicit Impl(const std::vector<aabb::K::Segment_3>& segments) : tree(segments) {}
};

namespace {
std::vector<aabb::K::Segment_3> cgal_segments(const Scene& scene, const std::vector<std::array<int, 2>>& edges) {
  std::vector<aabb::K::Segment_3> out;
  out.reserve(edges.size());
  for (const auto& e : edges)
    out.emplace_back(aabb::cgal_point(scene.vertices[e[0]]), aabb::cgal_point(scene.vertices[e[1]]));
  return out;
}
std::vector<int> as_int(const std::vector<std::int64_t>& ids) { return {ids.begin(), ids.end()}; }
}  // namespace

EdgeIndex::EdgeIndex(const Scene& scene, const std::vector<std::array<int, 2>>& edges)
    : impl_(std::make_shared<Impl>(cgal_segments(scene, edges))) {}

std::vector<int> EdgeIndex::edges_meeting_tetrahedron(const Point3& a, const Point3& b, const Point3& c,
                                                      const Point3& d) const {
  return as_int(impl_->tree.meeting(aabb::K::Tetrahedron_3(aabb::cgal_point(a), aabb::cgal_point(b),
                                                           aabb::cgal_point(c), aabb::cgal_point(d))));
}

std::vector<int> EdgeIndex::edges_meeting_box(const Box3& box) const {
  if (box.empty()) return {};
  return as_int(impl_->tree.meeting(aabb::K::Iso_cuboid_3(box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z)));
}

}  // namespace exactvis
