#pragma once
// The potentially visible set (PVS) of one view cell: the types every PVS method shares (the exact method
// region/exact_pvs.hpp; the dispatch over methods region/pvs_method.hpp), and the scene context they are
// computed in (the scene, its exact triangle index and its float ray caster, built once for all cells).
//
// Conventions (docs/theory.md §5.1, §5.7): a triangle is visible from the closed cell when the lines from the
// cell to its relative interior that miss every other closed triangle have positive measure; an object is
// visible when one of its triangles is. Cells inside geometry are allowed.
#include "kernel/float_ray_caster.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"
#include "region/convex_occluder.hpp"
#include "region/convex_polygon_3.hpp"
#include "region/coplanar_panels.hpp"
#include "region/extruded_scene.hpp"
#include "region/triangle_bvh.hpp"
#include "region/visibility_options.hpp"
#include "region/witness.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace exactvis::region {

// What every cell of a run is computed against. Builds the AABB tree, the Embree BVH and the PVS hierarchy
// (region/triangle_bvh.hpp) once (O(n log n));
// `scene` must outlive the context. Queries are const and thread-safe.
class PvsContext {
 public:
  explicit PvsContext(const Scene& scene);
  const Scene& scene() const { return scene_; }
  const TriangleIndex& index() const { return index_; }
  const FloatRayCaster& rays() const { return rays_; }
  const TriangleBvh& bvh() const { return bvh_; }
  double diagonal() const { return diagonal_; }  // length of the scene's bounding box diagonal
  // The 2.5D verdict and wall rectangles of method `conservative` (region/extruded_scene.hpp), computed on
  // first use (thread-safe; O(n log n)), so the other methods do not pay for it.
  const ExtrudedScene& extruded() const;
  // The scene's closed convex solids (region/convex_occluder.hpp), computed on first use like extruded().
  const std::vector<ConvexSolid>& solids() const;
  // The scene's coplanar convex panels and pairs (region/coplanar_panels.hpp), computed on first use like solids().
  const CoplanarPanels& coplanar_panels() const;

 private:
  const Scene& scene_;
  TriangleIndex index_;
  FloatRayCaster rays_;
  TriangleBvh bvh_;
  double diagonal_ = 0;
  struct Lazy {
    std::once_flag once, solids_once, panels_once;
    ExtrudedScene extruded;
    std::vector<ConvexSolid> solids;
    CoplanarPanels panels;
  };
  std::unique_ptr<Lazy> lazy_ = std::make_unique<Lazy>();
};

struct PvsOptions {
  VisibilityOptions query;  // the exact per-triangle query (its sampling, seed and witness rounding)
  int rays = 8;             // Embree rays cast per triangle before the exact query (proposals only)
  std::int64_t cell_rays = 100000;  // method `sampled`: random rays per cell (region/sampled_pvs.hpp)
  int threads = 0;          // worker threads: 0 = all cores, else 1 .. kMaxThreads
  bool hierarchy = true;    // cull subtrees of the triangle BVH whose box is proved hidden (§5.8)
  int box_rays = 32;        // Embree rays per BVH node to its triangles: one reaching the subtree skips the
                            // node's (exact) hidden-box test
  int box_face_rays = 32;   // then Embree rays per BVH node from the cell to its box's faces facing the cell:
                            // one hitting nothing before the face skips the node's hidden-box test (sound:
                            // descending is; docs/theory.md §5.8)
  int min_cull = 16;        // hidden-box tests only for nodes of at least this many triangles
  bool merge_coplanar = true;  // hidden-box tests and triangle queries subtract coplanar pairs (two triangles
                               // with a convex union, region/coplanar_panels.hpp) as one convex occluder (the same
                               // line sets, §5.8; witnesses found by the CSG may differ from those without)
  bool merge_panels = true;  // with merge_coplanar: whole coplanar convex panels first (a wall strip, a roof fan)
                             // as one convex occluder, the pairs then for the triangles left (§5.8)
  int box_splits_per_triangle = 0;   // > 0: a node's hidden-box test gives up after this many CSG splits per
                                      // triangle of the node, and the node is descended (sound, docs/theory.md
                                      // §5.8); 0: no limit
  bool occluder_proofs = true;  // method `exact`: try the single wall / convex solid proofs of method
                                // `conservative` (region/single_occluder_culling.hpp) before the line-space tests
  bool back_faces = true;       // method `exact`: a triangle of a closed convex solid apart from the cell whose
                                // plane has the whole cell on the solid's side is hidden by that solid
                                // (region/back_face_culling.hpp, docs/theory.md §5.8), before its rays and query
  bool back_face_occluders = true;  // method `exact`: such back faces are also dropped from the occluders of the
                                    // triangle queries and box tests (the solid's other triangles block the same
                                    // lines up to a null set; same answers, other CSG pieces and witnesses)
  int virtual_occluders = 32;   // method `exact` with the hierarchy: at most this many boxes proved hidden are
                                // kept as virtual occluders for what lies behind (region/virtual_occluders.hpp);
                                // 0: none (each node decided on its own, as before)
  // Called with the number of triangles decided so far in the current cell (thread-safe callers only:
  // it is called from the worker threads), e.g. for a progress bar. May be empty.
  std::function<void(std::int64_t decided)> on_progress;
};

