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

void add_line_crossing(std::vector<Exact>& out, const Point2& a, const Exact& dx, const Exact& dy, const Point2& p,
                       const Exact& ex, const Exact& ey) {
  const Exact den = dx * ey - dy * ex;
  if (CGAL::sign(den) == CGAL::ZERO) return;
  out.push_back(((p.x - a.x) * ey - (p.y - a.y) * ex) / den);
}

std::vector<Exact> unit_interval_cuts(std::vector<Exact> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](const Exact& x) { return !(x > 0 && x < 1); }), v.end());
  v.push_back(0);
  v.push_back(1);
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

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
  auto add_sigma = [&](const Point2& a, const Exact& dx, const Exact& dy) { add_line_crossing(sig, s0, sdx, sdy, a, dx, dy); };
  for (std::size_t i = 0; i < pts.size(); ++i) {
    for (std::size_t j = i + 1; j < pts.size(); ++j) add_sigma(*pts[i], pts[j]->x - pts[i]->x, pts[j]->y - pts[i]->y);
    add_sigma(*pts[i], tdx, tdy);  // pole of tau_v
  }
  const std::vector<Exact> sigmas = unit_interval_cuts(std::move(sig));
  for (std::size_t i = 0; i + 1 < sigmas.size(); ++i) {
    const Exact sm = (sigmas[i] + sigmas[i + 1]) / 2;
    const Point2 s(s0.x + sm * sdx, s0.y + sm * sdy);
    std::vector<Exact> tau;
    for (const Point2& v : scene.points) add_line_crossing(tau, t0, tdx, tdy, s, v.x - s.x, v.y - s.y);
    const std::vector<Exact> taus = unit_interval_cuts(std::move(tau));
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
