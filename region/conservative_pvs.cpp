#include "region/conservative_pvs.hpp"

#include "region/cell_visibility.hpp"
#include "region/wall_umbra.hpp"
#include "util/for_each_index.hpp"

#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

namespace exactvis::region {
namespace {

UmbraTarget box_target(const Box3& b) {
  return {{Point3{b.lo.x, b.lo.y, 0}, Point3{b.hi.x, b.lo.y, 0}, Point3{b.lo.x, b.hi.y, 0}, Point3{b.hi.x, b.hi.y, 0}},
          b.lo.z, b.hi.z};
}

UmbraTarget triangle_target(const Scene& scene, const SceneTriangle& t) {
  UmbraTarget u;
  u.z_lo = u.z_hi = scene.corner(t, 0).z;
  for (int k = 0; k < 3; ++k) {
    u.points.push_back(scene.corner(t, k));
    u.z_lo = std::min(u.z_lo, scene.corner(t, k).z);
    u.z_hi = std::max(u.z_hi, scene.corner(t, k).z);
  }
  return u;
}

// Exact: the closed box b and the solid's bounding box are strictly apart on some axis (so b misses the
// closed solid).
bool strictly_apart(const RationalBox3& b, const ConvexSolid& solid) {
  for (int k = 0; k < 3; ++k)
    if (b.hi[k] < Exact(solid.box.lo[k]) || b.lo[k] > Exact(solid.box.hi[k])) return true;
  return false;
}

// Doubles, a proposal only: does the segment between the two points pass through the box (slab test)?
bool segment_near_box(const Point3& p, const Point3& q, const Box3& box) {
  double t0 = 0, t1 = 1;
  for (int k = 0; k < 3; ++k) {
    const double d = q[k] - p[k];
    if (d == 0) {
      if (p[k] < box.lo[k] || p[k] > box.hi[k]) return false;
      continue;
    }
    double a = (box.lo[k] - p[k]) / d, b = (box.hi[k] - p[k]) / d;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

Point3 centre(const Box3& b) { return {0.5 * (b.lo.x + b.hi.x), 0.5 * (b.lo.y + b.hi.y), 0.5 * (b.lo.z + b.hi.z)}; }

}  // namespace

CellPvs conservative_cell_pvs(const PvsContext& context, const RationalBox3& cell, const PvsOptions& options) {
  check_view_cell(cell);
  check_thread_count(options.threads);
  const auto start = std::chrono::steady_clock::now();
  const Scene& scene = context.scene();
  const std::size_t n = scene.triangles.size();
  const std::vector<WallRectangle>& walls = context.extruded().walls;
  const Box3 approx = approximate_box(cell);

  // The walls that can hide anything from this cell (cell strictly on one side, spanning its heights),
  // nearest first: a near wall has the widest umbra.
  std::vector<WallFromCell> prepared(walls.size());
  std::vector<std::size_t> usable;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    prepared[w] = prepare_wall(walls[w], approx);
    if (prepared[w].usable) usable.push_back(w);
  }
  const double cx = 0.5 * (approx.lo.x + approx.hi.x), cy = 0.5 * (approx.lo.y + approx.hi.y);
  std::vector<double> distance(walls.size(), 0);
  for (const std::size_t w : usable) {
    const WallRectangle& r = walls[w];
    // Distance from the cell's centre to the wall's segment (ordering only).
    const double dx = r.bx - r.ax, dy = r.by - r.ay, len2 = dx * dx + dy * dy;
    const double s = len2 > 0 ? std::clamp(((cx - r.ax) * dx + (cy - r.ay) * dy) / len2, 0.0, 1.0) : 0.0;
    distance[w] = std::hypot(cx - (r.ax + s * dx), cy - (r.ay + s * dy));
  }
  std::stable_sort(usable.begin(), usable.end(), [&](std::size_t a, std::size_t b) { return distance[a] < distance[b]; });

  // Pairs of usable walls whose footprints share an endpoint and that do not lie on one line (building
  // corners, adjacent facades): umbra fusion across walls (wall_pair_hides_exactly), tried when no single
  // wall proves a target hidden; nearest first.
  std::vector<std::pair<std::size_t, std::size_t>> corner_pairs;
  {
    std::map<std::pair<double, double>, std::vector<std::size_t>> at_end;
    for (const std::size_t w : usable) {
      at_end[{walls[w].ax, walls[w].ay}].push_back(w);
      at_end[{walls[w].bx, walls[w].by}].push_back(w);
    }
    for (const auto& [end, list] : at_end)
      for (std::size_t i = 0; i < list.size(); ++i)
        for (std::size_t j = i + 1; j < list.size(); ++j) {
          const WallRectangle &u = walls[list[i]], &v = walls[list[j]];
          const double dux = u.bx - u.ax, duy = u.by - u.ay, dvx = v.bx - v.ax, dvy = v.by - v.ay;
          if (dux * dvy - duy * dvx == 0) continue;  // (nearly) one line: merged runs cover it; a proposal only
          corner_pairs.push_back({list[i], list[j]});
        }
    std::stable_sort(corner_pairs.begin(), corner_pairs.end(), [&](const auto& x, const auto& y) {
      return std::min(distance[x.first], distance[x.second]) < std::min(distance[y.first], distance[y.second]);
    });
  }

  // The closed convex solids strictly apart from the cell (single-occluder culling, region/convex_occluder),
  // nearest first. solid_blocks_box_pair itself proves both boxes disjoint from the closed solid (so the
  // segment meets the surface inside, never only at its end on the target); strictly_apart is a cheaper
  // pre-test of the same kind that skips solids which cannot qualify before its 64 segment tests.
  const std::vector<ConvexSolid>& solids = context.solids();
  std::vector<std::size_t> usable_solids;
  for (std::size_t k = 0; k < solids.size(); ++k)
    if (strictly_apart(cell, solids[k])) usable_solids.push_back(k);
  const Point3 cell_centre = centre(approx);
  auto box_distance = [&](std::size_t k) {
    const Point3 c = centre(solids[k].box);
    return std::hypot(c.x - cell_centre.x, c.y - cell_centre.y, c.z - cell_centre.z);
  };
  std::stable_sort(usable_solids.begin(), usable_solids.end(),
                   [&](std::size_t a, std::size_t b) { return box_distance(a) < box_distance(b); });

  std::atomic<std::int64_t> exact_tests{0}, nodes_tested{0}, nodes_hidden{0};
  // A proof that the target (its top-view points and heights, its box, and which solids contain one of its
  // triangles) is hidden by one wall or one solid: `hint` (the wall of the last proof nearby) first.
  auto hidden = [&](const UmbraTarget& target, const Box3& target_box, const auto& owns_triangle_of,
                    std::ptrdiff_t& hint) {
    auto attempt = [&](std::size_t w) {
      if (!wall_may_hide(walls[w], prepared[w], approx, target)) return false;
      exact_tests.fetch_add(1, std::memory_order_relaxed);
      return wall_hides_exactly(walls[w], cell, target);
    };
    if (hint >= 0 && attempt(static_cast<std::size_t>(hint))) return true;
    for (const std::size_t w : usable)
      if (static_cast<std::ptrdiff_t>(w) != hint && attempt(w)) {
        hint = static_cast<std::ptrdiff_t>(w);
        return true;
      }
    for (const auto& [w, u] : corner_pairs) {
      if (!wall_pair_may_hide(walls[w], prepared[w], walls[u], prepared[u], approx, target)) continue;
      exact_tests.fetch_add(1, std::memory_order_relaxed);
      if (wall_pair_hides_exactly(walls[w], walls[u], cell, target)) return true;
    }
    if (usable_solids.empty()) return false;
    const Point3 target_centre = centre(target_box);
    std::optional<RationalBox3> exact_target;
    for (const std::size_t k : usable_solids) {
      const ConvexSolid& solid = solids[k];
      if (!segment_near_box(cell_centre, target_centre, solid.box)) continue;
      if (!exact_target) exact_target = exact_box(target_box);
      if (!strictly_apart(*exact_target, solid) || owns_triangle_of(solid)) continue;
      exact_tests.fetch_add(1, std::memory_order_relaxed);
      if (solid_blocks_box_pair(solid, cell, *exact_target)) return true;
    }
    return false;
  };

  std::vector<char> culled(n, 0);
  std::atomic<std::int64_t> decided{0};
  auto report = [&](std::int64_t k) {
    const std::int64_t d = decided.fetch_add(k) + k;
    if (options.on_progress) options.on_progress(d);
  };
  auto decide_triangle = [&](std::size_t i, std::ptrdiff_t& hint) {
    const SceneTriangle& t = scene.triangles[i];
    auto owns = [&](const ConvexSolid& solid) {
      return std::binary_search(solid.triangles.begin(), solid.triangles.end(), static_cast<std::int64_t>(i));
    };
    if (hidden(triangle_target(scene, t), triangle_box(scene, t), owns, hint)) culled[i] = 1;
    report(1);
  };
  const TriangleBvh& bvh = context.bvh();
  std::function<void(int, std::ptrdiff_t)> visit = [&](int index, std::ptrdiff_t hint) {
    const BvhNode& node = bvh.nodes[static_cast<std::size_t>(index)];
    if (node.end - node.begin > 1) {
      nodes_tested.fetch_add(1, std::memory_order_relaxed);
      auto owns = [&](const ConvexSolid& solid) {
        return std::any_of(solid.triangles.begin(), solid.triangles.end(), [&](std::int64_t t) {
          const int pos = bvh.position[static_cast<std::size_t>(t)];
          return pos >= node.begin && pos < node.end;
        });
      };
      if (hidden(box_target(node.box), node.box, owns, hint)) {
        nodes_hidden.fetch_add(1, std::memory_order_relaxed);
        for (int i = node.begin; i < node.end; ++i) culled[static_cast<std::size_t>(bvh.order[static_cast<std::size_t>(i)])] = 1;
        report(node.end - node.begin);
        return;
      }
    }
    if (node.left < 0) {
      for (int i = node.begin; i < node.end; ++i) decide_triangle(static_cast<std::size_t>(bvh.order[static_cast<std::size_t>(i)]), hint);
      return;
    }
    if (options.threads == 1) {
      visit(node.left, hint);
      visit(node.right, hint);
    } else {
      tbb::parallel_invoke([&] { visit(node.left, hint); }, [&] { visit(node.right, hint); });
    }
  };
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  if (!usable.empty() || !usable_solids.empty()) {
    if (options.hierarchy && !bvh.nodes.empty()) arena.execute([&] { visit(0, -1); });
    else
      arena.execute([&] {
        for_each_index(n, options.threads != 1, 16, [&](std::size_t i) {
          std::ptrdiff_t hint = -1;
          decide_triangle(i, hint);
        });
      });
  }

  CellPvs out;
  out.cell = cell;
  out.stats.triangles = static_cast<std::int64_t>(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (culled[i]) ++out.stats.culled;
    else out.visible.push_back({static_cast<std::int64_t>(i), std::nullopt});
  }
  out.stats.visible = static_cast<std::int64_t>(out.visible.size());
  out.stats.exact_queries = exact_tests.load();
  out.stats.boxes_tested = nodes_tested.load();
  out.stats.boxes_culled = nodes_hidden.load();
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace exactvis::region
