#include "shadows/blocker_events.hpp"

#include "events/ev_interval_split.hpp"
#include "events/scene_adjacency.hpp"
#include "kernel/edge_index.hpp"
#include "events/tangency.hpp"
#include "kernel/predicates.hpp"
#include "kernel/triangle_index.hpp"
#include "shadows/light_edge_hull.hpp"
#include "util/for_each_index.hpp"
#include "util/progress_bar.hpp"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <initializer_list>
#include <set>

namespace exactvis::shadows {
namespace {

// Whether the light triangle (a, b, c) meets the plane of (V, A, B) (closed): not all corners strictly on
// one side. Exact (filtered orient3d).
bool plane_meets_triangle(const Point3& v, const Point3& a, const Point3& b, const std::array<Point3, 3>& t) {
  int pos = 0, neg = 0;
  for (const auto& p : t) {
    const Sign s = orient3d(v, a, b, p);
    if (s == Sign::Positive) ++pos;
    else if (s == Sign::Negative) ++neg;
    else return true;
  }
  return pos > 0 && neg > 0;
}

// Whether x lies in the closed convex hull of the five points (the light triangle l and the edge [f0, f1]):
// by Carathéodory, in one of the closed tetrahedra on four of them; all five coplanar: true
// (conservatively). Exact.
bool in_light_edge_hull(const Point3& x, const std::array<Point3, 3>& l, const Point3& f0, const Point3& f1) {
  return any_light_edge_tetrahedron(l, f0, f1, [&](const std::array<Point3, 4>& t, Sign o) {
    // x in the closed tetrahedron: on the inner side (or on) of each face plane.
    return orient3d(t[0], t[1], t[2], x) != -o && orient3d(t[0], t[1], x, t[3]) != -o &&
           orient3d(t[0], x, t[2], t[3]) != -o && orient3d(x, t[1], t[2], t[3]) != -o;
  });
}

Box3 box_of(std::initializer_list<Point3> pts) {
  Box3 b{*pts.begin(), *pts.begin()};
  for (const auto& p : pts)
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = std::min(b.lo[k], p[k]);
      b.hi[k] = std::max(b.hi[k], p[k]);
    }
  return b;
}

}  // namespace

