#pragma once
// Test helpers: oracle scenes (plain doubles) to exactvis Scene2D and back to exact gmpxx points.
#include "oracles/visibility2d_oracle.hpp"
#include "skeleton/scene2d.hpp"

#include <optional>

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

}  // namespace exactvis::test2d
