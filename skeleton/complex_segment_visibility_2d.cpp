#include "skeleton/complex_segment_visibility_2d.hpp"

#include <algorithm>
#include <stdexcept>

namespace exactvis {
namespace {

Exact cross(const Exact& ax, const Exact& ay, const Exact& bx, const Exact& by) { return ax * by - ay * bx; }

// Sorted distinct values of `v` inside (0, 1), with 0 and 1 added.
std::vector<Exact> unit_breakpoints(std::vector<Exact> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](const Exact& x) { return !(x > 0 && x < 1); }), v.end());
  v.push_back(0);
  v.push_back(1);
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// Parameter along a -> b (b - a = (dx, dy)) where the line through p, p + (ex, ey) meets it, if not parallel.
void add_crossing(std::vector<Exact>& out, const Point2& a, const Exact& dx, const Exact& dy, const Point2& p,
                  const Exact& ex, const Exact& ey) {
  const Exact den = cross(dx, dy, ex, ey);
  if (CGAL::sign(den) == CGAL::ZERO) return;
  out.push_back(cross(p.x - a.x, p.y - a.y, ex, ey) / den);
}

// Strictly inside the closed polygon (not on its boundary): crossing number with exact orientations.
bool strictly_inside(const std::vector<Point2>& poly, const Point2& p) {
  bool in = false;
  const std::size_t m = poly.size();
  for (std::size_t i = 0; i < m; ++i) {
    const Point2 &a = poly[i], &b = poly[(i + 1) % m];
    if (segments_intersect(a, b, p, p)) return false;
    const bool a_above = a.y > p.y, b_above = b.y > p.y;
    if (a_above == b_above) continue;
    // the edge crosses the horizontal line of p: is the crossing to the right of p?
    const Sign o = orientation2(a, b, p);
    if ((o == Sign::Positive) == b_above) in = !in;
  }
  return in;
}

}  // namespace

SegmentVisibility2D segment_visibility_in_complex(const ComplexWalkIndex2D& index, const Point2& s0,
                                                  const Point2& s1, const Point2& t0, const Point2& t1,
                                                  ComplexSegmentStats2D* stats) {
  const Scene2D& scene = *index.scene;
  require_free_segment(scene, s0, s1, "segment S");
  require_free_segment(scene, t0, t1, "segment T");
  ComplexSegmentStats2D st;
  SegmentVisibility2D out;
  // a frame containing S and T strictly (the polygons are clipped by it)
  double margin = 0.5;
  Scene2D framed = with_frame(scene, margin);
  for (int k = 0;; ++k) {
    const Ring2D& fr = framed.rings[framed.frame_ring];
    const Point2 &lo = framed.points[fr.first], &hi = framed.points[fr.first + 2];
    bool inside = true;
    for (const Point2* p : {&s0, &s1, &t0, &t1})
      inside = inside && lo.x < p->x && p->x < hi.x && lo.y < p->y && p->y < hi.y;
    if (inside) break;
    if (k == 64) throw std::invalid_argument("segments too far from the scene for a frame");
    margin = 2 * margin + 1;
    framed = with_frame(scene, margin);
  }
  // sigmas: S meets the line through two vertices seeing each other (strict pairs, ring edges) or through
  // t0 / t1 and a vertex
  const Exact sdx = s1.x - s0.x, sdy = s1.y - s0.y, tdx = t1.x - t0.x, tdy = t1.y - t0.y;
  const auto& P = scene.points;
  std::vector<Exact> sig;
  auto through = [&](const Point2& a, const Point2& b) { add_crossing(sig, s0, sdx, sdy, a, b.x - a.x, b.y - a.y); };
  for (const auto& [u, v] : index.complex->graph.strict_pairs) through(P[u], P[v]);
  for (int v = 0; v < scene.num_vertices(); ++v) {
    through(P[v], P[scene.next[v]]);
    if (P[v] != t0) through(P[v], t0);
    if (P[v] != t1) through(P[v], t1);
  }
  st.breakpoints = sig.size();
  const std::vector<Exact> sigmas = unit_breakpoints(std::move(sig));
  for (std::size_t i = 0; i + 1 < sigmas.size() && !out.visible; ++i) {
    const Exact sm = (sigmas[i] + sigmas[i + 1]) / 2;
    const Point2 s(s0.x + sm * sdx, s0.y + sm * sdy);
    ++st.walks;
    const VisibilityPolygon2D vp = visibility_polygon_in_complex(index, framed, s);
    // T cut at every point where it meets the polygon's boundary
    std::vector<Exact> tau;
    const std::size_t m = vp.vertices.size();
    for (std::size_t k = 0; k < m; ++k) {
      const Point2 &a = vp.vertices[k], &b = vp.vertices[(k + 1) % m];
      if (!segments_intersect(a, b, t0, t1)) continue;
      const std::size_t before = tau.size();
      add_crossing(tau, t0, tdx, tdy, a, b.x - a.x, b.y - a.y);
      if (tau.size() == before) {  // collinear overlap: both ends of the edge
        const Exact len2 = tdx * tdx + tdy * tdy;
        for (const Point2* p : {&a, &b}) tau.push_back(((p->x - t0.x) * tdx + (p->y - t0.y) * tdy) / len2);
      }
    }
    const std::vector<Exact> taus = unit_breakpoints(std::move(tau));
    for (std::size_t j = 0; j + 1 < taus.size(); ++j) {
      Exact tm = (taus[j] + taus[j + 1]) / 2;
      Point2 t(t0.x + tm * tdx, t0.y + tm * tdy);
      if (t == s) {  // T passes through s*: any other point of the piece
        tm = (taus[j] + tm) / 2;
        t = Point2(t0.x + tm * tdx, t0.y + tm * tdy);
      }
      ++out.candidates;
      if (!strictly_inside(vp.vertices, t)) continue;
      if (!open_segment_free(scene, s, t))
        throw std::logic_error("segment_visibility_in_complex: witness not free (bug)");
      out.visible = true;
      out.witness_s = s;
      out.witness_t = t;
      break;
    }
  }
  if (stats) *stats = st;
  return out;
}

}  // namespace exactvis
