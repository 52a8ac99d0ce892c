#include "skeleton/segment_visibility_2d.hpp"

#include <algorithm>

namespace exactvis {

bool open_segment_free(const Scene2D& s, const Point2& a, const Point2& b) {
  for (int e = 0; e < s.num_vertices(); ++e)
    if (segments_intersect(a, b, s.points[e], s.points[s.next[e]])) return false;
  return true;
}

void require_free_segment(const Scene2D& s, const Point2& a, const Point2& b, const char* name) {
  if (a == b) throw std::invalid_argument(std::string(name) + " has zero length");
  if (!open_segment_free(s, a, b)) throw std::invalid_argument(std::string(name) + " meets a polygon boundary");
  if (inside_obstacle(s, a)) throw std::invalid_argument(std::string(name) + " lies inside an object");
}

namespace {

// Sorted distinct values of `v` inside (0, 1), with 0 and 1 added.
std::vector<Exact> breakpoints(std::vector<Exact> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](const Exact& x) { return !(x > 0 && x < 1); }), v.end());
  v.push_back(0);
  v.push_back(1);
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

Exact cross(const Exact& ax, const Exact& ay, const Exact& bx, const Exact& by) { return ax * by - ay * bx; }

}  // namespace

SegmentVisibility2D segment_visibility(const Scene2D& scene, const Point2& s0, const Point2& s1, const Point2& t0,
                                       const Point2& t1) {
  require_free_segment(scene, s0, s1, "segment S");
  require_free_segment(scene, t0, t1, "segment T");
  SegmentVisibility2D out;
  const Exact sdx = s1.x - s0.x, sdy = s1.y - s0.y, tdx = t1.x - t0.x, tdy = t1.y - t0.y;
  std::vector<const Point2*> pts;
  for (const Point2& p : scene.points) pts.push_back(&p);
  pts.push_back(&t0);
  pts.push_back(&t1);
  // sigma where the line through a with direction (dx, dy) meets the line of S
  std::vector<Exact> sig;
  auto add_sigma = [&](const Point2& a, const Exact& dx, const Exact& dy) {
    const Exact den = cross(dx, dy, sdx, sdy);
    if (CGAL::sign(den) == CGAL::ZERO) return;
    sig.push_back(-cross(dx, dy, s0.x - a.x, s0.y - a.y) / den);
  };
  for (std::size_t i = 0; i < pts.size(); ++i) {
    for (std::size_t j = i + 1; j < pts.size(); ++j) add_sigma(*pts[i], pts[j]->x - pts[i]->x, pts[j]->y - pts[i]->y);
    add_sigma(*pts[i], tdx, tdy);  // pole of tau_v
  }
  const std::vector<Exact> sigmas = breakpoints(std::move(sig));
  for (std::size_t i = 0; i + 1 < sigmas.size(); ++i) {
    const Exact sm = (sigmas[i] + sigmas[i + 1]) / 2;
    const Point2 s(s0.x + sm * sdx, s0.y + sm * sdy);
    std::vector<Exact> tau;
    for (const Point2& v : scene.points) {
      const Exact vx = v.x - s.x, vy = v.y - s.y;
      const Exact den = cross(vx, vy, tdx, tdy);
      if (CGAL::sign(den) == CGAL::ZERO) continue;
      tau.push_back(-cross(vx, vy, t0.x - s.x, t0.y - s.y) / den);
    }
    const std::vector<Exact> taus = breakpoints(std::move(tau));
    for (std::size_t j = 0; j + 1 < taus.size(); ++j) {
      const Exact tm = (taus[j] + taus[j + 1]) / 2;
      const Point2 t(t0.x + tm * tdx, t0.y + tm * tdy);
      ++out.candidates;
      if (open_segment_free(scene, s, t)) {
        out.visible = true;
        out.witness_s = s;
        out.witness_t = t;
        return out;
      }
    }
  }
  return out;
}

}  // namespace exactvis
