#include "skeleton/visibility_skeleton_3d.hpp"

#include "events/eee_enumeration.hpp"
#include "events/eee_events.hpp"
#include "events/ev_events.hpp"
#include "events/scene_adjacency.hpp"
#include "kernel/rational_between.hpp"
#include "kernel/triangle_index.hpp"
#include "skeleton/node_validity.hpp"
#include "skeleton/line_first_hit.hpp"
#include "util/for_each_index.hpp"
#include "util/progress_bar.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <utility>

namespace exactvis {
namespace {

using R = RootNumber;

Vec3<R> lift(const Point3& p) { return {R(Exact(p.x)), R(Exact(p.y)), R(Exact(p.z))}; }
Vec3<R> lift(const Vec3<Exact>& p) { return {R(p.x), R(p.y), R(p.z)}; }

// A node's line as first met at an arc end: a point, a direction, and (FEE) the EEE family's points.
struct NodeLine {
  Vec3<R> origin, dir;
  std::vector<Vec3<R>> family_points;
};

// The point where the line (o, d) meets the line of edge (a, b), when they meet at a finite point.
std::optional<Vec3<R>> meet_edge_line(const Vec3<R>& o, const Vec3<R>& d, const Vec3<R>& a, const Vec3<R>& b) {
  const auto u = edge_meeting_parameter(o, d, a, b);
  if (!u) return std::nullopt;
  return a + *u * (b - a);
}

// The parameter of the EEE family `ev` (t along E1) at which its line is the line (o, d) (which must meet
// E1's line at a finite point).
std::optional<R> family_parameter(const Scene& scene, const EeeEvent& ev, const Vec3<R>& o, const Vec3<R>& d) {
  const Vec3<R> a = lift(scene.vertices[ev.edges[0][0]]), b = lift(scene.vertices[ev.edges[0][1]]);
  const auto x = meet_edge_line(o, d, a, b);
  if (!x) return std::nullopt;
  const Vec3<R> w = b - a;
  return dot(*x - a, w) / dot(w, w);
}

NodeLine ev_end_line(const Scene& scene, const EvEvent& ev, const R& t) {
  const Vec3<Exact> p = ev_edge_point(scene, ev.edge, rational_parameter(t));
  const Vec3<R> v = lift(scene.vertices[ev.vertex]);
  return {v, lift(p) - v, {}};
}

NodeLine eee_end_line(const Scene& scene, const EeeEvent& ev, const R& t, bool keep_points) {
  const EeeLinePoints l = eee_line_points(scene, ev, t);
  NodeLine n{l.on_e1, l.direction, {}};
  if (keep_points) {
    n.family_points.push_back(l.on_e1);
    if (l.on_e2) n.family_points.push_back(*l.on_e2);
    if (l.on_e3) n.family_points.push_back(*l.on_e3);
  }
  return n;
}

// Spanned segment of a node and, when `ends` is set, its end objects.
void span_node(const Scene& scene, const TriangleIndex& index, const Box3& box, const NodeLine& line, bool ends,
               SkeletonNode& node) {
  std::vector<Vec3<R>> pts = line.family_points;
  // The edge line each point lies on by construction ({} when not known): rays from it need no exact
  // arithmetic for that edge's planes (kernel/ray_first_hit).
  std::vector<RayOriginOnEdgeLine> on(pts.size());
  const ExtremalLineKey& k = node.key;
  for (int i = 0; i < k.vertex_count(); ++i) {
    pts.push_back(lift(scene.vertices[k.vertices[i]]));
    on.emplace_back();
  }
  const int edges = k.kind == ExtremalLineKind::EEP ? 2 : k.edge_count();  // EEP: edge 3 is met at infinity
  for (int i = 0; i < edges; ++i) {
    const auto x = meet_edge_line(line.origin, line.dir, lift(scene.vertices[k.edges[i][0]]),
                                  lift(scene.vertices[k.edges[i][1]]));
    if (x) {
      pts.push_back(*x);
      on.push_back({k.edges[i][0], k.edges[i][1]});
    }
  }
  // Order along the line: every point is origin + lambda dir, so one axis with dir_k != 0 orders them
  // (lambda dir_k = p_k - origin_k; negated when dir_k < 0).
  int axis = 0;
  while (axis < 2 && is_zero_root(line.dir[axis])) ++axis;
  const bool flip = CGAL::sign(line.dir[axis]) < 0;
  std::size_t lo = 0, hi = 0;
  std::vector<R> s(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    s[i] = flip ? line.origin[axis] - pts[i][axis] : pts[i][axis] - line.origin[axis];
    if (s[i] < s[lo]) lo = i;
    if (s[hi] < s[i]) hi = i;
  }
  node.from = pts[lo];
  node.to = pts[hi];
  if (!ends) return;
  node.ends[0] = line_first_hit(scene, index, box, node.from, -line.dir, on[lo]);
  node.ends[1] = line_first_hit(scene, index, box, node.to, line.dir, on[hi]);
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

const char* arc_kind_name(SkeletonArcKind kind) { return kind == SkeletonArcKind::EV ? "EV" : "EEE"; }

int object_of_triangle(const Scene& scene, std::int64_t id) {
  if (id < 0) return -1;
  return scene.triangles[scene.index_of_id(id)].object;
}

Skeleton3D build_skeleton_3d(const Scene& scene, const SkeletonOptions& options) {
  Skeleton3D sk;
  const auto start = std::chrono::steady_clock::now();
  EvOptions ev_opt;
  ev_opt.progress = options.progress;
  ev_opt.parallel = options.parallel;
  ev_opt.accept_pair = options.accept_ev_pair;
  ev_opt.accept_interval = options.accept_ev_interval;
  EeeOptions eee_opt;
  eee_opt.progress = options.progress;
  eee_opt.parallel = options.parallel;
  const EvResult ev = enumerate_ev_events(scene, ev_opt);
  const EeeResult eee = enumerate_eee_events(scene, eee_opt);
  sk.stats.ev_events = ev.events.size();
  sk.stats.eee_events = eee.events.size();
  sk.stats.seconds_events = seconds_since(start);
  const auto node_start = std::chrono::steady_clock::now();

  // 1. Every arc end is a node; its line is taken from the first family that reaches it.
  std::map<ExtremalLineKey, NodeLine> lines;
  for (const EvEvent& e : ev.events)
    for (const CriticalInterval& iv : e.intervals) {
      if (!lines.count(iv.end0.line)) lines.emplace(iv.end0.line, ev_end_line(scene, e, iv.t0));
      if (!lines.count(iv.end1.line)) lines.emplace(iv.end1.line, ev_end_line(scene, e, iv.t1));
    }
  for (const EeeEvent& e : eee.events)
    for (const CriticalInterval& iv : e.intervals) {
      for (const auto* end : {&iv.end0, &iv.end1}) {
        if (lines.count(end->line)) continue;
        const bool fee = end->line.kind == ExtremalLineKind::FEE;
        lines.emplace(end->line, eee_end_line(scene, e, end == &iv.end0 ? iv.t0 : iv.t1, fee));
      }
    }

  // 2. EEE arcs are cut at the EEEE nodes strictly inside them: such a node's line is L(t) of the EEE
  // family of any three of its four edges.
  std::map<std::array<EdgeIds, 3>, int> eee_by_edges;
  for (std::size_t i = 0; i < eee.events.size(); ++i) eee_by_edges.emplace(eee.events[i].edges, static_cast<int>(i));
  // cuts[event][interval]: (parameter, node key)
  std::vector<std::map<int, std::vector<std::pair<R, ExtremalLineKey>>>> cuts(eee.events.size());
  for (const auto& [key, line] : lines) {
    if (key.kind != ExtremalLineKind::EEEE) continue;
    for (int drop = 0; drop < 4; ++drop) {
      std::array<EdgeIds, 3> tri;
      for (int i = 0, j = 0; i < 4; ++i)
        if (i != drop) tri[j++] = key.edges[i];
      std::sort(tri.begin(), tri.end());
      const auto it = eee_by_edges.find(tri);
      if (it == eee_by_edges.end()) continue;
      const EeeEvent& e = eee.events[it->second];
      const auto t = family_parameter(scene, e, line.origin, line.dir);
      if (!t) continue;
      for (std::size_t k = 0; k < e.intervals.size(); ++k)
        if (e.intervals[k].t0 < *t && *t < e.intervals[k].t1)
          cuts[it->second][static_cast<int>(k)].emplace_back(*t, key);
    }
  }

  // 3. Nodes sorted by key; arcs with their end nodes.
  std::map<ExtremalLineKey, int> node_of;
  for (const auto& [key, line] : lines) {
    node_of.emplace(key, static_cast<int>(sk.nodes.size()));
    SkeletonNode n;
    n.key = key;
    sk.nodes.push_back(std::move(n));
  }
  for (const EvEvent& e : ev.events)
    for (const CriticalInterval& iv : e.intervals) {
      SkeletonArc a;
      a.kind = SkeletonArcKind::EV;
      a.vertex = e.vertex;
      a.edges[0] = e.edge;
      a.t0 = iv.t0, a.t1 = iv.t1, a.sample_t = iv.sample_t;
      a.nodes = {node_of.at(iv.end0.line), node_of.at(iv.end1.line)};
      a.ends = {iv.back_object, iv.front_object};
      sk.arcs.push_back(std::move(a));
    }
  const TriangleIndex index(scene);
  const Box3 box = bounding_box(scene);
  const SceneAdjacency adj = build_scene_adjacency(scene);
  for (std::size_t ei = 0; ei < eee.events.size(); ++ei) {
    const EeeEvent& e = eee.events[ei];
    for (std::size_t k = 0; k < e.intervals.size(); ++k) {
      const CriticalInterval& iv = e.intervals[k];
      auto cit = cuts[ei].find(static_cast<int>(k));
      std::vector<std::pair<R, ExtremalLineKey>> pieces_at;
      if (cit != cuts[ei].end()) {
        pieces_at = cit->second;
        std::sort(pieces_at.begin(), pieces_at.end(), [](const auto& x, const auto& y) {
          return x.first < y.first || (!(y.first < x.first) && x.second < y.second);
        });
        // One cut per parameter (two EEEE keys of one line would be a degenerate regulus configuration:
        // the lower key names the cut).
        pieces_at.erase(std::unique(pieces_at.begin(), pieces_at.end(),
                                    [](const auto& x, const auto& y) { return x.first == y.first; }),
                        pieces_at.end());
      }
      EeeEvent piece_event;
      piece_event.edges = e.edges;
      std::vector<std::pair<int, int>> piece_nodes;
      R lo = iv.t0;
      int lo_node = node_of.at(iv.end0.line);
      for (std::size_t c = 0; c <= pieces_at.size(); ++c) {
        const R hi = c < pieces_at.size() ? pieces_at[c].first : iv.t1;
        const int hi_node = c < pieces_at.size() ? node_of.at(pieces_at[c].second) : node_of.at(iv.end1.line);
        CriticalInterval p = iv;
        p.t0 = lo, p.t1 = hi;
        if (!pieces_at.empty()) p.sample_t = rational_strictly_between(lo, hi);
        piece_event.intervals.push_back(std::move(p));
        piece_nodes.emplace_back(lo_node, hi_node);
        lo = hi, lo_node = hi_node;
      }
      if (!pieces_at.empty()) {
        eee_segment_ends(scene, index, box, piece_event);
        sk.stats.eee_cuts += pieces_at.size();
      }
      for (std::size_t c = 0; c < piece_event.intervals.size(); ++c) {
        const CriticalInterval& p = piece_event.intervals[c];
        SkeletonArc a;
        a.kind = SkeletonArcKind::EEE;
        a.edges = e.edges;
        a.t0 = p.t0, a.t1 = p.t1, a.sample_t = p.sample_t;
        a.nodes = {piece_nodes[c].first, piece_nodes[c].second};
        a.ends = {p.back_object, p.front_object};
        sk.arcs.push_back(std::move(a));
      }
    }
  }
  for (std::size_t i = 0; i < sk.arcs.size(); ++i)
    for (int n : sk.arcs[i].nodes) sk.nodes[n].arcs.push_back(static_cast<int>(i));

  // 4. Spanned segments and end objects (exact rays), in parallel: each task reads only its own node's line.
  std::vector<const NodeLine*> line_of(sk.nodes.size());
  {
    std::size_t i = 0;
    for (const auto& [key, line] : lines) line_of[i++] = &line;
  }
  // With SkeletonOptions::wanted_ends, only the nodes of wanted ends and the end nodes of wanted arcs get
  // their validity; node lines the caller proves irrelevant get no end objects.
  std::vector<char> needed(sk.nodes.size(), options.wanted_ends ? 0 : 1);
  {
    ProgressBar bar("skeleton: nodes", sk.nodes.size(), options.progress);
    for_each_index(sk.nodes.size(), options.parallel, 16, [&](std::size_t i) {
      const NodeLine copy = *line_of[i];  // own copies: RootNumber caches are not thread-safe
      const bool ends = !options.node_line_may_matter || options.node_line_may_matter(copy.origin, copy.dir);
      span_node(scene, index, box, copy, ends, sk.nodes[i]);
      if (needed[i]) sk.nodes[i].valid = node_line_valid(scene, adj, index, sk.nodes[i], copy.dir);
      bar.advance();
    });
  }
  if (options.wanted_ends) {
    for (std::size_t i = 0; i < sk.nodes.size(); ++i) needed[i] = options.wanted_ends(sk.nodes[i].ends) ? 1 : 0;
    for (const SkeletonArc& a : sk.arcs)
      if (options.wanted_ends(a.ends))
        for (int n : a.nodes) needed[n] = 1;
    std::vector<std::size_t> todo;
    for (std::size_t i = 0; i < sk.nodes.size(); ++i)
      if (needed[i]) todo.push_back(i);
    for_each_index(todo.size(), options.parallel, 16, [&](std::size_t j) {
      const NodeLine copy = *line_of[todo[j]];
      sk.nodes[todo[j]].valid = node_line_valid(scene, adj, index, sk.nodes[todo[j]], copy.dir);
    });
  }

  // 5. Durand's table.
  fill_object_table(scene, sk);
  sk.stats.seconds_nodes = seconds_since(node_start);
  return sk;
}

void fill_object_table(const Scene& scene, Skeleton3D& sk) {
  auto pair_key = [&](const std::array<std::int64_t, 2>& ends) {
    std::array<int, 2> k{object_of_triangle(scene, ends[0]), object_of_triangle(scene, ends[1])};
    if (k[1] < k[0]) std::swap(k[0], k[1]);
    return k;
  };
  sk.by_objects.clear();
  for (std::size_t i = 0; i < sk.nodes.size(); ++i) sk.by_objects[pair_key(sk.nodes[i].ends)].nodes.push_back(int(i));
  for (std::size_t i = 0; i < sk.arcs.size(); ++i) sk.by_objects[pair_key(sk.arcs[i].ends)].arcs.push_back(int(i));
}

SkeletonPairSlice skeleton_pair(const Skeleton3D& skeleton, int object_a, int object_b) {
  std::array<int, 2> k{std::min(object_a, object_b), std::max(object_a, object_b)};
  const auto it = skeleton.by_objects.find(k);
  return it == skeleton.by_objects.end() ? SkeletonPairSlice{} : it->second;
}

}  // namespace exactvis