struct VisibleTriangle {
  std::int64_t index = -1;         // into Scene::triangles
  std::optional<Witness> witness;  // set by the exact method: p in the closed cell, q in relint T, open
                                   // segment free (checked exactly before it is reported)
};

// Counters of one cell (deterministic: they do not depend on the thread count).
struct CellPvsStats {
  std::int64_t triangles = 0;          // triangles decided (the whole scene)
  std::int64_t visible = 0;
  std::int64_t accepted_by_rays = 0;   // visible through an exactly re-checked Embree proposal
  std::int64_t exact_queries = 0;      // triangles decided by the exact from-region query
  std::int64_t culled = 0;             // triangles proved hidden without their own line-space query: by a
                                       // hidden hierarchy box or a single-occluder proof
  std::int64_t culled_by_occluders = 0;  // of those, by one wall or one convex solid (not in JSON files)
  std::int64_t boxes_tested = 0;       // exact hidden-box tests run
  std::int64_t boxes_culled = 0;       // boxes proved hidden
  std::int64_t boxes_given_up = 0;     // box tests that spent their split budget (descended; not in JSON files)
  std::int64_t culled_by_back_faces = 0;  // of culled_by_occluders, back faces of their own solid (not in JSON)
  std::int64_t culled_by_virtual = 0;  // triangles culled by a virtual occluder (a box proved hidden before;
                                       // not in JSON files)
  std::int64_t virtual_occluders = 0;  // boxes registered as virtual occluders (before the cap; not in JSON)
  std::int64_t virtual_tests = 0;      // exact virtual-occluder tests run (not in JSON files)
  std::int64_t neighbour_tries = 0;    // coherence: triangles with a previous cell's witness to try (not in JSON)
  std::int64_t neighbour_hits = 0;     // of those, accepted through it (counted in accepted_by_rays; not in JSON)
  std::int64_t rays_cast = 0;          // method `sampled`: random rays cast from the cell
  VisibilityStats query;               // accumulated over the exact queries (exact_evaluations left at 0)
  double seconds = 0;                  // wall-clock time (for benchmarks; not written to JSON files)
};

struct CellPvs {
  RationalBox3 cell;
  std::vector<VisibleTriangle> visible;  // sorted by index
  CellPvsStats stats;
};

// Names of the objects (Scene::objects) with at least one visible triangle, in object order.
std::vector<std::string> visible_objects(const Scene& scene, const CellPvs& pvs);

// Throws std::invalid_argument unless lo < hi in every coordinate ("view cell ... is empty or inverted").
void check_view_cell(const RationalBox3& cell);

}  // namespace exactvis::region