EvResult blocker_ev_events(const Scene& scene, const std::vector<int>& light, const BlockerEvOptions& options) {
  const SceneAdjacency adj = build_scene_adjacency(scene);
  const TriangleIndex index(scene);
  const Box3 box = bounding_box(scene);
  const int nv = static_cast<int>(scene.vertices.size());
  std::vector<char> light_vertex(nv, 0);
  std::set<std::int64_t> light_ids;
  std::vector<std::array<Point3, 3>> light_corners;
  for (int ti : light) {
    const auto& t = scene.triangles.at(ti);
    for (int k = 0; k < 3; ++k) light_vertex[t.v[k]] = 1;
    light_ids.insert(t.id);
    light_corners.push_back({scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2)});
  }
  std::vector<char> light_edge(adj.edges.size(), 0);
  for (std::size_t ei = 0; ei < adj.edges.size(); ++ei)
    for (int ti : adj.edges[ei].triangles)
      if (std::find(light.begin(), light.end(), ti) != light.end()) light_edge[ei] = 1;

  // The cull (docs/theory.md section 11, "Blocker-blocker events"): a kept interval's line meets a light
  // triangle L at q beyond E (then E's point e lies on [V, q], in conv(V ∪ L): an edge query of that
  // tetrahedron) or behind V (then V lies on [e, q], in conv(L ∪ E): per edge, the vertices of the
  // triangles in the box of L ∪ E, tested exactly). Every other pair has no kept interval.
  std::vector<std::vector<int>> cand(options.cull ? nv : 0);
  if (options.cull) {
    const EdgeIndex edge_index = scene_edge_index(scene, adj);
    for_each_index(static_cast<std::size_t>(nv), options.parallel, 16, [&](std::size_t v) {
      if (light_vertex[v] || adj.vertex_triangles[v].empty()) return;
      const Point3& V = scene.vertices[v];
      for (const auto& l : light_corners) {
        const auto hits = orient3d(V, l[0], l[1], l[2]) != Sign::Zero
                              ? edge_index.edges_meeting_tetrahedron(V, l[0], l[1], l[2])
                              : edge_index.edges_meeting_box(box_of({V, l[0], l[1], l[2]}));
        cand[v].insert(cand[v].end(), hits.begin(), hits.end());
      }
    });
    tbb::enumerable_thread_specific<std::vector<std::array<int, 2>>> behind;  // (vertex, edge) pairs
    for_each_index(adj.edges.size(), options.parallel, 16, [&](std::size_t ei) {
      if (light_edge[ei]) return;
      auto& out = behind.local();
      const Point3& A = scene.vertices[adj.edges[ei].v[0]];
      const Point3& B = scene.vertices[adj.edges[ei].v[1]];
      for (const auto& l : light_corners) {
        const Box3 b = box_of({A, B, l[0], l[1], l[2]});
        std::vector<int> seen;
        for (std::int64_t ti : index.candidates_in_box(b))
          for (int k = 0; k < 3; ++k) {
            const int v = scene.triangles[ti].v[k];
            const Point3& X = scene.vertices[v];
            if (light_vertex[v] || X.x < b.lo.x || X.x > b.hi.x || X.y < b.lo.y || X.y > b.hi.y || X.z < b.lo.z ||
                X.z > b.hi.z)
              continue;
            if (std::find(seen.begin(), seen.end(), v) != seen.end()) continue;
            seen.push_back(v);
            if (in_light_edge_hull(X, l, A, B)) out.push_back({v, static_cast<int>(ei)});
          }
      }
    });
    for (const auto& local : behind)
      for (const auto& [v, ei] : local) cand[v].push_back(ei);
    for_each_index(static_cast<std::size_t>(nv), options.parallel, 64, [&](std::size_t v) {
      std::sort(cand[v].begin(), cand[v].end());
      cand[v].erase(std::unique(cand[v].begin(), cand[v].end()), cand[v].end());
    });
  }
  std::vector<int> all_edges;
  if (!options.cull)
    for (int ei = 0; ei < static_cast<int>(adj.edges.size()); ++ei) all_edges.push_back(ei);

  std::vector<std::vector<EvEvent>> per_vertex(nv);
  std::vector<EvStats> per_vertex_stats(nv);
  ProgressBar bar("blocker EV events", static_cast<std::uint64_t>(nv), options.progress);
  auto work = [&](int v) {
    if (light_vertex[v] || adj.vertex_triangles[v].empty()) {
      bar.advance();
      return;
    }
    const Point3& V = scene.vertices[v];
    std::optional<VertexFan> fan;
    EvStats& st = per_vertex_stats[v];
    for (int ei : options.cull ? cand[v] : all_edges) {
      if (light_edge[ei]) continue;
      const auto& e = adj.edges[ei].v;
      if (e[0] == v || e[1] == v) continue;
      const Point3& A = scene.vertices[e[0]];
      const Point3& B = scene.vertices[e[1]];
      if (collinear(V, A, B)) continue;
      bool meets = false;
      for (const auto& t : light_corners)
        if (plane_meets_triangle(V, A, B, t)) {
          meets = true;
          break;
        }
      if (!meets) continue;
      if (!fan) fan = build_vertex_fan(scene, adj, v);
      auto ev = ev_event(scene, adj, index, *fan, ei, &st);
      if (!ev) continue;
      std::vector<CriticalInterval> kept;
      for (const auto& iv : ev->intervals)
        for (auto& piece : split_ev_interval(scene, adj, index, box, ev->vertex, ev->edge, iv)) {
          const bool front_light = light_ids.count(piece.front_object) > 0;
          const bool back_light = light_ids.count(piece.back_object) > 0;
          const std::int64_t other = front_light ? piece.back_object : piece.front_object;
          if (front_light != back_light && other >= 0) kept.push_back(std::move(piece));
        }
      if (kept.empty()) continue;
      ev->intervals = std::move(kept);
      per_vertex[v].push_back(std::move(*ev));
    }
    bar.advance();
  };
  for_each_index(static_cast<std::size_t>(nv), options.parallel, 1, [&](std::size_t v) { work(static_cast<int>(v)); });
  return join_per_vertex_ev(std::move(per_vertex), per_vertex_stats);
}

}  // namespace exactvis::shadows
