#include "skeleton/visibility_polygon_2d.hpp"

#include "skeleton/angular_sweep_2d.hpp"
#include "skeleton/rotational_visibility_2d.hpp"

#include <algorithm>
#include <stdexcept>

namespace exactvis {
namespace {

void check_query(const Scene2D& scene, const Point2& q) {
  if (scene.frame_ring < 0) throw std::invalid_argument("visibility query needs a bounded scene (with_frame)");
  if (on_boundary(scene, q)) throw std::invalid_argument("query point lies on a polygon boundary");
  if (inside_obstacle(scene, q)) throw std::invalid_argument("query point lies inside an object or outside the frame");
}

}  // namespace

VisibilityPolygon2D visibility_polygon(const Scene2D& scene, const Point2& q) {
  check_query(scene, q);
  const auto events = angular_sweep(scene, q);
  VisibilityPolygon2D vp;
  auto push = [&](const Point2& p) {
    if (vp.vertices.empty() || vp.vertices.back() != p) vp.vertices.push_back(p);
  };
  for (const SweepEvent2D& ev : events) {
    if (ev.before < 0 || ev.after < 0) throw std::invalid_argument("visibility region is unbounded");
    if (ev.before == ev.after) continue;
    const Point2& dir = scene.points[ev.vertices.front()];
    const auto hit = [&](int e) {
      const int a = e, b = scene.next[e];
      if (orientation2(q, dir, scene.points[a]) == Sign::Zero) return scene.points[a];
      if (orientation2(q, dir, scene.points[b]) == Sign::Zero) return scene.points[b];
      return line_intersection(q, q, dir, scene.points[a], scene.points[b]);
    };
    push(hit(ev.before));
    push(hit(ev.after));
  }
  while (vp.vertices.size() > 1 && vp.vertices.back() == vp.vertices.front()) vp.vertices.pop_back();
  return vp;
}

std::vector<VisibilityPolygon2D> visibility_polygons(const Scene2D& scene, const std::vector<Point2>& points) {
  if (scene.frame_ring < 0) throw std::invalid_argument("visibility query needs a bounded scene (with_frame)");
  auto rings = rotational_visibility_polygons(scene, points);
  std::vector<VisibilityPolygon2D> out(rings.size());
  for (std::size_t i = 0; i < rings.size(); ++i) out[i].vertices = std::move(rings[i]);
  return out;
}

std::vector<int> visible_edges(const Scene2D& scene, const Point2& q) {
  check_query(scene, q);
  const auto events = angular_sweep(scene, q);
  std::vector<int> seen;
  for (const SweepEvent2D& ev : events)
    if (ev.after >= 0) seen.push_back(ev.after);
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  return seen;
}

}  // namespace exactvis
