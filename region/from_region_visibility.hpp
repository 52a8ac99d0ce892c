#pragma once
// Exact from-region visibility of one scene triangle from a convex polygon or an axis-aligned box.
//
// Definition (docs/theory.md §5.1): T is visible from S iff the set of lines that cross relint S and
// relint T and whose segment between them has an open interior missing every closed occluder triangle has
// positive measure. Occluders are all scene triangles except T. Touching counts as blocked; grazing and
// measure-zero apertures are hidden.
//
// Method: the stabbing lines of each (S', T') pair (stabbing_pair.hpp) form an open cone of Plücker space
// intersected with the quadric; occluders (clipped to the wedge between the two planes, culled against the
// shaft) are subtracted by splitting cones along their edge hyperplanes (CSG), and a cone survives only if
// it still contains real lines (real_line_test.hpp). A surviving leaf proves visibility and yields a witness
// segment, re-checked exactly against every candidate occluder before it is reported.
#include "kernel/scene.hpp"
#include "region/convex_polygon_3.hpp"

#include <cstdint>
#include <functional>
#include <optional>

namespace exactvis::region {

// Returns indices into Scene::triangles of (at least) every triangle whose bounding box meets `box`.
using CandidateFinder = std::function<std::vector<std::int64_t>(const Box3& box)>;

// Brute-force candidate finder (for tests and tiny scenes).
CandidateFinder brute_force_candidates(const Scene& scene);

struct VisibilityOptions {
  int samples = 48;             // random segments cast per stabbing pair before the exact query
  std::uint64_t seed = 1;       // for sampling (results do not depend on it, only the witness may)
  bool round_witness = true;    // report the witness with double coordinates when that rounding stays a
                                // valid witness (re-checked exactly), else with exact rationals
};

struct VisibilityStats {
  std::int64_t stabbing_pairs = 0;
  std::int64_t occluders_considered = 0;   // candidates left after shaft culling and clipping
  std::int64_t effective_occluders = 0;    // occluders that split or removed at least one cone
  std::int64_t samples_cast = 0;
  std::int64_t splits = 0;                 // halfspace intersections performed
  std::int64_t cones_created = 0;
  std::int64_t cones_alive_max = 0;        // largest stack of pending cones
  std::int64_t real_line_tests = 0;
  std::int64_t face_tests = 0;             // faces examined by the exhaustive step of the real-line test
  std::int64_t exact_evaluations = 0;      // kernel predicate exact fallbacks during the query (approximate
                                           // when queries run in parallel)
  bool accepted_by_sampling = false;
};

// Adds the counters of `part` to `total` (cones_alive_max: maximum; accepted_by_sampling: or).
void accumulate(VisibilityStats& total, const VisibilityStats& part);

struct Witness {
  RationalPoint3 p;  // on the source
  RationalPoint3 q;  // in the relative interior of the target
};

struct VisibilityResult {
  std::int64_t triangle_index = -1;  // index into Scene::triangles
  bool visible = false;
  std::optional<Witness> witness;
  VisibilityStats stats;
};

// Visibility of scene.triangles[triangle_index] from the convex polygon `source` (>= 3 coplanar vertices,
// positive area, convex; checked by the caller, see validate_source_polygon).
VisibilityResult visible_from_polygon(const Scene& scene, const CandidateFinder& candidates, const Polygon3& source,
                                      std::int64_t triangle_index, const VisibilityOptions& options = {});

// Visibility from an axis-aligned box (view cell) with lo < hi in every coordinate.
VisibilityResult visible_from_box(const Scene& scene, const CandidateFinder& candidates, const Box3& cell,
                                  std::int64_t triangle_index, const VisibilityOptions& options = {});

// The witness rounded to the nearest doubles, if that is still a valid witness (exact re-check: p on the
// source per `on_source`, q in relint T, open segment free); std::nullopt otherwise.
std::optional<Witness> round_witness(const Scene& scene, const CandidateFinder& candidates,
                                     const std::function<bool(const RationalPoint3&)>& on_source,
                                     std::int64_t triangle_index, const Witness& w);

// Throws std::invalid_argument with a clear message unless `poly` is a convex planar polygon of positive
// area with >= 3 vertices and no repeated consecutive vertices.
void validate_source_polygon(const Polygon3& poly);

// True iff the open segment (p, q) meets no candidate triangle other than `skip` (exact).
bool segment_is_free(const Scene& scene, const std::vector<std::int64_t>& candidates, const RationalPoint3& p,
                     const RationalPoint3& q, std::int64_t skip);

}  // namespace exactvis::region
