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

// Input: the scene, the occluders (indices into Scene::triangles), the closed cell and a closed box B that
// does not meet it (the caller checks), options of the line-space query. Output: false proves that the
// lines meeting the cell and B whose segment from the cell to B has an open interior missing every
// occluder form a set of measure zero; true means such lines may exist (a witness was found). Method: each
// face of B that the cell sees from its outer side, cut into two triangles, is a target of the exact
// cell-face/triangle CSG of §5.2-§5.5 with these occluders only. Exact; cost: up to 6 such queries.
bool box_may_be_visible(const Scene& scene, const std::vector<std::int64_t>& occluders, const RationalBox3& cell,
                        const Box3& box, const VisibilityOptions& options, VisibilityStats& stats);

// The same answer and stats with the occluders given as occluders(query_box) (query_box: a box holding the
// cell and B), gathered per stabbing pair through the finder's hierarchy (region/line_set_csg.hpp), so the
// cost follows the triangles near each shaft rather than all of them.
bool box_may_be_visible(const Scene& scene, const HierarchyCandidates& occluders, const Box3& query_box,
                        const RationalBox3& cell, const Box3& box, const VisibilityOptions& options,
                        VisibilityStats& stats);

// True iff the closed boxes meet (exact comparisons).
bool boxes_meet(const RationalBox3& cell, const Box3& box);

}  // namespace exactvis::region
