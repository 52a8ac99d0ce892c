#pragma once
// The CGAL AABB tree behind kernel/triangle_index and kernel/edge_index (included only by their .cpp files:
// CGAL's AABB headers stay out of every public header).
//
// An AabbIndex<Datum> holds a list of Epick objects (Triangle_3 or Segment_3 of the exact input doubles),
// each with its position in the list as id, in a tree built once at construction. Queries are const and
// thread-safe (the tree is never modified after build(); CGAL builds lazily only when asked first, so the
// constructor builds it). Two kinds of query:
//   - meeting(q): every object that meets the closed query object q exactly (CGAL's Epick do_intersect
//     predicates are exactly evaluated on the input doubles);
//   - bbox_overlapping(box): every object whose axis-aligned bounding box meets the closed box (plain
//     comparisons of doubles), a candidate filter.
// Both return ids in increasing order. Cost: O(log n + k) per query for k results (plus the sort).
#include "kernel/scene.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <vector>

namespace exactvis::aabb {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

inline K::Point_3 cgal_point(const Point3& p) { return {p.x, p.y, p.z}; }
inline CGAL::Bbox_3 cgal_bbox(const Box3& b) { return {b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z}; }

// AABB primitive: one object (stored by value, so the tree does not point into a caller's container) and
// its id.
template <class Datum_>
struct Primitive {
  using Id = std::int64_t;
  using Point = K::Point_3;
  using Datum = Datum_;
  Id index = -1;
  Datum datum_;

  Primitive() = default;
  template <class Iterator>
  explicit Primitive(Iterator it) : index(it->first), datum_(it->second) {}
  Id id() const { return index; }
  const Datum& datum() const { return datum_; }
  Point reference_point() const { return datum_.vertex(0); }
};

template <class Datum>
class AabbIndex {
 public:
  explicit AabbIndex(const std::vector<Datum>& items) : items_(items) {
    std::vector<std::pair<std::int64_t, Datum>> tagged;
    tagged.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) tagged.emplace_back(static_cast<std::int64_t>(i), items[i]);
    if (!tagged.empty()) {
      tree_.insert(tagged.begin(), tagged.end());
      tree_.build();  // now, so that later const queries never modify the tree (thread safety)
    }
  }

  std::size_t size() const { return items_.size(); }
  const Datum& item(std::int64_t id) const { return items_[static_cast<std::size_t>(id)]; }

  template <class Query>
  std::vector<std::int64_t> meeting(const Query& q) const {
    std::vector<std::int64_t> out;
    if (items_.empty()) return out;
    tree_.all_intersected_primitives(q, std::back_inserter(out));
    std::sort(out.begin(), out.end());
    return out;
  }

  std::vector<std::int64_t> bbox_overlapping(const Box3& box) const {
    std::vector<std::int64_t> out;
    if (box.empty() || items_.empty()) return out;
    const CGAL::Bbox_3 q = cgal_bbox(box);
    if (items_.size() == 1) {  // CGAL's traversal of one primitive skips the node test
      if (CGAL::do_overlap(q, items_[0].bbox())) out.push_back(0);
      return out;
    }
    BoxOverlapTraversal traversal{&out};
    tree_.traversal(q, traversal);
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive<Datum>>>;

  // Descends into nodes whose box meets the query box, reports primitives whose own box meets it.
  struct BoxOverlapTraversal {
    std::vector<std::int64_t>* out;
    bool go_further() const { return true; }
    void intersection(const CGAL::Bbox_3& q, const Primitive<Datum>& p) {
      if (CGAL::do_overlap(q, p.datum().bbox())) out->push_back(p.index);
    }
    template <class Node>
    bool do_intersect(const CGAL::Bbox_3& q, const Node& node) const {
      return CGAL::do_overlap(q, node.bbox());
    }
  };

  std::vector<Datum> items_;
  Tree tree_;
};

}  // namespace exactvis::aabb
