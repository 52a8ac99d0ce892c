#pragma once
// Exact visibility of an axis-aligned box from a view cell with respect to a given set of occluders: the
// hidden-box test of the PVS hierarchy (docs/theory.md §5.8). A box proved hidden with respect to occluders
// that exclude every triangle inside it hides each of those triangles.
#include "kernel/scene.hpp"
#include "region/hierarchy_candidates.hpp"
#include "region/convex_polygon_3.hpp"
#include "region/visibility_options.hpp"

#include <cstdint>
#include <vector>

namespace exactvis::region {

// The answer of a hidden-box test.
struct BoxReach {
  bool may_be_visible = false;  // false proves B hidden (below); true: a witness was found, or the test gave up
  bool gave_up = false;         // options.split_budget was spent first (then may_be_visible is true)
};

// Input: the scene, the occluders (indices into Scene::triangles), the closed cell and a closed box B that
// does not meet it (the caller checks), options of the line-space query; stats are added to. Output:
// may_be_visible false proves that the lines meeting the cell and B whose segment from the cell to B has an
// open interior missing every occluder form a set of measure zero; true means such lines may exist (a
// witness was found, or the test gave up: then gave_up is true). Method: each face of B that the cell sees from its
// outer side, as one convex quadrilateral, is a target of the exact cell-face/polygon CSG of §5.2-§5.5 with
// these occluders only, from each cell face that sees part of it. options.split_budget > 0 bounds the splits
// of the whole test: once they are spent, the test gives up (returns true; sound for a caller that then
// descends, §5.8). Exact; cost: up to 9 cell-face/box-face sources, up to 4 stabbing pairs each.
BoxReach box_may_be_visible(const Scene& scene, const std::vector<std::int64_t>& occluders, const RationalBox3& cell,
                            const Box3& box, const VisibilityOptions& options, VisibilityStats& stats);

// The same answer and stats with the occluders given as occluders(query_box) (query_box: a box holding the
// cell and B), gathered per stabbing pair through the finder's hierarchy (region/line_set_csg.hpp), so the
// cost follows the triangles near each shaft rather than all of them.
BoxReach box_may_be_visible(const Scene& scene, const HierarchyCandidates& occluders, const Box3& query_box,
                            const RationalBox3& cell, const Box3& box, const VisibilityOptions& options,
                            VisibilityStats& stats);

// True iff the closed boxes meet (exact comparisons).
bool boxes_meet(const RationalBox3& cell, const Box3& box);

}  // namespace exactvis::region
