#include "region/extruded_scene.hpp"

#include "kernel/predicates.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

namespace exactvis::region {
namespace {

using Key = std::tuple<double, double, double, double, double, double>;

Key key_of(const WallRectangle& w) { return {w.ax, w.ay, w.bx, w.by, w.z_lo, w.z_hi}; }

bool xy_less(double ax, double ay, double bx, double by) { return ax < bx || (ax == bx && ay < by); }

// Exact: is (cx, cy) on the line through a and b (2D)?
bool collinear_xy(double ax, double ay, double bx, double by, double cx, double cy) {
  return orient2d_projected(Point3{ax, ay, 0}, Point3{bx, by, 0}, Point3{cx, cy, 0}, 2) == Sign::Zero;
}

// Maximal runs (length >= 2) of rectangles joined end to end: along their common line with equal z range
// (horizontal = true), or stacked on a common footprint (horizontal = false). absorbed[i] is set for every
// member of a run (a run contains its members, so they are no longer needed as occluders).
std::vector<WallRectangle> merged_runs(const std::vector<WallRectangle>& rects, bool horizontal,
                                       std::vector<char>& absorbed) {
  absorbed.assign(rects.size(), 0);
  // Where a rectangle can start: its "head" key; a successor of r is s with head(s) = tail(r).
  using Head = std::tuple<double, double, double, double, double>;
  auto head = [&](const WallRectangle& w) {
    return horizontal ? Head{w.ax, w.ay, w.z_lo, w.z_hi, 0} : Head{w.ax, w.ay, w.bx, w.by, w.z_lo};
  };
  auto tail = [&](const WallRectangle& w) {
    return horizontal ? Head{w.bx, w.by, w.z_lo, w.z_hi, 0} : Head{w.ax, w.ay, w.bx, w.by, w.z_hi};
  };
  std::multimap<Head, std::size_t> by_head;
  for (std::size_t i = 0; i < rects.size(); ++i) by_head.emplace(head(rects[i]), i);
  auto successor = [&](std::size_t r) -> std::ptrdiff_t {
    const auto [lo, hi] = by_head.equal_range(tail(rects[r]));
    for (auto it = lo; it != hi; ++it) {
      const WallRectangle& s = rects[it->second];
      if (!horizontal || collinear_xy(rects[r].ax, rects[r].ay, rects[r].bx, rects[r].by, s.bx, s.by))
        return static_cast<std::ptrdiff_t>(it->second);
    }
    return -1;
  };
  std::vector<std::ptrdiff_t> next(rects.size());
  std::vector<char> has_pred(rects.size(), 0);
  for (std::size_t i = 0; i < rects.size(); ++i) {
    next[i] = successor(i);
    if (next[i] >= 0) has_pred[static_cast<std::size_t>(next[i])] = 1;
  }
  std::vector<WallRectangle> out;
  std::vector<char> visited(rects.size(), 0);
  for (std::size_t i = 0; i < rects.size(); ++i) {
    if (has_pred[i]) continue;  // chains start at rectangles without a predecessor (cycles are impossible:
                                // lexicographic order along the line, or z, strictly increases)
    WallRectangle run = rects[i];
    std::size_t len = 1;
    visited[i] = 1;
    for (std::ptrdiff_t j = next[i]; j >= 0 && !visited[static_cast<std::size_t>(j)]; j = next[static_cast<std::size_t>(j)]) {
      visited[static_cast<std::size_t>(j)] = 1;
      const WallRectangle& s = rects[static_cast<std::size_t>(j)];
      if (horizontal) run.bx = s.bx, run.by = s.by;
      else run.z_hi = s.z_hi;
      absorbed[static_cast<std::size_t>(j)] = 1;
      ++len;
    }
    if (len >= 2) {
      absorbed[i] = 1;
      out.push_back(run);
    }
  }
  return out;
}

}  // namespace

ExtrudedScene detect_extruded_scene(const Scene& scene) {
  ExtrudedScene out;
  out.is_25d = true;
  auto fail = [&](const SceneTriangle& t, const std::string& why) {
    if (!out.is_25d) return;
    out.is_25d = false;
    out.reason = "triangle id " + std::to_string(t.id) + " " + why;
  };
  // Vertical triangles grouped by their rectangle, with the corner they miss (0..3 = end * 2 + top).
  std::map<Key, std::vector<std::pair<std::size_t, int>>> groups;
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    const SceneTriangle& t = scene.triangles[i];
    const Point3 &p = scene.corner(t, 0), &q = scene.corner(t, 1), &r = scene.corner(t, 2);
    if (p.z == q.z && q.z == r.z) {
      ++out.horizontal;
      continue;
    }
    if (orient2d_projected(p, q, r, 2) != Sign::Zero) {
      fail(t, "is sloped (neither horizontal nor vertical)");
      continue;
    }
    const Point3* c[3] = {&p, &q, &r};
    WallRectangle w;
    w.ax = w.bx = p.x, w.ay = w.by = p.y, w.z_lo = w.z_hi = p.z;
    for (const Point3* v : c) {
      if (xy_less(v->x, v->y, w.ax, w.ay)) w.ax = v->x, w.ay = v->y;
      if (xy_less(w.bx, w.by, v->x, v->y)) w.bx = v->x, w.by = v->y;
      w.z_lo = std::min(w.z_lo, v->z);
      w.z_hi = std::max(w.z_hi, v->z);
    }
    int sum = 0;
    bool corners_ok = true;
    for (const Point3* v : c) {
      const bool at_a = v->x == w.ax && v->y == w.ay, at_b = v->x == w.bx && v->y == w.by;
      const bool low = v->z == w.z_lo, top = v->z == w.z_hi;
      if (!(at_a || at_b) || !(low || top)) corners_ok = false;
      sum += (at_b ? 2 : 0) + (top ? 1 : 0);
    }
    if (!corners_ok) {
      fail(t, "is vertical but not half of a wall rectangle");
      continue;
    }
    groups[key_of(w)].push_back({i, 6 - sum});
  }
  std::vector<WallRectangle> base;
  for (auto& [key, members] : groups) {
    // Pair each triangle with one missing the opposite corner (3 - m).
    std::vector<std::vector<std::size_t>> by_missing(4);
    for (const auto& [tri, m] : members) by_missing[static_cast<std::size_t>(m)].push_back(tri);
    std::size_t paired = 0;
    for (int m : {0, 1}) {
      const std::size_t k = std::min(by_missing[static_cast<std::size_t>(m)].size(), by_missing[static_cast<std::size_t>(3 - m)].size());
      paired += 2 * k;
      for (std::size_t j = k; j < by_missing[static_cast<std::size_t>(m)].size(); ++j)
        fail(scene.triangles[by_missing[static_cast<std::size_t>(m)][j]], "is vertical but has no partner completing its wall rectangle");
      for (std::size_t j = k; j < by_missing[static_cast<std::size_t>(3 - m)].size(); ++j)
        fail(scene.triangles[by_missing[static_cast<std::size_t>(3 - m)][j]], "is vertical but has no partner completing its wall rectangle");
    }
    out.wall_triangles += static_cast<std::int64_t>(paired);
    if (paired > 0) {
      const auto& [ax, ay, bx, by, zl, zh] = key;
      base.push_back({ax, ay, bx, by, zl, zh});
    }
  }
  // Merged runs: along lines, stacked, and each of those merged the other way.
  std::vector<char> abs_h, abs_v, abs_hv, abs_vh;
  const std::vector<WallRectangle> h = merged_runs(base, true, abs_h);
  const std::vector<WallRectangle> v = merged_runs(base, false, abs_v);
  const std::vector<WallRectangle> hv = merged_runs(h, false, abs_hv);
  const std::vector<WallRectangle> vh = merged_runs(v, true, abs_vh);
  std::set<Key> seen;
  auto add = [&](const WallRectangle& w) {
    if (seen.insert(key_of(w)).second) out.walls.push_back(w);
  };
  for (std::size_t i = 0; i < base.size(); ++i)
    if (!abs_h[i] && !abs_v[i]) add(base[i]);
  for (std::size_t i = 0; i < h.size(); ++i)
    if (!abs_hv[i]) add(h[i]);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!abs_vh[i]) add(v[i]);
  for (const auto& w : hv) add(w);
  for (const auto& w : vh) add(w);
  return out;
}

}  // namespace exactvis::region
