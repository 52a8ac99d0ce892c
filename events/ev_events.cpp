#include "events/ev_events.hpp"

#include "events/ev_interval_split.hpp"
#include "events/interval_end_key.hpp"
#include "events/ev_parameter.hpp"
#include "util/for_each_index.hpp"
#include "util/progress_bar.hpp"
#include "events/tangency.hpp"
#include "kernel/predicates.hpp"
#include "kernel/ray_first_hit.hpp"
#include "kernel/triangle_index.hpp"


#include <algorithm>
#include <map>

namespace exactvis {
namespace {

// A closed parameter interval where lines are invalid, with the causes at its ends.
struct Invalid {
  EvParameter lo, hi;
  CriticalEnd lo_end, hi_end;
};

CriticalEnd occluder_end(std::int64_t triangle, const OccluderFeature& feature) {
  CriticalEnd e;
  e.cause = CriticalEnd::Cause::Occluder;
  e.triangle = triangle;
  e.feature = feature;
  return e;
}

CriticalInterval make_interval(const EvParameter& t0, const EvParameter& t1, const CriticalEnd& end0,
                               const CriticalEnd& end1) {
  CriticalInterval iv;
  iv.t0 = RootNumber(t0.exact());
  iv.t1 = RootNumber(t1.exact());
  iv.end0 = end0;
  iv.end1 = end1;
  return iv;
}

bool has_vertex(const SceneTriangle& t, int v) { return t.v[0] == v || t.v[1] == v || t.v[2] == v; }

// Parameters t in (0, 1) where the vertex rule may change, each with the fan triangle causing it, sorted.
// The rule's inputs are signs of functions linear in t: det(d(t), w1, w2) per fan triangle (the line enters
// a face plane) and, when the wedge lies in a face plane, the t where the line passes through W1 or W2.
std::vector<std::pair<EvParameter, int>> vertex_rule_breakpoints(const Scene& scene, const VertexFan& fan,
                                                                 const Vec3<Ring>& av, const Vec3<Ring>& bv) {
  std::vector<std::pair<EvParameter, int>> out;
  auto ring = [](const Point3& q) { return Vec3<Ring>(Ring(q.x), Ring(q.y), Ring(q.z)); };
  const Vec3<Ring> V = ring(scene.vertices[fan.vertex]);
  const Vec3<Ring> ba = bv - av;
  const EvParameter zero = EvParameter::integer(0), one = EvParameter::integer(1);
  auto add = [&](const EvParameter& t, int ti) {
    if (t > zero && t < one) out.emplace_back(t, ti);
  };
  for (int ti : fan.triangles) {
    const auto& t = scene.triangles[ti];
    int k = 0;
    while (t.v[k] != fan.vertex) ++k;
    const Vec3<Ring> w1 = ring(scene.vertices[t.v[(k + 1) % 3]]) - V;
    const Vec3<Ring> w2 = ring(scene.vertices[t.v[(k + 2) % 3]]) - V;
    const Vec3<Ring> n = cross(w1, w2);
    const Ring c0 = dot(av, n), c1 = dot(ba, n);
    if (CGAL::sign(c1) != 0) {
      add(EvParameter(-c0, c1), ti);
    } else if (CGAL::sign(c0) == 0) {
      // The wedge lies in this face's plane: the rule changes where the line passes through W1 or W2.
      for (const auto& w : {w1, w2}) {
        const Vec3<Ring> c = cross(av, w), e = cross(ba, w);
        for (int j = 0; j < 3; ++j) {
          if (CGAL::sign(e[j]) == 0) continue;
          const EvParameter s(-c[j], e[j]);
          const Vec3<Ring> dd = s.den * av + s.num * ba;
          const Vec3<Ring> z = cross(dd, w);
          if (CGAL::sign(z.x) == 0 && CGAL::sign(z.y) == 0 && CGAL::sign(z.z) == 0) add(s, ti);
          break;
        }
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  out.erase(std::unique(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
            out.end());
  return out;
}

// True iff the union of the closed intervals is [0, 1].
bool covers_unit_interval(std::vector<Invalid> invalid) {
  std::sort(invalid.begin(), invalid.end(), [](const Invalid& x, const Invalid& y) { return x.lo < y.lo; });
  EvParameter pos = EvParameter::integer(0);
  for (const auto& iv : invalid) {
    if (iv.lo > pos) return false;
    if (iv.hi > pos) pos = iv.hi;
  }
  return pos >= EvParameter::integer(1);
}

// Sweeps [0, 1] minus the union of closed invalid intervals; keeps components of positive length.
std::vector<CriticalInterval> free_components(std::vector<Invalid> invalid) {
  std::sort(invalid.begin(), invalid.end(), [](const Invalid& x, const Invalid& y) { return x.lo < y.lo; });
  std::vector<CriticalInterval> out;
  EvParameter pos = EvParameter::integer(0);
  CriticalEnd pos_end;  // EdgeEndpoint
  for (const auto& iv : invalid) {
    if (iv.lo > pos) out.push_back(make_interval(pos, iv.lo, pos_end, iv.lo_end));
    if (iv.hi >= pos) {
      pos = iv.hi;
      pos_end = iv.hi_end;
    }
  }
  if (pos < EvParameter::integer(1)) out.push_back(make_interval(pos, EvParameter::integer(1), pos_end, CriticalEnd{}));
  return out;
}

}  // namespace

Vec3<Exact> ev_edge_point(const Scene& scene, const std::array<int, 2>& edge, const Exact& t) {
  const Vec3<Exact> a = to_rational(scene.vertices[edge[0]]);
  const Vec3<Exact> b = to_rational(scene.vertices[edge[1]]);
  return a + t * (b - a);
}

std::optional<EvEvent> ev_event(const Scene& scene, const SceneAdjacency& adj, const TriangleIndex& index,
                                const VertexFan& fan, int edge, EvStats* stats) {
  const int v = fan.vertex;
  const SceneEdge& e = adj.edges[edge];
  if (e.v[0] == v || e.v[1] == v) return std::nullopt;
  if (stats) ++stats->pairs;
  const Point3& pv = scene.vertices[v];
  const Point3& pa = scene.vertices[e.v[0]];
  const Point3& pb = scene.vertices[e.v[1]];
  if (collinear(pv, pa, pb)) return std::nullopt;  // no 1-parameter family (docs: degenerate cases)
  if (!edge_tangent_in_plane(scene, e, pv)) return std::nullopt;
  if (stats) ++stats->tangent_pairs;

  auto ring = [](const Point3& q) { return Vec3<Ring>(Ring(q.x), Ring(q.y), Ring(q.z)); };
  const Vec3<Ring> V = ring(pv);
  const Vec3<Ring> av = ring(pa) - V, bv = ring(pb) - V;
  const Vec3<Ring> ba = bv - av;
  auto to_exact_vec = [](const Vec3<Ring>& x) {
    return Vec3<Exact>(Exact(static_cast<CGAL::Gmpq>(x.x)), Exact(static_cast<CGAL::Gmpq>(x.y)),
                       Exact(static_cast<CGAL::Gmpq>(x.z)));
  };
  const Vec3<Exact> normal = to_exact_vec(cross(av, bv));
  // Direction of L(t), up to the positive factor den.
  auto dir = [&](const EvParameter& t) { return to_exact_vec(t.den * av + t.num * ba); };

  std::vector<Invalid> invalid;
  // Vertex rule: constant between breakpoints; test each open piece at its midpoint and each breakpoint.
  {
    std::vector<std::pair<EvParameter, int>> pts{{EvParameter::integer(0), -1}};
    for (auto& bp : vertex_rule_breakpoints(scene, fan, av, bv)) pts.push_back(std::move(bp));
    pts.emplace_back(EvParameter::integer(1), -1);
    auto end_at = [&](int ti) {
      CriticalEnd x;
      x.cause = ti >= 0 ? CriticalEnd::Cause::Tangency : CriticalEnd::Cause::EdgeEndpoint;
      x.triangle = ti >= 0 ? scene.triangles[ti].id : -1;
      return x;
    };
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      if (!line_tangent_at_vertex(scene, fan, dir(midpoint(pts[i].first, pts[i + 1].first)), normal).tangent)
        invalid.push_back({pts[i].first, pts[i + 1].first, end_at(pts[i].second), end_at(pts[i + 1].second)});
      if (i + 1 < pts.size() - 1) {
        const auto& [t, ti] = pts[i + 1];
        if (!line_tangent_at_vertex(scene, fan, dir(t), normal).tangent) invalid.push_back({t, t, end_at(ti), end_at(ti)});
      }
    }
  }
  // Occluders: closed triangles not incident to V and not having E as an edge. Large ones first (a float
  // heuristic for order only), and stop as soon as the invalid set covers [0, 1].
  std::vector<std::pair<double, int>> cand;
  for (int ti : index.triangles_meeting_triangle(pv, pa, pb)) {
    const auto& t = scene.triangles[ti];
    if (has_vertex(t, v) || (has_vertex(t, e.v[0]) && has_vertex(t, e.v[1]))) continue;
    const Point3 &p0 = scene.corner(t, 0), &p1 = scene.corner(t, 1), &p2 = scene.corner(t, 2);
    const Point3 c = cross(p1 - p0, p2 - p0);
    cand.emplace_back(-dot(c, c), ti);
  }
  std::sort(cand.begin(), cand.end());
  int since_check = 0;
  for (const auto& [key, ti] : cand) {
    const auto& t = scene.triangles[ti];
    if (stats) ++stats->occluder_tests;
    const auto b = wedge_blocked_interval(pv, pa, pb, {scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2)},
                                          {t.v[0], t.v[1], t.v[2]});
    if (!b) continue;
    invalid.push_back({b->lo, b->hi, occluder_end(t.id, b->lo_feature), occluder_end(t.id, b->hi_feature)});
    if (++since_check >= 4) {
      since_check = 0;
      if (covers_unit_interval(invalid)) return std::nullopt;
    }
  }
  EvEvent ev;
  ev.vertex = v;
  ev.edge = e.v;
  ev.intervals = free_components(std::move(invalid));
  if (ev.intervals.empty()) return std::nullopt;
  for (auto& iv : ev.intervals)
    for (auto* end : {&iv.end0, &iv.end1}) {
      const Exact t = rational_parameter(end == &iv.end0 ? iv.t0 : iv.t1);
      if (end->cause == CriticalEnd::Cause::EdgeEndpoint) end->vertex = CGAL::is_zero(t) ? e.v[0] : e.v[1];
      end->line = ev_end_key(scene, adj, v, e.v, t, *end);
    }
  return ev;
}

EvResult join_per_vertex_ev(std::vector<std::vector<EvEvent>>&& per_vertex, const std::vector<EvStats>& stats) {
  EvResult result;
  for (std::size_t v = 0; v < per_vertex.size(); ++v) {
    for (auto& ev : per_vertex[v]) result.events.push_back(std::move(ev));
    result.stats.pairs += stats[v].pairs;
    result.stats.tangent_pairs += stats[v].tangent_pairs;
    result.stats.occluder_tests += stats[v].occluder_tests;
  }
  return result;
}

EvResult enumerate_ev_events(const Scene& scene, const EvOptions& options) {
  const SceneAdjacency adj = build_scene_adjacency(scene);
  const TriangleIndex index(scene);
  const int nv = static_cast<int>(scene.vertices.size());

  std::vector<char> light_vertex(nv, 0);
  std::vector<int> light_edges;
  const bool restricted = !options.light_triangles.empty();
  for (int ti : options.light_triangles) {
    const auto& t = scene.triangles.at(ti);
    for (int k = 0; k < 3; ++k) {
      light_vertex[t.v[k]] = 1;
      light_edges.push_back(adj.edge_index(t.v[k], t.v[(k + 1) % 3]));
    }
  }
  std::sort(light_edges.begin(), light_edges.end());
  light_edges.erase(std::unique(light_edges.begin(), light_edges.end()), light_edges.end());

  std::vector<std::vector<EvEvent>> per_vertex(nv);
  std::vector<EvStats> per_vertex_stats(nv);
  ProgressBar bar("EV events", static_cast<std::uint64_t>(nv), options.progress);
  auto work = [&](int v) {
    if (!adj.vertex_triangles[v].empty()) {
      const VertexFan fan = build_vertex_fan(scene, adj, v);
      EvStats& st = per_vertex_stats[v];
      auto one = [&](int ei) {
        if (options.accept_pair && !options.accept_pair(v, adj.edges[ei].v)) return;
        auto ev = ev_event(scene, adj, index, fan, ei, &st);
        if (!ev) return;
        if (options.accept_interval) {
          std::erase_if(ev->intervals,
                        [&](const CriticalInterval& iv) { return !options.accept_interval(v, ev->edge, iv); });
          if (ev->intervals.empty()) return;
        }
        per_vertex[v].push_back(std::move(*ev));
      };
      if (!restricted || light_vertex[v]) {
        for (int ei = 0; ei < static_cast<int>(adj.edges.size()); ++ei) one(ei);
      } else {
        for (int ei : light_edges) one(ei);
      }
    }
    bar.advance();
  };
  for_each_index(static_cast<std::size_t>(nv), options.parallel, 1, [&](std::size_t v) { work(static_cast<int>(v)); });
  EvResult result = join_per_vertex_ev(std::move(per_vertex), per_vertex_stats);
  if (options.segment_ends && !result.events.empty()) {
    const TriangleIndex& spatial = index;
    const Box3 box = bounding_box(scene);
    ProgressBar ends_bar("segment ends", result.events.size(), options.progress);
    auto ends = [&](EvEvent& ev) {
      if (options.split_at_end_objects) {
        std::vector<CriticalInterval> pieces;
        for (const auto& iv : ev.intervals)
          for (auto& piece : split_ev_interval(scene, adj, spatial, box, ev.vertex, ev.edge, iv))
            pieces.push_back(std::move(piece));
        ev.intervals = std::move(pieces);
        ends_bar.advance();
        return;
      }
      const Vec3<Exact> V = to_rational(scene.vertices[ev.vertex]);
      for (auto& iv : ev.intervals) {
        iv.sample_t = (rational_parameter(iv.t0) + rational_parameter(iv.t1)) / 2;
        const Vec3<Exact> p = ev_edge_point(scene, ev.edge, iv.sample_t);
        const Vec3<Exact> d = p - V;
        const RayHit beyond = ray_first_hit(scene, spatial, box, p, d, {ev.edge[0], ev.edge[1]});  // p lies on E
        const RayHit behind = ray_first_hit(scene, spatial, box, V, -d);
        iv.front_object = beyond.triangle >= 0 ? scene.triangles[beyond.triangle].id : -1;
        iv.back_object = behind.triangle >= 0 ? scene.triangles[behind.triangle].id : -1;
      }
      ends_bar.advance();
    };
    for_each_index(result.events.size(), options.parallel, 16, [&](std::size_t i) { ends(result.events[i]); });
  }
  return result;
}

}  // namespace exactvis
