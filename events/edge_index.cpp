#include "events/edge_index.hpp"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <iterator>

namespace exactvis {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using SegIt = std::vector<K::Segment_3>::const_iterator;
using Primitive = CGAL::AABB_segment_primitive<K, SegIt>;
using Traits = CGAL::AABB_traits<K, Primitive>;
using Tree = CGAL::AABB_tree<Traits>;
K::Point_3 to_point(const Point3& p) { return {p.x, p.y, p.z}; }
}  // namespace

struct EdgeIndex::Impl {
  std::vector<K::Segment_3> segs;
  Tree tree;
};

EdgeIndex::EdgeIndex(const Scene& scene, const SceneAdjacency& adj) : impl_(std::make_unique<Impl>()) {
  impl_->segs.reserve(adj.edges.size());
  for (const auto& e : adj.edges)
    impl_->segs.emplace_back(to_point(scene.vertices[e.v[0]]), to_point(scene.vertices[e.v[1]]));
  impl_->tree.insert(impl_->segs.cbegin(), impl_->segs.cend());
  impl_->tree.build();
}

EdgeIndex::~EdgeIndex() = default;

std::vector<int> EdgeIndex::edges_meeting_tetrahedron(const Point3& a, const Point3& b, const Point3& c,
                                                      const Point3& d) const {
  std::vector<int> out;
  if (impl_->segs.empty()) return out;
  std::vector<SegIt> hits;
  impl_->tree.all_intersected_primitives(K::Tetrahedron_3(to_point(a), to_point(b), to_point(c), to_point(d)),
                                         std::back_inserter(hits));
  out.reserve(hits.size());
  for (const auto& it : hits) out.push_back(static_cast<int>(it - impl_->segs.cbegin()));
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> EdgeIndex::edges_meeting_box(const Box3& box) const {
  std::vector<int> out;
  if (impl_->segs.empty() || box.empty()) return out;
  std::vector<SegIt> hits;
  impl_->tree.all_intersected_primitives(
      K::Iso_cuboid_3(box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z), std::back_inserter(hits));
  out.reserve(hits.size());
  for (const auto& it : hits) out.push_back(static_cast<int>(it - impl_->segs.cbegin()));
  std::sort(out.begin(), out.end());
  return out;
}

bool segment_meets_tetrahedron(const Point3& p, const Point3& q, const Point3& a, const Point3& b,
                               const Point3& c, const Point3& d) {
  const K::Tetrahedron_3 t(to_point(a), to_point(b), to_point(c), to_point(d));
  if (p.x == q.x && p.y == q.y && p.z == q.z) return !t.has_on_unbounded_side(to_point(p));
  return CGAL::do_intersect(K::Segment_3(to_point(p), to_point(q)), t);
}

}  // namespace exactvis
