#include "skeleton/skeleton_pair.hpp"

#include "events/ev_pencil_filter.hpp"
#include "kernel/predicates.hpp"
#include "kernel/triangle_index.hpp"
#include "skeleton/node_validity.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <set>

namespace exactvis {
namespace {

bool pair_matches(const Scene& scene, const std::array<std::int64_t, 2>& ends, const SkeletonPairSide& a,
                  const SkeletonPairSide& b) {
  return (on_side(scene, ends[0], a) && on_side(scene, ends[1], b)) ||
         (on_side(scene, ends[0], b) && on_side(scene, ends[1], a));
}

void grow(Box3& box, const Point3& p) {
  box.lo.x = std::min(box.lo.x, p.x), box.lo.y = std::min(box.lo.y, p.y), box.lo.z = std::min(box.lo.z, p.z);
  box.hi.x = std::max(box.hi.x, p.x), box.hi.y = std::max(box.hi.y, p.y), box.hi.z = std::max(box.hi.z, p.z);
}

// True iff proved that the line {origin + s dir} misses the closed box: the parameter ranges of the slabs
// of the axes where dir is certainly non-zero are certainly disjoint (interval arithmetic), or the line is
// certainly outside a slab of an axis along which it certainly does not move. Not thread-safe (RootNumber
// caches): the caller passes its own copies.
bool line_misses_box(const Vec3<RootNumber>& origin, const Vec3<RootNumber>& dir, const Box3& box) {
  using I = CGAL::Interval_nt<>;
  double s_lo = -std::numeric_limits<double>::infinity(), s_hi = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const auto oi = CGAL::to_interval(origin[k]), di = CGAL::to_interval(dir[k]);
    const I o(oi.first, oi.second), d(di.first, di.second);
    if (is_zero_root(dir[k])) {
      if (o.sup() < box.lo[k] || o.inf() > box.hi[k]) return true;
      continue;
    }
    if (!(d.inf() > 0 || d.sup() < 0)) continue;  // no certain slab range
    const I u = (I(box.lo[k]) - o) / d, v = (I(box.hi[k]) - o) / d;
    const I lo = d.inf() > 0 ? u : v, hi = d.inf() > 0 ? v : u;  // the slab's parameter range [lo, hi]
    s_lo = std::max(s_lo, lo.inf());
    s_hi = std::min(s_hi, hi.sup());
    if (s_lo > s_hi) return true;
  }
  return false;
}

}  // namespace

bool on_side(const Scene& scene, std::int64_t end, const SkeletonPairSide& side) {
  if (end < 0) return false;
  if (side.triangle >= 0) return end == side.triangle;
  return object_of_triangle(scene, end) == side.object;
}

SkeletonPairSlice pair_slice(const Scene& scene, const Skeleton3D& sk, const SkeletonPairSide& a,
                             const SkeletonPairSide& b) {
  SkeletonPairSlice s;
  for (std::size_t i = 0; i < sk.nodes.size(); ++i)
    if (pair_matches(scene, sk.nodes[i].ends, a, b)) s.nodes.push_back(static_cast<int>(i));
  for (std::size_t i = 0; i < sk.arcs.size(); ++i)
    if (pair_matches(scene, sk.arcs[i].ends, a, b)) s.arcs.push_back(static_cast<int>(i));
  return s;
}

