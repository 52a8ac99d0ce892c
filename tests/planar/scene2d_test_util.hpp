#pragma once
// Test helpers: oracle scenes (plain doubles) to exactvis Scene2D and back to exact gmpxx points, and the
// random degenerate scene generators shared by the 2D suites (boxes with flat vertices and holes, triangles
// on a small grid).
#include "oracles/visibility2d_oracle.hpp"
#include "planar/scene2d.hpp"

#include <array>
#include <cstdint>
#include <algorithm>
#include <optional>
#include <random>
#include <vector>

namespace exactvis::test2d {

inline std::vector<PolygonInput2D> to_input(const std::vector<oracle2d::Polygon>& scene) {
  std::vector<PolygonInput2D> out;
  for (const auto& poly : scene) {
    PolygonInput2D p;
    for (const auto& ring : poly.rings) {
      std::vector<Point2> r;
      for (const auto& q : ring) r.emplace_back(q[0], q[1]);
      p.rings.push_back(std::move(r));
    }
    out.push_back(std::move(p));
  }
  return out;
}

// The scene if it is valid (random generators may produce self-intersecting stars).
inline std::optional<Scene2D> try_scene(const std::vector<oracle2d::Polygon>& scene) {
  try {
    return make_scene2d(to_input(scene));
  } catch (const Scene2DError&) {
    return std::nullopt;
  }
}

inline oracle2d::Pt to_pt(const Point2& p) { return {mpq_class(p.x.mpq()), mpq_class(p.y.mpq())}; }

// The scene's frame as an extra oracle polygon: a box ring treated as the hole of a bigger box.
inline oracle2d::Polygon frame_polygon(const Scene2D& framed) {
  const Ring2D& r = framed.rings[framed.frame_ring];
  oracle2d::Ring hole;
  double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
  for (int i = 0; i < r.size; ++i) {
    const Point2& p = framed.points[r.first + i];
    hole.push_back({p.ax, p.ay});
    lo_x = std::min(lo_x, p.ax), lo_y = std::min(lo_y, p.ay), hi_x = std::max(hi_x, p.ax), hi_y = std::max(hi_y, p.ay);
  }
  oracle2d::Ring outer{{lo_x - 1, lo_y - 1}, {hi_x + 1, lo_y - 1}, {hi_x + 1, hi_y + 1}, {lo_x - 1, hi_y + 1}};
  return {{outer, hole}};
}

// Axis-parallel box ring.
inline oracle2d::Ring box_ring(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

// Axis-parallel rectangles on a small integer grid, some with flat vertices at edge midpoints (parallel
// and collinear edges everywhere), some with a rectangular hole holding an island.
inline std::vector<oracle2d::Polygon> random_box_scene(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::vector<oracle2d::Polygon> out;
  std::vector<std::array<int, 4>> used;
  for (int tries = 0; tries < 50 && static_cast<int>(out.size()) < count; ++tries) {
    const int x0 = 2 * uni(0, 8), y0 = 2 * uni(0, 8), w = 2 * uni(1, 3), h = 2 * uni(1, 3);
    const std::array<int, 4> r{x0, y0, x0 + w, y0 + h};
    bool clash = false;
    for (const auto& u : used)
      if (r[0] <= u[2] && u[0] <= r[2] && r[1] <= u[3] && u[1] <= r[3]) clash = true;
    if (clash) continue;
    used.push_back(r);
    const int type = uni(0, 3);
    if (type == 0 && w >= 6 && h >= 6) {  // ring with a hole and an island
      out.push_back({{box_ring(r[0], r[1], r[2], r[3]), box_ring(r[0] + 1, r[1] + 1, r[2] - 1, r[3] - 1)}});
      out.push_back({{box_ring(r[0] + 2, r[1] + 2, r[0] + 3, r[1] + 3)}});
    } else if (type == 1) {  // flat vertices at the midpoints
      const double mx = (r[0] + r[2]) / 2.0, my = (r[1] + r[3]) / 2.0;
      out.push_back({{{{double(r[0]), double(r[1])}, {mx, double(r[1])}, {double(r[2]), double(r[1])},
                       {double(r[2]), my}, {double(r[2]), double(r[3])}, {mx, double(r[3])},
                       {double(r[0]), double(r[3])}, {double(r[0]), my}}}});
    } else if (type == 2) {  // an L shape (non-convex)
      out.push_back({{{{double(r[0]), double(r[1])}, {double(r[2]), double(r[1])}, {double(r[2]), r[1] + h / 2.0},
                       {r[0] + w / 2.0, r[1] + h / 2.0}, {r[0] + w / 2.0, double(r[3])},
                       {double(r[0]), double(r[3])}}}});
    } else {
      out.push_back({{box_ring(r[0], r[1], r[2], r[3])}});
    }
  }
  return out;
}

// Triangles with vertices on a 7 x 7 grid: many collinear triples and parallel edges across objects.
inline std::vector<oracle2d::Polygon> random_triangle_scene(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::vector<oracle2d::Polygon> out;
  for (int tries = 0; tries < 200 && static_cast<int>(out.size()) < count; ++tries) {
    oracle2d::Ring t{{double(uni(0, 6)), double(uni(0, 6))}, {double(uni(0, 6)), double(uni(0, 6))},
                     {double(uni(0, 6)), double(uni(0, 6))}};
    auto candidate = out;
    candidate.push_back({{t}});
    if (try_scene(candidate)) out = std::move(candidate);
  }
  return out;
}

// Edges (ids into `scene`) as endpoint pairs, each pair and the list sorted: the form in which
// oracle2d::brute_force_visible_edges gives them.
inline std::vector<std::array<oracle2d::Pt, 2>> edge_endpoint_pairs(const Scene2D& scene, const std::vector<int>& ids) {
  std::vector<std::array<oracle2d::Pt, 2>> out;
  for (int e : ids) {
    oracle2d::Pt a = to_pt(scene.points[e]), b = to_pt(scene.points[scene.next[e]]);
    if (b < a) std::swap(a, b);
    out.push_back({a, b});
  }
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x[0] < y[0] || (x[0] == y[0] && x[1] < y[1]); });
  return out;
}

}  // namespace exactvis::test2d
