#include "events/occluder_index.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <iterator>

namespace exactvis {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using TriIt = std::vector<K::Triangle_3>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<K, TriIt>;
using Traits = CGAL::AABB_traits<K, Primitive>;
using Tree = CGAL::AABB_tree<Traits>;
K::Point_3 to_point(const Point3& p) { return {p.x, p.y, p.z}; }
}  // namespace

struct OccluderIndex::Impl {
  std::vector<K::Triangle_3> tris;
  Tree tree;
};

OccluderIndex::OccluderIndex(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->tris.reserve(scene.triangles.size());
  for (int i = 0; i < static_cast<int>(scene.triangles.size()); ++i) {
    const auto& t = scene.triangles[i];
    impl_->tris.emplace_back(to_point(scene.corner(t, 0)), to_point(scene.corner(t, 1)), to_point(scene.corner(t, 2)));
  }
  impl_->tree.insert(impl_->tris.cbegin(), impl_->tris.cend());
  impl_->tree.build();
}

OccluderIndex::~OccluderIndex() = default;

std::vector<int> OccluderIndex::triangles_meeting(const Point3& a, const Point3& b, const Point3& c) const {
  std::vector<int> out;
  if (impl_->tris.empty()) return out;
  std::vector<TriIt> hits;
  impl_->tree.all_intersected_primitives(K::Triangle_3(to_point(a), to_point(b), to_point(c)),
                                         std::back_inserter(hits));
  out.reserve(hits.size());
  for (const auto& it : hits) out.push_back(static_cast<int>(it - impl_->tris.cbegin()));
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> OccluderIndex::triangles_in_box(const Box3& box) const {
  std::vector<int> out;
  if (impl_->tris.empty() || box.empty()) return out;
  std::vector<TriIt> hits;
  impl_->tree.all_intersected_primitives(CGAL::Bbox_3(box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z),
                                         std::back_inserter(hits));
  out.reserve(hits.size());
  for (const auto& it : hits) out.push_back(static_cast<int>(it - impl_->tris.cbegin()));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace exactvis
