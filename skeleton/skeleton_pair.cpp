#include "skeleton/skeleton_pair.hpp"

#include "kernel/predicates.hpp"
#include "kernel/triangle_index.hpp"

#include <algorithm>
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
  // Only EV pairs whose wedge plane can meet both sides (docs/theory.md section 9, "Lazy build of one pair"):
  // every line of an EV set lies in the plane of V and E, and a line of the slice, or an end node of one of
  // its arcs (a limit of such lines, the sides being closed), meets a and b. The plane misses a side when all
  // of that side's vertices lie strictly on one side of it (exact orient3d on the scene's doubles).
  std::array<std::vector<int>, 2> side_vertices;
  for (const SceneTriangle& t : sub.triangles)
    for (int s = 0; s < 2; ++s)
      if (on_side(scene, t.id, s == 0 ? a : b)) side_vertices[s].insert(side_vertices[s].end(), t.v.begin(), t.v.end());
  for (auto& vs : side_vertices) {
    std::sort(vs.begin(), vs.end());
    vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
  }
  SkeletonOptions sub_options = options;
  sub_options.accept_ev_pair = [&](int v, const std::array<int, 2>& e) {
    const Point3 &pv = sub.vertices[v], &pa = sub.vertices[e[0]], &pb = sub.vertices[e[1]];
    for (const auto& vs : side_vertices) {
      bool pos = false, neg = false, zero = false;
      for (int w : vs) {
        const Sign o = orient3d(pv, pa, pb, sub.vertices[w]);
        (o == Sign::Positive ? pos : o == Sign::Negative ? neg : zero) = true;
        if (zero || (pos && neg)) break;
      }
      if (!zero && !(pos && neg)) return false;  // the side is strictly on one side of the plane
    }
    return true;
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
