#include "skeleton/visibility_graph_2d.hpp"

#include "skeleton/angular_sweep_2d.hpp"
#include "skeleton/rotational_visibility_2d.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace exactvis {

bool in_free_wedge(const Scene2D& s, int v, const Point2& d0, const Point2& d1) {
  const auto& P = s.points;
  return in_open_ccw_sector(d0, d1, P[v], P[s.prev[v]], P[v], P[s.next[v]]);
}

bool in_object_wedge(const Scene2D& s, int v, const Point2& d0, const Point2& d1) {
  const auto& P = s.points;
  return in_open_ccw_sector(d0, d1, P[v], P[s.next[v]], P[v], P[s.prev[v]]);
}

namespace {

using Found = VisibleFrom2D;

char side_at(const Scene2D& s, int v, int a, int b) {
  const auto& P = s.points;
  Sign o = orientation2(P[a], P[b], P[s.prev[v]]);
  if (o == Sign::Zero) o = orientation2(P[a], P[b], P[s.next[v]]);
  return o == Sign::Positive ? 'L' : 'R';
}

std::vector<Found> sweep_vertex(const Scene2D& s, int p) {
  const auto& P = s.points;
  std::vector<Found> out;
  const auto events = angular_sweep(s, P[p], p);
  for (const SweepEvent2D& ev : events) {
    const int w = ev.vertices.front();
    if (!vertex_before_crossing(s, P[p], w, ev.crossing)) continue;
    if (!in_free_wedge(s, p, P[p], P[w])) continue;
    Found f{w, false, {}};
    // tangent at p: the line behind p does not enter p's object; tangent at w: nor beyond w
    f.tangent = !in_object_wedge(s, p, P[w], P[p]) && !in_object_wedge(s, w, P[p], P[w]);
    if (f.tangent) {
      const auto along = [&](int u) {
        return orientation2(P[p], P[w], P[u]) == Sign::Zero && dot_sign(P[p], P[w], P[w], P[u]) == Sign::Positive;
      };
      if (along(s.next[w]) || along(s.prev[w])) {
        f.beyond = {SegmentEnd2D::Vertex, w, s.object_of(w), P[w]};
      } else if (ev.vertices.size() > 1 && vertex_before_crossing(s, P[p], ev.vertices[1], ev.crossing)) {
        const int r = ev.vertices[1];
        f.beyond = {SegmentEnd2D::Vertex, r, s.object_of(r), P[r]};
      } else if (ev.crossing >= 0) {
        const int e = ev.crossing;
        f.beyond = {SegmentEnd2D::EdgeInterior, e, s.object_of(e),
                    line_intersection(P[p], P[p], P[w], P[e], P[s.next[e]])};
      }
    }
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace

VisibilityGraph2D visibility_graph(const Scene2D& s, void (*progress)(double), VisibilityGraphMethod method) {
  const int n = s.num_vertices();
  std::vector<std::vector<Found>> found(n);
  if (method == VisibilityGraphMethod::RotationalSweep) {
    found = rotational_visible_pairs(s, progress);
  } else {
    std::atomic<int> done{0};
    tbb::parallel_for(0, n, [&](int p) {
      found[p] = sweep_vertex(s, p);
      const int d = ++done;
      if (progress && (d % 64 == 0 || d == n)) progress(static_cast<double>(d) / n);
    });
  }
  VisibilityGraph2D g;
  for (int v = 0; v < n; ++v) g.ring_edges.emplace_back(v, s.next[v]);
  // each pair must be found from both ends, once; the extension beyond p comes from q's side
  std::size_t entries = 0;
  for (int p = 0; p < n; ++p) {
    std::sort(found[p].begin(), found[p].end(), [](const Found& x, const Found& y) { return x.w < y.w; });
    for (std::size_t i = 1; i < found[p].size(); ++i)
      if (found[p][i].w == found[p][i - 1].w) throw std::logic_error("visibility_graph: pair found twice (bug)");
    entries += found[p].size();
  }
  auto lookup = [&](int q, int p) -> const Found* {
    const auto it = std::lower_bound(found[q].begin(), found[q].end(), p,
                                     [](const Found& x, int w) { return x.w < w; });
    return it != found[q].end() && it->w == p ? &*it : nullptr;
  };
  for (int p = 0; p < n; ++p) {
    for (const Found& fr : found[p]) {
      const Found* f = &fr;
      const int q = f->w;
      if (q < p) continue;
      const Found* back_found = lookup(q, p);
      if (!back_found || back_found->tangent != f->tangent)
        throw std::logic_error("visibility_graph: asymmetric visibility (bug)");
      const Found* back_f = back_found;
      g.strict_pairs.emplace_back(p, q);
      if (!f->tangent) continue;
      Bitangent2D b;
      b.a = p;
      b.b = q;
      b.object_a = s.object_of(p);
      b.object_b = s.object_of(q);
      b.side_a = side_at(s, p, p, q);
      b.side_b = side_at(s, q, p, q);
      b.end_a = back_f->beyond;
      b.end_b = f->beyond;
      g.bitangents.push_back(std::move(b));
    }
  }
  if (entries != 2 * g.strict_pairs.size()) throw std::logic_error("visibility_graph: asymmetric visibility (bug)");
  return g;
}

}  // namespace exactvis