Skeleton3D build_pair_skeleton(const Scene& scene, const SkeletonPairSide& a, const SkeletonPairSide& b,
                               const SkeletonOptions& options) {
  // The bounding box of both sides' triangles.
  Box3 box{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
  for (const SceneTriangle& t : scene.triangles)
    if (on_side(scene, t.id, a) || on_side(scene, t.id, b))
      for (int k = 0; k < 3; ++k) grow(box, scene.corner(t, k));
  Skeleton3D out;
  if (box.empty()) return out;
  std::vector<std::int64_t> keep = TriangleIndex(scene).triangles_meeting_box(box);
  std::sort(keep.begin(), keep.end());
  // The sub-scene: kept triangles in id order, vertices compacted in order (a monotone map of ids).
  std::vector<int> new_of(scene.vertices.size(), -1), old_of;
  for (std::int64_t ti : keep)
    for (int v : scene.triangles[ti].v) new_of[v] = 0;
  Scene sub;
  for (std::size_t v = 0; v < scene.vertices.size(); ++v)
    if (new_of[v] == 0) {
      new_of[v] = static_cast<int>(old_of.size());
      old_of.push_back(static_cast<int>(v));
      sub.vertices.push_back(scene.vertices[v]);
    }
  for (std::int64_t ti : keep) {
    SceneTriangle t = scene.triangles[ti];
    for (int& v : t.v) v = new_of[v];
    sub.triangles.push_back(t);
  }
  sub.objects = scene.objects;
  sub.faces_read = scene.faces_read;
  // Only EV pairs and free intervals some line of which can meet both sides (docs/theory.md section 9, "Lazy
  // build of one pair"): a line of the slice, or an end node of one of its arcs (a limit of such lines, the
  // sides being closed), meets a and b. The pencil-range certificate (events/ev_pencil_filter) proves that
  // no line L(t), t in the range, meets a side: its box, or each of its triangles.
  std::array<PencilSide, 2> sides;
  {
    std::array<std::map<int, int>, 2> index_of;  // sub-scene vertex id -> index into the side's points
    for (const SceneTriangle& t : sub.triangles)
      for (int s = 0; s < 2; ++s)
        if (on_side(scene, t.id, s == 0 ? a : b)) {
          std::array<int, 3> tri;
          for (int k = 0; k < 3; ++k) {
            const auto [it, inserted] = index_of[s].try_emplace(t.v[k], static_cast<int>(sides[s].points.size()));
            if (inserted) sides[s].points.push_back(sub.vertices[t.v[k]]);
            tri[k] = it->second;
            grow(sides[s].box, sub.vertices[t.v[k]]);
          }
          sides[s].triangles.push_back(tri);
        }
  }
  auto reachable = [&](int v, const std::array<int, 2>& e, std::pair<double, double> t0, std::pair<double, double> t1) {
    const EvPencilRange range(sub.vertices[v], sub.vertices[e[0]], sub.vertices[e[1]], t0.first, t0.second,
                              t1.first, t1.second);
    return !range.misses_side(sides[0]) && !range.misses_side(sides[1]);
  };
  SkeletonOptions sub_options = options;
  sub_options.accept_ev_pair = [&](int v, const std::array<int, 2>& e) { return reachable(v, e, {0, 0}, {1, 1}); };
  sub_options.accept_ev_interval = [&](int v, const std::array<int, 2>& e, const CriticalInterval& iv) {
    return reachable(v, e, enclosing_interval(rational_parameter(iv.t0)), enclosing_interval(rational_parameter(iv.t1)));
  };
  // Only the slice's nodes and arcs and the arcs' end nodes are used: the other nodes need no validity, and
  // a node line proved to miss a side's box is none of them (no end objects for it).
  sub_options.wanted_ends = [&](const std::array<std::int64_t, 2>& ends) { return pair_matches(scene, ends, a, b); };
  sub_options.node_line_may_matter = [&](const Vec3<RootNumber>& o, const Vec3<RootNumber>& d) {
    return !line_misses_box(o, d, sides[0].box) && !line_misses_box(o, d, sides[1].box);
  };
  const Skeleton3D full = build_skeleton_3d(sub, sub_options);

  // The slice, with its arcs' end nodes, renumbered; ids mapped back.
  const SkeletonPairSlice slice = pair_slice(scene, full, a, b);
  std::set<int> nodes(slice.nodes.begin(), slice.nodes.end());
  for (int ai : slice.arcs) nodes.insert(full.arcs[ai].nodes.begin(), full.arcs[ai].nodes.end());
  std::map<int, int> node_pos;
  auto back = [&](int v) { return v < 0 ? v : old_of[v]; };
  auto back_edge = [&](EdgeIds e) { return EdgeIds{back(e[0]), back(e[1])}; };
  for (int ni : nodes) {
    node_pos[ni] = static_cast<int>(out.nodes.size());
    SkeletonNode n = full.nodes[ni];
    for (int& v : n.key.vertices) v = back(v);
    for (EdgeIds& e : n.key.edges) e = back_edge(e);
    n.arcs.clear();
    out.nodes.push_back(std::move(n));
  }
  for (int ai : slice.arcs) {
    SkeletonArc arc = full.arcs[ai];
    arc.vertex = back(arc.vertex);
    for (EdgeIds& e : arc.edges) e = back_edge(e);
    for (int& n : arc.nodes) {
      n = node_pos.at(n);
      out.nodes[n].arcs.push_back(static_cast<int>(out.arcs.size()));
    }
    out.arcs.push_back(std::move(arc));
  }
  for (auto& n : out.nodes) std::sort(n.arcs.begin(), n.arcs.end());
  fill_object_table(scene, out);
  out.stats = full.stats;
  return out;
}

std::vector<int> pair_blockers(const Scene& scene, const Skeleton3D& sk, const SkeletonPairSlice& slice,
                               const SkeletonPairSide& a, const SkeletonPairSide& b) {
  // Objects of each vertex id (a vertex may belong to several objects' triangles).
  std::map<int, std::set<int>> objects_of_vertex;
  for (const SceneTriangle& t : scene.triangles)
    for (int v : t.v) objects_of_vertex[v].insert(t.object);
  std::set<int> out;
  auto add_vertex = [&](int v) {
    if (v < 0) return;
    for (int o : objects_of_vertex[v]) out.insert(o);
  };
  for (int ni : slice.nodes) {
    const ExtremalLineKey& k = sk.nodes[ni].key;
    for (int i = 0; i < k.vertex_count(); ++i) add_vertex(k.vertices[i]);
    for (int i = 0; i < k.edge_count(); ++i) add_vertex(k.edges[i][0]), add_vertex(k.edges[i][1]);
    for (int i = 0; i < k.face_count(); ++i) out.insert(object_of_triangle(scene, k.faces[i]));
  }
  for (int ai : slice.arcs) {
    const SkeletonArc& arc = sk.arcs[ai];
    add_vertex(arc.vertex);
    for (const EdgeIds& e : arc.edges) add_vertex(e[0]), add_vertex(e[1]);
  }
  // a's and b's own objects are not blockers.
  auto own = [&](const SkeletonPairSide& s) {
    return s.triangle >= 0 ? object_of_triangle(scene, s.triangle) : s.object;
  };
  out.erase(own(a));
  out.erase(own(b));
  return {out.begin(), out.end()};
}

}  // namespace exactvis
