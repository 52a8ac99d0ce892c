#pragma once
// Exact from-region visibility of one scene triangle from a convex polygon or an axis-aligned box.
//
// Definition (docs/theory.md §5.1): T is visible from S iff the set of lines that cross relint S and
// relint T and whose segment between them has an open interior missing every closed occluder triangle has
// positive measure. Occluders are all scene triangles except T. Touching counts as blocked; grazing and
// measure-zero apertures are hidden.
//
// Method: the stabbing lines of each (S', T') pair (stabbing_pair.hpp) form an open cone of Plücker space
// intersected with the quadric; occluders (occluder_shaft.hpp: clipped to the wedge between the two planes,
// culled against the shaft) are subtracted by splitting cones along their edge hyperplanes (line_set_csg.hpp),
// and a cone survives only if it still contains real lines (real_line_test.hpp). A surviving leaf proves
// visibility and yields a witness segment (witness.hpp), re-checked exactly against every candidate occluder
// before it is reported. A box source is reduced to its faces (after a witness inside the cell, if the target
// enters it).
#include "kernel/scene.hpp"
#include "region/candidate_finder.hpp"
#include "region/convex_polygon_3.hpp"
#include "region/visibility_options.hpp"
#include "region/witness.hpp"

#include <cstdint>
#include <optional>

namespace exactvis::region {

struct VisibilityResult {
  std::int64_t triangle_index = -1;  // index into Scene::triangles
  bool visible = false;
  std::optional<Witness> witness;
  VisibilityStats stats;
};

// Visibility of scene.triangles[triangle_index] from the convex polygon `source` (>= 3 coplanar vertices,
// positive area, convex; checked by the caller, see validate_source_polygon). Thread-safe (the candidate
// finder must be).
VisibilityResult visible_from_polygon(const Scene& scene, const CandidateFinder& candidates, const Polygon3& source,
                                      std::int64_t triangle_index, const VisibilityOptions& options = {});

// Visibility from an axis-aligned box (view cell) with lo < hi in every coordinate (throws
// std::invalid_argument otherwise). Thread-safe. The box may have exact rational corners (a cell given as
// num/den) or double corners.
VisibilityResult visible_from_box(const Scene& scene, const CandidateFinder& candidates, const RationalBox3& cell,
                                  std::int64_t triangle_index, const VisibilityOptions& options = {});
VisibilityResult visible_from_box(const Scene& scene, const CandidateFinder& candidates, const Box3& cell,
                                  std::int64_t triangle_index, const VisibilityOptions& options = {});

}  // namespace exactvis::region
