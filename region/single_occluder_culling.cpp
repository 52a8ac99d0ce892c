#include "region/single_occluder_culling.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

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

SingleOccluderCulling::SingleOccluderCulling(const PvsContext& context, const RationalBox3& cell, OccluderSearch search)
    : context_(context), cell_(cell), approx_(approximate_box(cell)), search_(search) {
  const std::vector<WallRectangle>& walls = context.extruded().walls;
  // The walls that can hide anything from this cell (cell strictly on one side, spanning its heights),
  // nearest first: a near wall has the widest umbra.
  prepared_.resize(walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w) {
    prepared_[w] = prepare_wall(walls[w], approx_);
    if (prepared_[w].usable) usable_walls_.push_back(w);
  }
  const double cx = 0.5 * (approx_.lo.x + approx_.hi.x), cy = 0.5 * (approx_.lo.y + approx_.hi.y);
  std::vector<double> distance(walls.size(), 0);
  for (const std::size_t w : usable_walls_) {
    const WallRectangle& r = walls[w];
    // Distance from the cell's centre to the wall's segment (ordering only).
    const double dx = r.bx - r.ax, dy = r.by - r.ay, len2 = dx * dx + dy * dy;
    const double s = len2 > 0 ? std::clamp(((cx - r.ax) * dx + (cy - r.ay) * dy) / len2, 0.0, 1.0) : 0.0;
    distance[w] = std::hypot(cx - (r.ax + s * dx), cy - (r.ay + s * dy));
  }
  std::stable_sort(usable_walls_.begin(), usable_walls_.end(),
                   [&](std::size_t a, std::size_t b) { return distance[a] < distance[b]; });

  // Pairs of usable walls whose footprints share an endpoint and that do not lie on one line (building
  // corners, adjacent facades): umbra fusion of two walls (wall_pair_hides_exactly), tried after every single
  // wall fails; nearest first. Collinear neighbours are skipped: merged runs cover them.
  {
    std::map<std::pair<double, double>, std::vector<std::size_t>> at_end;
    for (const std::size_t w : usable_walls_) {
      at_end[{walls[w].ax, walls[w].ay}].push_back(w);
      at_end[{walls[w].bx, walls[w].by}].push_back(w);
    }
    links_.resize(walls.size());
    for (const auto& [end, list] : at_end)
      for (std::size_t i = 0; i < list.size(); ++i)
        for (std::size_t j = i + 1; j < list.size(); ++j) {
          const WallRectangle &u = walls[list[i]], &v = walls[list[j]];
          links_[list[i]].push_back(list[j]), links_[list[j]].push_back(list[i]);
          if ((u.bx - u.ax) * (v.by - v.ay) - (u.by - u.ay) * (v.bx - v.ax) == 0) continue;  // a proposal only
          corner_pairs_.push_back({list[i], list[j]});
        }
    std::stable_sort(corner_pairs_.begin(), corner_pairs_.end(), [&](const auto& x, const auto& y) {
      return std::min(distance[x.first], distance[x.second]) < std::min(distance[y.first], distance[y.second]);
    });
  }
  if (search_ == OccluderSearch::grid) {
    partners_.resize(walls.size());
    for (const auto& [w, u] : corner_pairs_) partners_[w].push_back(u), partners_[u].push_back(w);
    std::vector<Box3> footprints;
    footprints.reserve(usable_walls_.size());
    for (const std::size_t w : usable_walls_) {
      const WallRectangle& r = walls[w];
      footprints.push_back({{std::min(r.ax, r.bx), std::min(r.ay, r.by), r.z_lo}, {std::max(r.ax, r.bx), std::max(r.ay, r.by), r.z_hi}});
    }
    wall_grid_ = FootprintGrid(footprints);
  }

  // The closed convex solids strictly apart from the cell, nearest first. solid_blocks_box_pair itself proves
  // both boxes disjoint from the closed solid (so the segment meets the surface inside, never only at its end
  // on the target); strictly_apart is a cheaper pre-test of the same kind that skips solids which cannot
  // qualify before its 64 segment tests.
  const std::vector<ConvexSolid>& solids = context.solids();
  for (std::size_t k = 0; k < solids.size(); ++k)
    if (strictly_apart(cell, solids[k])) usable_solids_.push_back(k);
  const Point3 cell_centre = centre(approx_);
  auto box_distance = [&](std::size_t k) {
    const Point3 c = centre(solids[k].box);
    return std::hypot(c.x - cell_centre.x, c.y - cell_centre.y, c.z - cell_centre.z);
  };
  std::stable_sort(usable_solids_.begin(), usable_solids_.end(),
                   [&](std::size_t a, std::size_t b) { return box_distance(a) < box_distance(b); });
  if (search_ == OccluderSearch::grid) {
    std::vector<Box3> boxes;
    boxes.reserve(usable_solids_.size());
    for (const std::size_t k : usable_solids_) boxes.push_back(solids[k].box);
    solid_grid_ = FootprintGrid(boxes);
    solid_filter_ = SolidMissFilter(solids, usable_solids_, cell);
  }
}

