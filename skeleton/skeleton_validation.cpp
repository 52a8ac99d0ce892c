#include "skeleton/skeleton_validation.hpp"

#include "events/scene_adjacency.hpp"
#include "events/tangency.hpp"
#include "skeleton/node_validity.hpp"

#include <algorithm>
#include <map>
#include <sstream>

namespace exactvis {
namespace {

using R = RootNumber;

Vec3<R> lift(const Point3& p) { return {R(Exact(p.x)), R(Exact(p.y)), R(Exact(p.z))}; }

// A family: EV (vertex, edge) or EEE (three sorted edges).
struct Family {
  SkeletonArcKind kind;
  int vertex;
  std::array<EdgeIds, 3> edges;
  friend auto operator<=>(const Family&, const Family&) = default;
};

Family family_of(const SkeletonArc& a) {
  Family f{a.kind, a.vertex, a.edges};
  if (a.kind == SkeletonArcKind::EV) f.edges[1] = f.edges[2] = EdgeIds{-1, -1};
  return f;
}

Family ev_family(int v, const EdgeIds& e) { return {SkeletonArcKind::EV, v, {e, EdgeIds{-1, -1}, EdgeIds{-1, -1}}}; }
Family eee_family(EdgeIds a, EdgeIds b, EdgeIds c) {
  std::array<EdgeIds, 3> e{a, b, c};
  std::sort(e.begin(), e.end());
  return {SkeletonArcKind::EEE, -1, e};
}

bool has_endpoint(const EdgeIds& e, int v) { return e[0] == v || e[1] == v; }

// Whether edge e's point on the node's line is an end of its spanned segment (outermost).
bool outermost(const Scene& scene, const SkeletonNode& n, const EdgeIds& e) {
  const Vec3<R> d = n.to - n.from;
  const Vec3<R> a = lift(scene.vertices[e[0]]), b = lift(scene.vertices[e[1]]);
  const auto u = edge_meeting_parameter(n.from, d, a, b);
  if (!u) return false;
  const Vec3<R> x = a + *u * (b - a);
  return x == n.from || x == n.to;
}

// Whether the node's line meets edge e in its relative interior.
bool meets_interior(const Scene& scene, const SkeletonNode& n, const EdgeIds& e) {
  const Vec3<R> d = n.to - n.from;
  const Vec3<R> a = lift(scene.vertices[e[0]]), b = lift(scene.vertices[e[1]]);
  const auto u = edge_meeting_parameter(n.from, d, a, b);
  if (!u || CGAL::sign(*u) <= 0 || !(*u < R(1))) return false;
  const Vec3<R> off = cross(a + *u * (b - a) - n.from, d);
  return CGAL::is_zero(dot(off, off));
}

// Whether the fan of v has no closed link cycles (the vertex rule is then rule (a) alone).
bool open_fan(const SceneAdjacency& adj, const Scene& scene, int v) { return build_vertex_fan(scene, adj, v).cycles.empty(); }

std::string family_text(const Family& f) {
  std::ostringstream os;
  if (f.kind == SkeletonArcKind::EV) {
    os << "EV(v " << f.vertex << "; e [" << f.edges[0][0] << "," << f.edges[0][1] << "])";
  } else {
    os << "EEE(e";
    for (const auto& e : f.edges) os << " [" << e[0] << "," << e[1] << "]";
    os << ")";
  }
  return os.str();
}

}  // namespace

SkeletonCheck validate_skeleton(const Scene& scene, const Skeleton3D& sk) {
  SkeletonCheck out;
  const SceneAdjacency adj = build_scene_adjacency(scene);
  auto problem = [&](const std::string& s) { out.problems.push_back(s); };
  const int nn = static_cast<int>(sk.nodes.size());
  std::vector<std::vector<int>> expected(sk.nodes.size());
  for (std::size_t i = 0; i < sk.arcs.size(); ++i) {
    const auto& a = sk.arcs[i];
    for (int n : a.nodes) {
      if (n < 0 || n >= nn) {
        problem("arc " + std::to_string(i) + ": end node " + std::to_string(n) + " out of range");
        continue;
      }
      expected[n].push_back(static_cast<int>(i));
    }
  }
  for (int n = 0; n < nn; ++n) {
    const SkeletonNode& node = sk.nodes[n];
    std::vector<int> got = node.arcs;
    std::sort(got.begin(), got.end());
    std::sort(expected[n].begin(), expected[n].end());
    if (got != expected[n]) problem(to_string(node.key) + ": its arc list differs from the arcs ending there");
    if (node.arcs.empty()) problem(to_string(node.key) + ": no arc ends here");
  }
  for (int n = 0; n < nn; ++n) {
    const SkeletonNode& node = sk.nodes[n];
    const ExtremalLineKey& k = node.key;
    if (!node.valid) continue;
    std::map<Family, int> count;
    for (int a : node.arcs) ++count[family_of(sk.arcs[a])];
    // expected[f] = exact count; "relaxed" families (a vertex generator relaxed to an edge at it): <= 1 each,
    // an even number >= 2 per vertex.
    std::map<Family, int> exact;
    std::map<int, std::vector<Family>> relaxed;  // vertex -> its allowed families
    std::map<Family, int> at_most;               // non-generic extra families: at most that many arcs
    auto allow_relaxed = [&](int v, const Family& f) { relaxed[v].push_back(f); };
    switch (k.kind) {
      case ExtremalLineKind::VV: {
        for (int side = 0; side < 2; ++side)
          for (const auto& [f, c] : count) {
            if (f.kind != SkeletonArcKind::EV || f.vertex != k.vertices[side]) continue;
            if (has_endpoint(f.edges[0], k.vertices[1 - side])) allow_relaxed(k.vertices[1 - side], f);
            else if (meets_interior(scene, node, f.edges[0])) at_most[f] = 2;  // non-generic: l meets that edge
          }
        break;
      }
      case ExtremalLineKind::VEE: {
        const int v = k.vertices[0];
        for (int i = 0; i < 2; ++i) exact[ev_family(v, k.edges[i])] = outermost(scene, node, k.edges[1 - i]) ? 2 : 1;
        for (const auto& [f, c] : count)
          if (f.kind == SkeletonArcKind::EEE) {
            const auto& e = f.edges;
            for (int i = 0; i < 3; ++i)
              if (has_endpoint(e[i], v) && eee_family(e[i], k.edges[0], k.edges[1]) == f) allow_relaxed(v, f);
          }
        break;
      }
      case ExtremalLineKind::EEEE:
        for (int drop = 0; drop < 4; ++drop) {
          std::array<EdgeIds, 3> t;
          for (int i = 0, j = 0; i < 4; ++i)
            if (i != drop) t[j++] = k.edges[i];
          exact[eee_family(t[0], t[1], t[2])] = outermost(scene, node, k.edges[drop]) ? 2 : 1;
        }
        break;
      case ExtremalLineKind::FVE:
        // Open fan at v (rule (a) only): the line crosses f's plane and both sides are tangent; closed link
        // cycles: one side enters the solid.
        exact[ev_family(k.vertices[0], k.edges[0])] = open_fan(adj, scene, k.vertices[0]) ? 2 : 1;
        break;
      case ExtremalLineKind::FEE: {
        // EEE(e1, e2, g) with g an edge of face f.
        const SceneTriangle& f = scene.triangles[scene.index_of_id(k.faces[0])];
        for (int c = 0; c < 3; ++c) {
          const EdgeIds g = edge_ids(f.v[c], f.v[(c + 1) % 3]);
          // One triangle at g: the edge rule fails only on f's plane (2 arcs); two: one side (1 arc).
          const int gi = adj.edge_index(g[0], g[1]);
          const int faces = gi < 0 ? 0 : static_cast<int>(adj.edges[gi].triangles.size());
          if (count.count(eee_family(k.edges[0], k.edges[1], g)))
            exact[eee_family(k.edges[0], k.edges[1], g)] = faces == 1 ? 2 : 1;
        }
        if (exact.empty()) problem(to_string(k) + ": no EEE arc of its two edges and an edge of its face");
        break;
      }
      default:
        continue;
    }
    ++out.nodes_checked;
    for (const auto& [f, c] : count) {
      bool allowed = exact.count(f) > 0 || (at_most.count(f) > 0 && c <= at_most.at(f));
      for (const auto& [v, fs] : relaxed) allowed = allowed || std::find(fs.begin(), fs.end(), f) != fs.end();
      if (!allowed) problem(to_string(k) + ": arc of " + family_text(f) + " is not in the catalogue of its kind");
    }
    for (const auto& [f, c] : exact)
      if ((count.count(f) ? count.at(f) : 0) != c)
        problem(to_string(k) + ": " + std::to_string(count.count(f) ? count.at(f) : 0) + " arcs of " +
                family_text(f) + ", the catalogue says " + std::to_string(c));
    std::map<int, int> per_vertex;
    for (const auto& [v, fs] : relaxed)
      for (const auto& f : fs) {
        if (count.at(f) > 1) problem(to_string(k) + ": " + std::to_string(count.at(f)) + " arcs of " + family_text(f) + ", at most 1");
        per_vertex[v] += count.at(f);
      }
    for (int i = 0; i < k.vertex_count(); ++i) {
      if (k.kind == ExtremalLineKind::FVE) break;
      const int c = per_vertex[k.vertices[i]];
      if (c < 2 || c % 2 != 0)
        problem(to_string(k) + ": " + std::to_string(c) + " arcs at vertex " + std::to_string(k.vertices[i]) +
                " (the catalogue: an even number >= 2)");
    }
  }
  return out;
}

}  // namespace exactvis
