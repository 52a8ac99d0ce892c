#include "region/exact_pvs.hpp"

#include "region/back_face_culling.hpp"
#include "region/box_visibility.hpp"
#include "region/cell_visibility.hpp"
#include "region/from_region_visibility.hpp"
#include "region/hierarchy_candidates.hpp"
#include "region/ray_witness.hpp"
#include "region/single_occluder_culling.hpp"
#include "region/virtual_occluders.hpp"
#include "util/for_each_index.hpp"
#include "util/mix_seed.hpp"

#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <glm/vec3.hpp>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>

namespace exactvis::region {
namespace {

struct TriangleAnswer {
  bool visible = false;
  bool by_rays = false;
  bool by_occluder = false;  // proved hidden by one wall or one convex solid (or its own solid: by_back_face)
  bool by_back_face = false;  // a back face of a closed convex solid apart from the cell
  bool by_neighbour = false;  // accepted through the previous cell's witness (counted in by_rays too)
  std::optional<Witness> witness;
  VisibilityStats stats;
};

}  // namespace

namespace {

bool in_open_box(const RationalPoint3& p, const RationalBox3& b) {
  for (int k = 0; k < 3; ++k)
    if (!(b.lo[k] < p[k] && p[k] < b.hi[k])) return false;
  return true;
}

// Proposals for this cell from a witness (p, q) of a neighbouring cell: p pulled into this cell (the nearest
// point of the cell shrunk by 1/64 of its size per side: a short move, so the segment likely stays free;
// doubles when they land strictly inside, else exact), then p translated by the offset between the cells.
// Only proposals: each is re-checked exactly by is_robust_cell_witness.
std::vector<Witness> neighbour_proposals(const Witness& w, const RationalBox3& cell, const Box3& approx,
                                         const RationalBox3& previous) {
  std::vector<Witness> out;
  Point3 pd;
  for (int k = 0; k < 3; ++k) {
    const double m = (approx.hi[k] - approx.lo[k]) / 64;
    pd[k] = std::min(std::max(CGAL::to_double(w.p[k]), approx.lo[k] + m), approx.hi[k] - m);
  }
  const RationalPoint3 pulled{Exact(pd.x), Exact(pd.y), Exact(pd.z)};
  if (in_open_box(pulled, cell)) {
    out.push_back({pulled, w.q});
  } else {
    RationalPoint3 p = w.p;
    for (int k = 0; k < 3; ++k) {
      const Exact m = (cell.hi[k] - cell.lo[k]) / 64;
      if (p[k] < cell.lo[k] + m) p[k] = cell.lo[k] + m;
      if (p[k] > cell.hi[k] - m) p[k] = cell.hi[k] - m;
    }
    out.push_back({p, w.q});
  }
  const RationalPoint3 moved{w.p.x + (cell.lo.x - previous.lo.x), w.p.y + (cell.lo.y - previous.lo.y),
                             w.p.z + (cell.lo.z - previous.lo.z)};
  if (in_open_box(moved, cell) && !(moved == out.front().p)) out.push_back({moved, w.q});
  return out;
}

}  // namespace

CellPvs exact_cell_pvs(const PvsContext& context, const RationalBox3& cell, const PvsOptions& options) {
  return exact_cell_pvs(context, cell, options, nullptr);
}

CellPvs exact_cell_pvs(const PvsContext& context, const RationalBox3& cell, const PvsOptions& options,
                       const CellPvs* previous) {
  check_view_cell(cell);
  check_thread_count(options.threads);
  const auto start = std::chrono::steady_clock::now();
  const Scene& scene = context.scene();
  const std::size_t n = scene.triangles.size();
  // Shaft occluders are gathered through the hierarchy (region/hierarchy_candidates.hpp): same answers.
  // With merge_coplanar, coplanar pairs (2-triangle panels) are one convex occluder in the queries too;
  // with merge_panels, whole coplanar convex panels first (region/coplanar_panels.hpp).
  const CoplanarPanels* panels = options.merge_coplanar ? &context.coplanar_panels() : nullptr;
  // Back faces of closed convex solids (region/back_face_culling.hpp): an exact proof from 8 orientations,
  // before everything else a triangle costs; with back_face_occluders also dropped from the queries' occluder
  // lists (the solids' other triangles block the same lines). Both only ever hide (docs/theory.md §5.8).
  std::optional<BackFaceCulling> back_faces;
  if (options.back_faces || options.back_face_occluders) back_faces.emplace(context, cell);
  const bool use_back_faces = options.back_faces && back_faces->any();
  const BackFaceCulling* drop_back_faces =
      options.back_face_occluders && back_faces && back_faces->any() ? &*back_faces : nullptr;
  const CandidateFinder finder =
      CandidateFinder(HierarchyCandidates{context.index(), &scene, &context.bvh(), {}, panels,
                                          options.merge_panels, drop_back_faces});
  const Box3 approx = approximate_box(cell);
  std::vector<TriangleAnswer> answers(n);
  std::atomic<std::int64_t> decided{0};
  // Coherence: the previous cell's witnesses, by triangle (proposals only: they never decide "hidden").
  std::vector<const Witness*> neighbour(previous ? n : 0, nullptr);
  if (previous)
    for (const VisibleTriangle& v : previous->visible)
      if (v.witness && v.index >= 0 && static_cast<std::size_t>(v.index) < n) neighbour[v.index] = &*v.witness;

  // Single-occluder proofs (one wall or one convex solid, region/single_occluder_culling.hpp): exact and
  // cheap, so they run before the line-space box test on every node, and on each triangle the rays do not
  // accept before its exact query. They only ever hide (docs/theory.md §5.8).
  std::optional<SingleOccluderCulling> proofs;
  if (options.occluder_proofs) proofs.emplace(context, cell);
  const bool use_proofs = proofs && proofs->any();
  // `hint` (null: no single-occluder proofs) is the wall of the last proof nearby.
  auto decide = [&](std::size_t i, std::ptrdiff_t* hint) {
    const auto t = static_cast<std::int64_t>(i);
    TriangleAnswer& a = answers[i];
    if (use_back_faces && back_faces->hides_triangle(t)) {
      a.by_occluder = a.by_back_face = true;
      const std::int64_t d = decided.fetch_add(1) + 1;
      if (options.on_progress) options.on_progress(d);
      return;
    }
    std::mt19937_64 rng(mix_seed(options.query.seed, i));
    if (!neighbour.empty() && neighbour[i])
      for (Witness& w : neighbour_proposals(*neighbour[i], cell, approx, previous->cell))
        if (is_robust_cell_witness(context, cell, t, w)) {
          a.visible = a.by_rays = a.by_neighbour = true;
          a.witness = std::move(w);
          break;
        }
    if (a.by_neighbour) {
    } else if (auto w = ray_witness(context, cell, approx, t, options.rays, rng)) {
      a.visible = a.by_rays = true;
      a.witness = std::move(w);
    } else if (hint && proofs->hides_triangle(t, *hint)) {
      a.by_occluder = true;
    } else {
      VisibilityResult r = visible_from_box(scene, finder, cell, t, options.query);
      a.visible = r.visible;
      a.witness = std::move(r.witness);
      a.stats = r.stats;
      a.stats.exact_evaluations = 0;  // a process-wide counter: not deterministic under threads
    }
    const std::int64_t d = decided.fetch_add(1) + 1;
    if (options.on_progress) options.on_progress(d);
  };
  // The hierarchy (docs/theory.md §5.7): a node whose box is proved hidden with respect to the triangles
  // outside its subtree hides all its triangles; the others are decided one by one as above.
  const TriangleBvh& bvh = context.bvh();
  std::vector<char> culled(n, 0);
  std::mutex box_stats_mutex;
  VisibilityStats box_stats;
  std::int64_t boxes_tested = 0, boxes_culled = 0, boxes_given_up = 0;
  auto box_reached_by_rays = [&](const BvhNode& node, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int r = 0; r < options.box_rays; ++r) {
      // From a random point of the cell to a random point of a random triangle of the subtree.
      Point3 p;
      for (int k = 0; k < 3; ++k) p[k] = approx.lo[k] + unit(rng) * (approx.hi[k] - approx.lo[k]);
      const auto& t = scene.triangles[bvh.order[node.begin + static_cast<int>(rng() % (node.end - node.begin))]];
      double a = unit(rng), b = unit(rng);
      if (a + b > 1) a = 1 - a, b = 1 - b;
      Point3 x;
      for (int k = 0; k < 3; ++k)
        x[k] = scene.corner(t, 0)[k] + a * (scene.corner(t, 1)[k] - scene.corner(t, 0)[k]) +
               b * (scene.corner(t, 2)[k] - scene.corner(t, 0)[k]);
      const glm::vec3 origin(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
      const glm::vec3 dir(static_cast<float>(x.x - p.x), static_cast<float>(x.y - p.y), static_cast<float>(x.z - p.z));
      const FloatRayCaster::Hit hit = context.rays().first_hit(origin, dir, 0.0f, 1.001f);
      // The first hit inside the subtree, or none: the ray probably reaches a triangle of the subtree, so the
      // exact test would fail: descend without it (descending is always sound).
      if (hit.triangle_index < 0) return true;
      const int pos = bvh.position[hit.triangle_index];
      if (pos >= node.begin && pos < node.end) return true;
    }
    // Rays to the box's faces: from a random point p of the cell to a random point x of a face whose outer
    // open half-space holds p (so [p, x) lies outside the box); if nothing is hit before x, lines from the cell
    // reach the box there, the exact test would most likely find them (it fails): descend without it.
    const Box3& b = node.box;
    for (int r = 0; r < options.box_face_rays; ++r) {
      Point3 p;
      for (int k = 0; k < 3; ++k) p[k] = approx.lo[k] + unit(rng) * (approx.hi[k] - approx.lo[k]);
      std::array<double, 6> area{};
      double total = 0;
      for (int axis = 0; axis < 3; ++axis)
        for (int high = 0; high < 2; ++high) {
          const bool outside = high ? p[axis] > b.hi[axis] : p[axis] < b.lo[axis];
          if (!outside) continue;
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          area[static_cast<std::size_t>(2 * axis + high)] = (b.hi[u] - b.lo[u]) * (b.hi[v] - b.lo[v]);
          total += area[static_cast<std::size_t>(2 * axis + high)];
        }
      if (!(total > 0)) continue;
      double pick = unit(rng) * total;
      int face = -1;  // by area; the last face with area when rounding leaves `pick` over
      for (int f = 0; f < 6; ++f) {
        if (area[static_cast<std::size_t>(f)] == 0) continue;
        face = f;
        if (pick < area[static_cast<std::size_t>(f)]) break;
        pick -= area[static_cast<std::size_t>(f)];
      }
      const int axis = face / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
      Point3 x;
      x[axis] = face % 2 ? b.hi[axis] : b.lo[axis];
      x[u] = b.lo[u] + unit(rng) * (b.hi[u] - b.lo[u]);
      x[v] = b.lo[v] + unit(rng) * (b.hi[v] - b.lo[v]);
      const glm::vec3 origin(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
      const glm::vec3 dir(static_cast<float>(x.x - p.x), static_cast<float>(x.y - p.y), static_cast<float>(x.z - p.z));
      if (!context.rays().occluded(origin, dir, 0.0f, 0.999f)) return true;
    }
    return false;
  };
  auto box_hidden = [&](int index) {
    const BvhNode& node = bvh.nodes[index];
    if (node.end - node.begin < std::max(1, options.min_cull) || boxes_meet(cell, node.box)) return false;
    std::mt19937_64 rng(mix_seed(options.query.seed, n + static_cast<std::uint64_t>(index)));
    if (box_reached_by_rays(node, rng)) return false;
    // Occluders: every triangle outside the subtree (any of the subtree's triangles could be the target).
    // Gathered per shaft through the hierarchy, as in the triangle queries.
    std::vector<RationalPoint3> corners{cell.lo, cell.hi, to_rational(node.box.lo), to_rational(node.box.hi)};
    const HierarchyCandidates outside{context.index(), &scene, &bvh, [&bvh, &node](std::int64_t t) {
                                        const int pos = bvh.position[t];
                                        return pos >= node.begin && pos < node.end;
                                      },
                                      panels, options.merge_panels, drop_back_faces};
    VisibilityStats stats;
    VisibilityOptions box_options = options.query;
    box_options.split_budget = static_cast<std::int64_t>(std::max(0, options.box_splits_per_triangle)) *
                               (node.end - node.begin);
    const BoxReach reach =
        box_may_be_visible(scene, outside, enclosing_box(corners), cell, node.box, box_options, stats);
    const bool hidden = !reach.may_be_visible;
    stats.exact_evaluations = 0;
    std::lock_guard lock(box_stats_mutex);
    accumulate(box_stats, stats);
    ++boxes_tested;
    boxes_culled += hidden ? 1 : 0;
    boxes_given_up += reach.gave_up ? 1 : 0;
    return hidden;
  };
  auto cull = [&](const BvhNode& node, char how) {
    for (int i = node.begin; i < node.end; ++i) culled[bvh.order[i]] = how;
    const std::int64_t d = decided.fetch_add(node.end - node.begin) + (node.end - node.begin);
    if (options.on_progress) options.on_progress(d);
  };
  // Front to back from the cell, on this thread only, so that the virtual occluders (boxes proved hidden
  // so far, docs/theory.md §5.8) and every counter are the same for any thread count; the triangles of the
  // leaves are decided by tasks on the other cores meanwhile (they do not feed back into the traversal).
  VirtualOccluders dark(cell, options.virtual_occluders);
  const Point3 cell_centre{approx.lo.x / 2 + approx.hi.x / 2, approx.lo.y / 2 + approx.hi.y / 2,
                           approx.lo.z / 2 + approx.hi.z / 2};
  auto gap = [&](const Box3& b) {  // squared distance from the cell's centre to the box (ordering only)
    double s = 0;
    for (int k = 0; k < 3; ++k) {
      const double g = std::max({b.lo[k] - cell_centre[k], cell_centre[k] - b.hi[k], 0.0});
      s += g * g;
    }
    return s;
  };
  tbb::task_group leaves;
  std::function<void(int, std::ptrdiff_t)> visit = [&](int index, std::ptrdiff_t hint) {
    const BvhNode& node = bvh.nodes[index];
    if (dark.blocks(corners_of(node.box))) return cull(node, 3);
    // A box proved hidden by a wall, a solid or the line-space test becomes a virtual occluder (one blocked
    // by a virtual occluder does not: its shadow lies inside that occluder's).
    if (use_proofs && node.end - node.begin > 1 && proofs->hides_node(node, hint)) {
      dark.add(node.box);
      return cull(node, 2);
    }
    // Every triangle a back face of its solid (early exit at the first that is not): culled without a box
    // test; the box is not dark (it may hold free points in front of the faces), so it is not registered.
    if (use_back_faces && node.end - node.begin > 1) {
      bool all = true;
      for (int i = node.begin; i < node.end && all; ++i) all = back_faces->hides_triangle(bvh.order[i]);
      if (all) return cull(node, 4);
    }
    if (box_hidden(index)) {
      dark.add(node.box);
      return cull(node, 1);
    }
    if (node.left < 0) {
      std::vector<std::size_t> open;
      for (int i = node.begin; i < node.end; ++i) {
        const std::int64_t t = bvh.order[i];
        const SceneTriangle& tri = scene.triangles[t];
        const std::array<Point3, 3> corners{scene.corner(tri, 0), scene.corner(tri, 1), scene.corner(tri, 2)};
        if (dark.blocks(corners)) {
          culled[t] = 3;
          const std::int64_t d = decided.fetch_add(1) + 1;
          if (options.on_progress) options.on_progress(d);
        } else {
          open.push_back(static_cast<std::size_t>(t));
        }
      }
      auto run = [&decide, use_proofs, open = std::move(open), hint] {
        std::ptrdiff_t h = hint;  // the leaf's own copy, as in the sequential order
        for (const std::size_t t : open) decide(t, use_proofs ? &h : nullptr);
      };
      if (options.threads == 1) run();
      else leaves.run(std::move(run));
      return;
    }
    // Nearer child first: what it proves hidden shadows the farther one.
    const bool swap = gap(bvh.nodes[node.right].box) < gap(bvh.nodes[node.left].box);
    visit(swap ? node.right : node.left, hint);
    visit(swap ? node.left : node.right, hint);
  };
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  if (options.hierarchy && !bvh.nodes.empty())
    arena.execute([&] {
      visit(0, -1);
      leaves.wait();
    });
  else
    arena.execute([&] {
      for_each_index(n, options.threads != 1, 4, [&](std::size_t i) {
        std::ptrdiff_t hint = -1;
        decide(i, use_proofs ? &hint : nullptr);
      });
    });

  CellPvs out;
  out.cell = cell;
  out.stats.triangles = static_cast<std::int64_t>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const TriangleAnswer& a = answers[i];
    if (culled[i] || a.by_occluder) ++out.stats.culled;
    if (culled[i] == 2 || culled[i] == 4 || a.by_occluder) ++out.stats.culled_by_occluders;
    if (culled[i] == 3) ++out.stats.culled_by_virtual;
    if (culled[i] == 4 || a.by_back_face) ++out.stats.culled_by_back_faces;
    if (culled[i] || a.by_occluder) continue;
    if (a.by_neighbour) ++out.stats.neighbour_hits;
    if (a.by_rays) ++out.stats.accepted_by_rays;
    else {
      ++out.stats.exact_queries;
      accumulate(out.stats.query, a.stats);
    }
    if (a.visible) out.visible.push_back({static_cast<std::int64_t>(i), a.witness});
  }
  out.stats.visible = static_cast<std::int64_t>(out.visible.size());
  if (previous)
    for (std::size_t i = 0; i < n; ++i) out.stats.neighbour_tries += neighbour[i] && !culled[i] ? 1 : 0;
  out.stats.boxes_tested = boxes_tested;
  out.stats.boxes_culled = boxes_culled;
  out.stats.boxes_given_up = boxes_given_up;
  out.stats.virtual_occluders = dark.added();
  out.stats.virtual_tests = dark.exact_tests();
  accumulate(out.stats.query, box_stats);
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace exactvis::region
