#pragma once
// A candidate finder (region/candidate_finder.hpp) that also carries the PVS hierarchy (region/triangle_bvh.hpp),
// so that a query can gather only what survives a test on hierarchy boxes instead of every triangle of its
// box: the shaft occluders of one stabbing pair skip whole nodes outside a shaft plane (docs/theory.md §5.2),
// the exact re-check of a witness segment visits only the nodes near the segment. Its plain query is the
// index's candidates_in_box, so a HierarchyCandidates stored in a CandidateFinder behaves as
// index_candidates everywhere; the from-region query detects it (hierarchy_of) and gathers through it.
#include "kernel/predicates.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"
#include "region/candidate_finder.hpp"
#include "region/coplanar_panels.hpp"
#include "region/triangle_bvh.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

namespace exactvis::region {

class BackFaceCulling;  // region/back_face_culling.hpp

// A test on closed boxes of doubles: true only when the caller has proved that no triangle inside the box is
// of use to it (it may answer false whenever unsure). Called on the querying thread only.
using BoxPrune = std::function<bool(const Box3& box)>;

struct HierarchyCandidates {
  TriangleIndex index;        // the scene's index (a cheap copy sharing the tree)
  const Scene* scene = nullptr;     // the scene `bvh` was built on; must outlive this
  const TriangleBvh* bvh = nullptr;  // must outlive this
  std::function<bool(std::int64_t)> excluded;  // may be empty; triangles it holds for are never returned
  // May be null. Else the scene's coplanar convex panels and pairs (region/coplanar_panels.hpp): the
  // stabbing-pair queries through this finder subtract each usable panel as one convex occluder (the same line
  // set up to a null set), then each usable pair of the triangles left; only the pairs when whole_panels is false.
  const CoplanarPanels* panels = nullptr;
  bool whole_panels = true;
  // May be null. Else the back faces of closed convex solids from the cell every query's source lies in
  // (region/back_face_culling.hpp): the stabbing-pair queries through this finder drop the occluders that are
  // back faces of a solid none of whose triangles is excluded (the solid's other triangles block the same
  // lines up to a null set), before the panels.
  const BackFaceCulling* back_faces = nullptr;

  // index.candidates_in_box(box) without the excluded triangles, in increasing order.
  std::vector<std::int64_t> operator()(const Box3& box) const;

  // (*this)(box) without the triangles t for which prune(B) holds for a box B containing t: depth first, a
  // node is entered when its box meets `box` and prune(node box) is false; a leaf reports its triangles whose
  // bounding box meets `box` (the same closed comparisons of the same doubles as candidates_in_box, so
  // pruned(box, never) == (*this)(box)) and for which prune(triangle box) is false; sorted.
  // Cost: O(nodes entered + k log k).
  std::vector<std::int64_t> pruned(const Box3& box, const BoxPrune& prune) const { return pruned_with(box, prune); }

  // The same with any callable Box3 -> bool (inlined: no call through std::function per node).
  template <class Prune>
  std::vector<std::int64_t> pruned_with(const Box3& box, const Prune& prune) const;
};

namespace hierarchy_detail {
// Closed boxes meet (plain comparisons, as CGAL::do_overlap in the index's query).
inline bool overlap(const Box3& a, const Box3& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}
}  // namespace hierarchy_detail

template <class Prune>
std::vector<std::int64_t> HierarchyCandidates::pruned_with(const Box3& box, const Prune& prune) const {
  using hierarchy_detail::overlap;
  std::vector<std::int64_t> out;
  if (box.empty() || bvh->nodes.empty()) return out;
  std::vector<int> stack;  // depth first
  stack.reserve(64);
  stack.push_back(0);
  while (!stack.empty()) {
    const int index = stack.back();
    stack.pop_back();
    const BvhNode& node = bvh->nodes[static_cast<std::size_t>(index)];
    if (!overlap(node.box, box) || prune(node.box)) continue;
    if (node.left >= 0) {
      stack.push_back(node.right);
      stack.push_back(node.left);
      continue;
    }
    for (int i = node.begin; i < node.end; ++i) {
      const std::int64_t t = bvh->order[static_cast<std::size_t>(i)];
      if (excluded && excluded(t)) continue;
      const Box3 tb = triangle_box(*scene, scene->triangles[static_cast<std::size_t>(t)]);
      if (overlap(tb, box) && !prune(tb)) out.push_back(t);
    }
  }
  std::sort(out.begin(), out.end());  // index order, as candidates_in_box
  return out;
}

// segment_is_free(scene, finder(box), p, q, skip) (region/witness.hpp) for a closed segment inside the closed
// `box`, visiting only the nodes whose boxes meet a box of doubles enclosing the segment (a triangle meeting
// the segment has its bounding box there): the same answer. Exact.
bool segment_is_free(const Scene& scene, const HierarchyCandidates& finder, const Box3& box, const RationalPoint3& p,
                     const RationalPoint3& q, std::int64_t skip);

// The finder of the PVS queries: index_candidates(index) carrying `bvh` (built on `scene`).
CandidateFinder hierarchy_candidates(const TriangleIndex& index, const Scene& scene, const TriangleBvh& bvh);

// The hierarchy a finder made by hierarchy_candidates (or from a HierarchyCandidates) carries; null for any
// other finder.
inline const HierarchyCandidates* hierarchy_of(const CandidateFinder& finder) {
  return finder.target<HierarchyCandidates>();
}

}  // namespace exactvis::region