bool SingleOccluderCulling::try_pair(std::size_t w, std::size_t u, const UmbraTarget& target) const {
  const std::vector<WallRectangle>& walls = context_.extruded().walls;
  if (!wall_pair_may_hide(walls[w], prepared_[w], walls[u], prepared_[u], approx_, target)) return false;
  exact_tests_.fetch_add(1, std::memory_order_relaxed);
  return wall_pair_hides_exactly(walls[w], walls[u], cell_, target);
}

bool SingleOccluderCulling::try_chains(const std::vector<std::size_t>& candidates, const UmbraTarget& target) const {
  const std::vector<WallRectangle>& walls = context_.extruded().walls;
  std::vector<std::size_t> members;
  for (const std::size_t w : candidates)
    if (wall_may_join_chain(walls[w], prepared_[w], approx_, target)) members.push_back(w);
  if (members.size() < 2) return false;
  std::sort(members.begin(), members.end());
  std::vector<std::size_t> parent(members.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  auto position = [&](std::size_t w) {
    const auto it = std::lower_bound(members.begin(), members.end(), w);
    return it != members.end() && *it == w ? static_cast<std::ptrdiff_t>(it - members.begin()) : std::ptrdiff_t{-1};
  };
  std::vector<std::pair<std::size_t, std::size_t>> links;  // (member position, member position)
  for (std::size_t i = 0; i < members.size(); ++i)
    for (const std::size_t u : links_[members[i]]) {
      const std::ptrdiff_t j = position(u);
      if (j <= static_cast<std::ptrdiff_t>(i)) continue;  // not a member, or counted from the other end
      links.push_back({i, static_cast<std::size_t>(j)});
      parent[find(i)] = find(static_cast<std::size_t>(j));
    }
  // View-overlap links (the exact test proves them): from the target's centre, each member's footprint spans
  // an interval of directions (measured from the direction to the cell's centre, so no interval wraps);
  // sweeping them by their start proposes links between overlapping arcs (checked in doubles here, exactly later).
  {
    double tx = 0, ty = 0;
    for (const Point3& p : target.points) tx += p.x, ty += p.y;
    tx /= static_cast<double>(target.points.size()), ty /= static_cast<double>(target.points.size());
    const double rx = 0.5 * (approx_.lo.x + approx_.hi.x) - tx, ry = 0.5 * (approx_.lo.y + approx_.hi.y) - ty;
    auto angle = [&](double x, double y) { return std::atan2(rx * (y - ty) - ry * (x - tx), rx * (x - tx) + ry * (y - ty)); };
    struct Arc {
      double lo, hi;
      std::size_t member;
    };
    std::vector<Arc> arcs;
    for (std::size_t i = 0; i < members.size(); ++i) {
      const WallRectangle& w = walls[members[i]];
      const double a = angle(w.ax, w.ay), b = angle(w.bx, w.by);
      arcs.push_back({std::min(a, b), std::max(a, b), i});
    }
    std::sort(arcs.begin(), arcs.end(), [](const Arc& x, const Arc& y) { return x.lo < y.lo || (x.lo == y.lo && x.member < y.member); });
    // Sweep by start; each arc is linked to the (at most 4) open arcs reaching farthest that pass the double
    // view-overlap test from the whole cell and target (a bounded number of proposals per wall).
    std::vector<std::size_t> open;  // indices into arcs, by decreasing hi
    for (std::size_t k = 0; k < arcs.size(); ++k) {
      while (!open.empty() && arcs[open.back()].hi < arcs[k].lo) open.pop_back();
      int proposed = 0;
      for (std::size_t o = 0; o < open.size() && proposed < 4; ++o) {
        if (arcs[open[o]].hi < arcs[k].lo) continue;
        const std::size_t i = arcs[open[o]].member, j = arcs[k].member;
        if (find(i) == find(j)) continue;
        ++proposed;
        if (!walls_views_may_overlap(walls[members[i]], walls[members[j]], approx_, target)) continue;
        links.push_back({std::min(i, j), std::max(i, j)});
        parent[find(i)] = find(j);
      }
      open.insert(std::upper_bound(open.begin(), open.end(), k, [&](std::size_t a, std::size_t b) { return arcs[a].hi > arcs[b].hi; }), k);
    }
  }
  // Group members and links by component (deterministic: by the smallest member of each).
  std::map<std::size_t, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < members.size(); ++i) groups[find(i)].push_back(i);
  for (const auto& [root, group] : groups) {
    if (group.size() < 2) continue;  // one wall: tried alone before
    std::vector<WallRectangle> chain;
    std::vector<std::size_t> local(members.size(), 0);
    for (const std::size_t i : group) local[i] = chain.size(), chain.push_back(walls[members[i]]);
    if (!wall_chain_may_cover(chain, approx_, target)) continue;
    std::vector<std::pair<std::size_t, std::size_t>> chain_links;
    for (const auto& [i, j] : links)
      if (find(i) == root) chain_links.push_back({local[i], local[j]});
    exact_tests_.fetch_add(1, std::memory_order_relaxed);
    if (wall_chain_hides_exactly(chain, chain_links, cell_, target)) return true;
  }
  return false;
}

