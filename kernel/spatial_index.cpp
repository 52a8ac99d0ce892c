#include "kernel/spatial_index.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>

namespace exactvis {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// AABB primitive: a scene triangle (as a CGAL triangle of the exact input doubles) and its index.
struct TrianglePrimitive {
  using Id = std::int64_t;
  using Point = K::Point_3;
  using Datum = K::Triangle_3;
  Id index = -1;
  Datum triangle;

  TrianglePrimitive() = default;
  template <class Iterator>
  explicit TrianglePrimitive(Iterator it) : index(it->first), triangle(it->second) {}
  Id id() const { return index; }
  const Datum& datum() const { return triangle; }
  Point reference_point() const { return triangle.vertex(0); }
};

using Traits = CGAL::AABB_traits<K, TrianglePrimitive>;
using Tree = CGAL::AABB_tree<Traits>;

K::Point_3 cgal_point(const Point3& p) { return {p.x, p.y, p.z}; }

// Traversal for "bounding box meets the query box": descend into nodes whose box meets it, report
// primitives whose own bounding box meets it. Bbox_3 comparisons are plain comparisons of the doubles.
struct BoxOverlapTraversal {
  std::vector<std::int64_t>* out;
  bool go_further() const { return true; }
  void intersection(const CGAL::Bbox_3& q, const TrianglePrimitive& p) {
    if (CGAL::do_overlap(q, p.triangle.bbox())) out->push_back(p.index);
  }
  template <class Node>
  bool do_intersect(const CGAL::Bbox_3& q, const Node& node) const {
    return CGAL::do_overlap(q, node.bbox());
  }
};

}  // namespace

struct SpatialIndex::Impl {
  Tree tree;
  std::vector<K::Triangle_3> triangles;  // by index (the tree reorders its primitives)
  std::int64_t count = 0;
};

SpatialIndex::SpatialIndex() : impl_(std::make_shared<Impl>()) {}

SpatialIndex::SpatialIndex(const Scene& scene) {
  auto impl = std::make_shared<Impl>();
  std::vector<std::pair<std::int64_t, K::Triangle_3>> items;
  items.reserve(scene.triangles.size());
  for (size_t i = 0; i < scene.triangles.size(); ++i) {
    const auto& t = scene.triangles[i];
    items.emplace_back(static_cast<std::int64_t>(i), K::Triangle_3(cgal_point(scene.corner(t, 0)),
                                                                   cgal_point(scene.corner(t, 1)),
                                                                   cgal_point(scene.corner(t, 2))));
  }
  impl->count = static_cast<std::int64_t>(items.size());
  impl->triangles.reserve(items.size());
  for (const auto& it : items) impl->triangles.push_back(it.second);
  if (!items.empty()) {
    impl->tree.insert(items.begin(), items.end());
    impl->tree.build();  // build now, so that later const queries never modify the tree (thread safety)
  }
  impl_ = std::move(impl);
}

std::int64_t SpatialIndex::size() const { return impl_->count; }

std::vector<std::int64_t> SpatialIndex::triangles_in_box(const Box3& box) const {
  std::vector<std::int64_t> out;
  if (box.empty() || impl_->count == 0) return out;
  const CGAL::Bbox_3 q(box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z);
  if (impl_->count == 1) {  // CGAL's traversal needs at least two primitives
    if (CGAL::do_overlap(q, impl_->triangles[0].bbox())) out.push_back(0);
    return out;
  }
  BoxOverlapTraversal traversal{&out};
  impl_->tree.traversal(q, traversal);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::int64_t> SpatialIndex::triangles_near_segment(const Point3& a, const Point3& b) const {
  std::vector<std::int64_t> out;
  if (impl_->count == 0) return out;
  if (a == b) {
    // A degenerate segment is a point; CGAL's Segment_3 needs two distinct ends.
    const K::Point_3 p = cgal_point(a);
    for (std::int64_t i : triangles_in_box({a, a}))
      if (impl_->triangles[i].has_on(p)) out.push_back(i);
    return out;
  }
  const K::Segment_3 s(cgal_point(a), cgal_point(b));
  impl_->tree.all_intersected_primitives(s, std::back_inserter(out));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace exactvis
