#include "shadows/blocker_eee_events.hpp"

#include "events/eee_prefilter.hpp"
#include "events/scene_adjacency.hpp"
#include "kernel/predicates.hpp"
#include "kernel/segment_tetrahedron_intersection.hpp"
#include "kernel/triangle_index.hpp"
#include "shadows/light_edge_hull.hpp"
#include "util/for_each_index.hpp"
#include "util/progress_bar.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_sort.h>

#include <algorithm>

namespace exactvis::shadows {
namespace {

using Triple = std::array<int, 3>;

// Can edge e ever satisfy the edge rule (events/tangency.hpp)? Not when it has exactly two triangles lying
// in one plane on opposite sides of it (a flat edge: every plane through e separates their third vertices).
bool can_be_tangent(const Scene& scene, const SceneEdge& e) {
  if (e.triangles.size() != 2) return true;
  auto third = [&](int ti) {
    const auto& t = scene.triangles[ti];
    return t.v[0] + t.v[1] + t.v[2] - e.v[0] - e.v[1];
  };
  const Point3& a = scene.vertices[e.v[0]];
  const Point3& b = scene.vertices[e.v[1]];
  const Point3& w0 = scene.vertices[third(e.triangles[0])];
  const Point3& w1 = scene.vertices[third(e.triangles[1])];
  if (orient3d(a, b, w0, w1) != Sign::Zero) return true;
  // Coplanar: flat iff w0 and w1 lie on opposite sides of the line ab within the plane; test with a point
  // off the plane (a + normal).
  const Point3 n = cross(b - a, w0 - a);
  const Point3 off{a.x + n.x, a.y + n.y, a.z + n.z};
  const Sign s0 = orient3d(a, b, off, w0), s1 = orient3d(a, b, off, w1);
  return !(s0 != Sign::Zero && s1 != Sign::Zero && s0 != s1);
}

// Does the closed segment [p, q] meet conv(L ∪ [f0, f1]) (L the triangle l)? By Carathéodory the hull of the
// five points is the union of the tetrahedra on four of them; coplanar quadruples are skipped (their hull is
// covered by the others unless all five are coplanar: then true, conservatively). Exact.
bool meets_light_hull(const Point3& p, const Point3& q, const std::array<Point3, 3>& l, const Point3& f0,
                      const Point3& f1) {
  return any_light_edge_tetrahedron(l, f0, f1, [&](const std::array<Point3, 4>& t, Sign) {
    return segment_meets_tetrahedron(p, q, t[0], t[1], t[2], t[3]);
  });
}

}  // namespace

EeeResult blocker_eee_events(const Scene& scene, const std::vector<int>& light, const BlockerEvOptions& options) {
  const SceneAdjacency adj = build_scene_adjacency(scene);
  const EdgeIndex edges = scene_edge_index(scene, adj);
  const TriangleIndex index(scene);
  const int m = static_cast<int>(adj.edges.size());
  std::vector<char> usable(m, 0);
  for (int e = 0; e < m; ++e) usable[e] = can_be_tangent(scene, adj.edges[e]) ? 1 : 0;
  std::vector<std::array<Point3, 3>> light_corners;
  Box3 light_box{{HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  auto grow = [](Box3& b, const Point3& p) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  };
  for (int ti : light) {
    const auto& t = scene.triangles.at(ti);
    light_corners.push_back({scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2)});
    for (int k = 0; k < 3; ++k) {
      grow(light_box, scene.corner(t, k));
      const int e = adj.edge_index(t.v[k], t.v[(k + 1) % 3]);
      if (e >= 0) usable[e] = 0;  // light edges: the light-restricted enumeration has them
    }
  }
  auto P = [&](int e, int k) -> const Point3& { return scene.vertices[adj.edges[e].v[k]]; };
  auto over_light = [&](int e, int far) {
    for (const auto& l : light_corners)
      if (meets_light_hull(P(e, 0), P(e, 1), l, P(far, 0), P(far, 1))) return true;
    return false;
  };

  struct Local {
    std::vector<Triple> triples;
    std::uint64_t pairs = 0, kept = 0;
  };
  tbb::enumerable_thread_specific<Local> locals;
  ProgressBar bar("blocker EEE pairs", static_cast<std::uint64_t>(m), options.progress);
  auto row = [&](int far) {
    if (!usable[far] || light_corners.empty()) {
      bar.advance();
      return;
    }
    Local& loc = locals.local();
    Box3 box = light_box;
    grow(box, P(far, 0));
    grow(box, P(far, 1));
    for (int near : edges.edges_meeting_box(box)) {
      if (near == far || !usable[near]) continue;
      ++loc.pairs;
      if (!eee_pair_possible(scene, adj.edges[near], adj.edges[far]) || !over_light(near, far)) continue;
      ++loc.kept;
      for (int mid : edges.edges_meeting_tetrahedron(P(near, 0), P(near, 1), P(far, 0), P(far, 1))) {
        if (mid == near || mid == far || !usable[mid]) continue;
        if (!eee_pair_possible(scene, adj.edges[mid], adj.edges[near]) ||
            !eee_pair_possible(scene, adj.edges[mid], adj.edges[far]) || !over_light(mid, far))
          continue;
        Triple t{near, mid, far};
        std::sort(t.begin(), t.end());
        loc.triples.push_back(t);
      }
    }
    bar.advance();
  };
  for_each_index(static_cast<std::size_t>(m), options.parallel, 1, [&](std::size_t e) { row(static_cast<int>(e)); });
  std::vector<Triple> triples;
  EeeResult result;
  for (auto& loc : locals) {
    triples.insert(triples.end(), loc.triples.begin(), loc.triples.end());
    result.stats.outer_pairs += loc.pairs;
    result.stats.outer_pairs_kept += loc.kept;
  }
  tbb::parallel_sort(triples.begin(), triples.end());
  triples.erase(std::unique(triples.begin(), triples.end()), triples.end());
  result.stats.candidate_triples = triples.size();

  const Box3 box = bounding_box(scene);
  EeeResult found = eee_events_of_triples(scene, adj, index, triples, options.parallel, 16, "blocker EEE triples",
                                          options.progress,
                                          [&](EeeEvent& ev) { eee_segment_ends(scene, index, box, ev); });
  result.events = std::move(found.events);
  result.stats.eee = found.stats.eee;
  return result;
}

}  // namespace exactvis::shadows