template <class Owns>
bool SingleOccluderCulling::hides(const UmbraTarget& target, const Box3& target_box, const Owns& owns_triangle_of,
                                  std::ptrdiff_t& hint) const {
  const std::vector<WallRectangle>& walls = context_.extruded().walls;
  auto attempt = [&](std::size_t w) {
    if (!wall_may_hide(walls[w], prepared_[w], approx_, target)) return false;
    exact_tests_.fetch_add(1, std::memory_order_relaxed);
    return wall_hides_exactly(walls[w], cell_, target);
  };
  if (hint >= 0 && attempt(static_cast<std::size_t>(hint))) return true;
  const Point3 cell_centre = centre(approx_), target_centre = centre(target_box);
  if (search_ == OccluderSearch::scan) {
    for (const std::size_t w : usable_walls_)
      if (static_cast<std::ptrdiff_t>(w) != hint && attempt(w)) {
        hint = static_cast<std::ptrdiff_t>(w);
        return true;
      }
    for (const auto& [w, u] : corner_pairs_)
      if (try_pair(w, u, target)) return true;
    if (try_chains(usable_walls_, target)) return true;
  } else if (!usable_walls_.empty()) {
    // Only walls whose footprint meets the top view of conv(cell's footprint ∪ target points) can pass
    // condition (ii) (every corner-to-point segment lies in that hull); the grid lists at least those.
    std::vector<XyPoint> hull{{approx_.lo.x, approx_.lo.y}, {approx_.hi.x, approx_.lo.y}, {approx_.lo.x, approx_.hi.y}, {approx_.hi.x, approx_.hi.y}};
    for (const Point3& p : target.points) hull.push_back({p.x, p.y});
    std::vector<std::size_t> tried;
    std::size_t proved = 0;
    if (wall_grid_.visit_hull(hull, {cell_centre.x, cell_centre.y}, [&](std::size_t k) {
          const std::size_t w = usable_walls_[k];
          tried.push_back(w);
          if (static_cast<std::ptrdiff_t>(w) == hint || !attempt(w)) return false;
          proved = w;
          return true;
        })) {
      hint = static_cast<std::ptrdiff_t>(proved);
      return true;
    }
    // A pair with neither wall listed cannot pass (ii'): no corner-to-point segment meets either footprint.
    // Every pair with a listed wall is tried, once (both listed: from the smaller wall index).
    std::vector<std::size_t> listed(tried);
    std::sort(listed.begin(), listed.end());
    for (const std::size_t w : tried)
      for (const std::size_t u : partners_[w])
        if ((u > w || !std::binary_search(listed.begin(), listed.end(), u)) && try_pair(w, u, target)) return true;
    // A chain member must have a footprint some corner-to-point segment crosses, so it meets the hull: listed.
    if (try_chains(tried, target)) return true;
  }
  if (usable_solids_.empty()) return false;
  const std::vector<ConvexSolid>& solids = context_.solids();
  std::optional<RationalBox3> exact_target;
  auto try_solid = [&](std::size_t k) {
    const ConvexSolid& solid = solids[k];
    if (!segment_near_box(cell_centre, target_centre, solid.box)) return false;
    if (!exact_target) exact_target = exact_box(target_box);
    if (!strictly_apart(*exact_target, solid) || owns_triangle_of(solid)) return false;
    // A corner-to-corner segment proved (intervals) to miss the solid: the exact test would fail (grid only:
    // the scan stays the unfiltered reference the tests compare with).
    if (search_ == OccluderSearch::grid && solid_filter_.proves_miss(k, target_box)) return false;
    exact_tests_.fetch_add(1, std::memory_order_relaxed);
    return solid_blocks_box_pair(solid, cell_, *exact_target);
  };
  if (search_ == OccluderSearch::scan) {
    for (const std::size_t k : usable_solids_)
      if (try_solid(k)) return true;
    return false;
  }
  // segment_near_box needs the solid's box to meet the centre segment, hence its xy box the segment's top view.
  return solid_grid_.visit_hull({{cell_centre.x, cell_centre.y}, {target_centre.x, target_centre.y}},
                                {cell_centre.x, cell_centre.y}, [&](std::size_t k) { return try_solid(usable_solids_[k]); });
}

bool SingleOccluderCulling::hides_triangle(std::int64_t triangle, std::ptrdiff_t& hint) const {
  const Scene& scene = context_.scene();
  const SceneTriangle& t = scene.triangles[static_cast<std::size_t>(triangle)];
  auto owns = [&](const ConvexSolid& solid) {
    return std::binary_search(solid.triangles.begin(), solid.triangles.end(), triangle);
  };
  return hides(triangle_target(scene, t), triangle_box(scene, t), owns, hint);
}

bool SingleOccluderCulling::hides_node(const BvhNode& node, std::ptrdiff_t& hint) const {
  const TriangleBvh& bvh = context_.bvh();
  auto owns = [&](const ConvexSolid& solid) {
    return std::any_of(solid.triangles.begin(), solid.triangles.end(), [&](std::int64_t t) {
      const int pos = bvh.position[static_cast<std::size_t>(t)];
      return pos >= node.begin && pos < node.end;
    });
  };
  return hides(box_target(node.box), node.box, owns, hint);
}

}  // namespace exactvis::region
