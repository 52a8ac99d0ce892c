#pragma once
// Exact exterior visibility of a model's triangles (docs/theory.md §5.6): T is exterior visible iff the rays
// from points of relint T that meet no other closed triangle (escape to infinity) have positive measure.
//
// Each triangle goes through three stages, the first that decides wins:
//   1. proposals: Embree rays from points of T (centroid along both normals first, then random points and
//      directions) that Embree sees escape are re-checked exactly (check_exterior_witness): a valid one is
//      the witness (it proves positive measure by itself, Lemma 5.6.2). Triangles on the convex hull are
//      accepted here by their first or second ray (Corollary 5.6.3). A first round of 32 rays runs before
//      stage 2, the remaining ones (up to ExteriorOptions::rays) after it.
//   2. enclosure: a closed shell of the scene around T (region/exterior_enclosure.hpp) proves T hidden.
//   3. the exact from-region query (region/from_region_visibility.hpp) of T from each face of a box strictly
//      enclosing the scene (Theorem 5.6.1): visible with a witness segment, which becomes the escaping ray,
//      or hidden (no face sees it).
// Floats only propose; every answer is exact and every "visible" carries a witness.
#include "kernel/float_ray_caster.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"
#include "region/candidate_finder.hpp"
#include "region/convex_polygon_3.hpp"
#include "region/exterior_enclosure.hpp"
#include "region/exterior_witness.hpp"
#include "region/visibility_options.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace exactvis::region {

struct ExteriorOptions {
  int rays = 4096;             // Embree proposals per triangle at most (stage 1: the first 32 before stage 2,
                               // the rest after it); 0 skips the stage
  bool use_enclosure = true;   // stage 2
  VisibilityOptions query;     // stage 3 (samples, seed, witness rounding of the from-region query)
  std::uint64_t seed = 1;      // proposals (answers do not depend on it; witnesses may)
  bool round_witness = true;   // report q and d as doubles when the rounded ray is still a witness
  int threads = 0;             // 0 = all cores, else 1 .. kMaxThreads (region/cell_visibility.hpp)
  std::function<void()> on_triangle_done;  // called from the worker threads after each triangle
};

// Which stage decided a triangle.
enum class ExteriorStage : std::uint8_t { Proposal, Enclosure, QueryVisible, QueryHidden };

struct ExteriorTriangle {
  bool visible = false;
  ExteriorStage stage = ExteriorStage::QueryHidden;
  std::optional<ExteriorWitness> witness;  // when visible (passes check_exterior_witness)
  std::optional<EnclosureProof> enclosure;  // when stage == Enclosure
};

struct ExteriorCounts {
  std::int64_t visible = 0, hidden = 0;
  std::int64_t by_proposal = 0, by_enclosure = 0, by_query_visible = 0, by_query_hidden = 0;
  std::int64_t proposals_cast = 0;     // Embree rays cast
  std::int64_t proposals_checked = 0;  // rays Embree saw escape, checked exactly
  std::int64_t proposals_rejected = 0; // of those, rejected by the exact check
};

struct ExteriorVisibility {
  std::vector<ExteriorTriangle> triangles;  // parallel to Scene::triangles
  RationalBox3 enclosing_box;               // the box of Theorem 5.6.1 (strictly contains the scene)
  ExteriorCounts counts;
  VisibilityStats query_stats;              // accumulated over the stage-3 queries
};

// The box of Theorem 5.6.1: bounding_box(scene) widened on every side by a power of two of about 1/16 of
// its largest extent (exact doubles). Requires a scene with at least one triangle.
RationalBox3 exterior_enclosing_box(const Scene& scene);

// One triangle at a time (the pieces built once per scene: box, shells, caster). Thread-safe.
class ExteriorClassifier {
 public:
  // `caster` may be null (then stage 1 is skipped). The scene, index and caster must outlive the classifier.
  ExteriorClassifier(const Scene& scene, const TriangleIndex& index, const FloatRayCaster* caster,
                     const ExteriorOptions& options);
  // Input: an index into Scene::triangles. Output: the decision; `stats` receives the stage-3 counters and
  // `counts` the proposal counters (both may be null). Exact.
  ExteriorTriangle classify(std::int64_t triangle_index, VisibilityStats* stats = nullptr,
                            ExteriorCounts* counts = nullptr) const;
  const RationalBox3& enclosing_box() const { return box_; }
  const Box3& scene_box() const { return scene_box_; }

 private:
  const Scene& scene_;
  const TriangleIndex& index_;
  const FloatRayCaster* caster_;
  ExteriorOptions options_;
  Box3 scene_box_;
  RationalBox3 box_;
  std::optional<SceneShells> shells_;
  CandidateFinder finder_;
};

// Input: scene (non-empty), its index, an Embree caster over it (or null), options. Output: one decision per
// triangle, on all cores; the answers do not depend on the thread count or the seed. Throws
// std::invalid_argument for a thread count outside [0, kMaxThreads]. Cost: stage 1 for every triangle
// (Embree rays, an exact ray check per proposal), stages 2-3 only for the triangles stage 1 leaves.
ExteriorVisibility exterior_visibility(const Scene& scene, const TriangleIndex& index, const FloatRayCaster* caster,
                                       const ExteriorOptions& options = {});

}  // namespace exactvis::region
