#include "skeleton/complex_segment_visibility_2d.hpp"

#include <stdexcept>

namespace exactvis {

SegmentVisibility2D segment_visibility_in_complex(const ComplexWalkIndex2D& index, const Point2& s0,
                                                  const Point2& s1, const Point2& t0, const Point2& t1,
                                                  ComplexSegmentStats2D* stats) {
  const Scene2D& scene = *index.scene;
  require_free_segment(scene, s0, s1, "segment S");
  require_free_segment(scene, t0, t1, "segment T");
  ComplexSegmentStats2D st;
  SegmentVisibility2D out;
  // a frame containing S and T strictly (the polygons are clipped by it); any such frame gives the same
  // answer (segments from S to T stay inside it), so margin 0 serves scenes too large for margin 0.5
  const Scene2D framed = with_frame_around(scene, {s0, s1, t0, t1}, frame_box(scene, 0.5).representable ? 0.5 : 0.0);
  for (const Point2* p : {&s0, &s1, &t0, &t1})
    if (!frame_contains(framed, *p)) throw std::invalid_argument("segments too far from the scene for a frame");
  // sigmas: S meets the line through two vertices seeing each other (strict pairs, ring edges) or through
  // t0 / t1 and a vertex
  const Exact sdx = s1.x - s0.x, sdy = s1.y - s0.y, tdx = t1.x - t0.x, tdy = t1.y - t0.y;
  const auto& P = scene.points;
  std::vector<Exact> sig;
  auto through = [&](const Point2& a, const Point2& b) { add_line_crossing(sig, s0, sdx, sdy, a, b.x - a.x, b.y - a.y); };
  for (const auto& [u, v] : index.complex->graph.strict_pairs) through(P[u], P[v]);
  for (int v = 0; v < scene.num_vertices(); ++v) {
    through(P[v], P[scene.next[v]]);
    if (P[v] != t0) through(P[v], t0);
    if (P[v] != t1) through(P[v], t1);
  }
  st.breakpoints = sig.size();
  const std::vector<Exact> sigmas = unit_interval_cuts(std::move(sig));
  for (std::size_t i = 0; i + 1 < sigmas.size() && !out.visible; ++i) {
    const Exact sm = (sigmas[i] + sigmas[i + 1]) / 2;
    const Point2 s(s0.x + sm * sdx, s0.y + sm * sdy);
    ++st.walks;
    const VisibilityPolygon2D vp = visibility_polygon_in_complex(index, framed, s);
    // T cut at every point where it meets the polygon's boundary
    std::vector<Exact> tau;
    const int m = static_cast<int>(vp.vertices.size());
    for (int k = 0; k < m; ++k) {
      const Point2 &a = vp.vertices[k], &b = vp.vertices[(k + 1) % m];
      if (!segments_intersect(a, b, t0, t1)) continue;
      const std::size_t before = tau.size();
      add_line_crossing(tau, t0, tdx, tdy, a, b.x - a.x, b.y - a.y);
      if (tau.size() == before) {  // collinear overlap: both ends of the edge
        const Exact len2 = tdx * tdx + tdy * tdy;
        for (const Point2* p : {&a, &b}) tau.push_back(((p->x - t0.x) * tdx + (p->y - t0.y) * tdy) / len2);
      }
    }
    const std::vector<Exact> taus = unit_interval_cuts(std::move(tau));
    for (std::size_t j = 0; j + 1 < taus.size(); ++j) {
      Exact tm = (taus[j] + taus[j + 1]) / 2;
      Point2 t(t0.x + tm * tdx, t0.y + tm * tdy);
      if (t == s) {  // T passes through s*: any other point of the piece
        tm = (taus[j] + tm) / 2;
        t = Point2(t0.x + tm * tdx, t0.y + tm * tdy);
      }
      ++out.candidates;
      if (on_ring(vp.vertices, 0, m, t) || !inside_ring(vp.vertices, 0, m, t)) continue;  // not strictly inside
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
