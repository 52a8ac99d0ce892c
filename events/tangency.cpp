#include "events/tangency.hpp"

#include "kernel/predicates.hpp"

#include <map>

namespace exactvis {
namespace {

// sign of det(d, p - v, q - v).
Sign det_dir(const Vec3<Exact>& d, const Point3& v, const Point3& p, const Point3& q) {
  static PredicateCounter counter("ev_det_direction");
  return filtered_sign(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    const auto V = point_as<NT>(v);
    return dot(point_as<NT>(d), cross(point_as<NT>(p) - V, point_as<NT>(q) - V));
  });
}

// sign of det(d, r, p - v).
Sign det_dir_ref(const Vec3<Exact>& d, const Vec3<Exact>& r, const Point3& v, const Point3& p) {
  static PredicateCounter counter("ev_det_direction_ref");
  return filtered_sign(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    return dot(point_as<NT>(d), cross(point_as<NT>(r), point_as<NT>(p) - point_as<NT>(v)));
  });
}

// For d in the plane of (v, p, q): signs of the coefficients l1, l2 in d = l1 (p - v) + l2 (q - v),
// each scaled by the positive |w1 x w2|^2.
std::pair<Sign, Sign> in_plane_coefficients(const Vec3<Exact>& d, const Point3& v, const Point3& p, const Point3& q) {
  static PredicateCounter counter("ev_in_plane_coefficient");
  auto coef = [&](bool first) {
    return filtered_sign(counter, [&](auto nt) {
      using NT = typename decltype(nt)::type;
      const auto V = point_as<NT>(v);
      const auto w1 = point_as<NT>(p) - V;
      const auto w2 = point_as<NT>(q) - V;
      const auto D = point_as<NT>(d);
      const auto n = cross(w1, w2);
      return first ? dot(cross(D, w2), n) : dot(cross(w1, D), n);
    });
  };
  return {coef(true), coef(false)};
}

}  // namespace

VertexFan build_vertex_fan(const Scene& scene, const SceneAdjacency& adj, int v) {
  VertexFan fan;
  fan.vertex = v;
  fan.triangles = adj.vertex_triangles[v];
  std::map<int, std::vector<int>> link;  // link vertex -> neighbours in the link
  for (int ti : fan.triangles) {
    const auto& t = scene.triangles[ti];
    int k = 0;
    while (t.v[k] != v) ++k;
    const int p = t.v[(k + 1) % 3], q = t.v[(k + 2) % 3];
    link[p].push_back(q);
    link[q].push_back(p);
  }
  for (const auto& [w, nb] : link)
    if (nb.size() != 2) return fan;  // open or non-manifold link: no closed cycles
  std::map<int, bool> seen;
  for (const auto& [start, nb] : link) {
    if (seen[start]) continue;
    std::vector<int> cycle{start};
    seen[start] = true;
    int prev = start, cur = nb[0];
    while (cur != start) {
      cycle.push_back(cur);
      seen[cur] = true;
      const auto& n2 = link[cur];
      const int next = (n2[0] == prev) ? n2[1] : n2[0];
      prev = cur;
      cur = next;
    }
    fan.cycles.push_back(std::move(cycle));
  }
  return fan;
}

bool edge_tangent_in_plane(const Scene& scene, const SceneEdge& e, const Point3& v) {
  const Point3& a = scene.vertices[e.v[0]];
  const Point3& b = scene.vertices[e.v[1]];
  Sign side = Sign::Zero;
  for (int ti : e.triangles) {
    const auto& t = scene.triangles[ti];
    int w = t.v[0];
    for (int k = 0; k < 3; ++k)
      if (t.v[k] != e.v[0] && t.v[k] != e.v[1]) w = t.v[k];
    const Sign s = orient3d(a, b, v, scene.vertices[w]);
    if (s == Sign::Zero) return false;         // a face lies in the wedge plane: the line runs into it
    if (side != Sign::Zero && s != side) return false;  // faces on both sides: the line pierces the surface
    side = s;
  }
  return true;
}

VertexTangency line_tangent_at_vertex(const Scene& scene, const VertexFan& fan, const Vec3<Exact>& d,
                                      const Vec3<Exact>& ref) {
  const Point3& v = scene.vertices[fan.vertex];
  // (a) the line meets an incident triangle in a segment: d in its plane and +-d in its closed angle at v.
  for (int ti : fan.triangles) {
    const auto& t = scene.triangles[ti];
    int k = 0;
    while (t.v[k] != fan.vertex) ++k;
    const Point3& p = scene.vertices[t.v[(k + 1) % 3]];
    const Point3& q = scene.vertices[t.v[(k + 2) % 3]];
    if (det_dir(d, v, p, q) != Sign::Zero) continue;
    const auto [l1, l2] = in_plane_coefficients(d, v, p, q);
    const bool same = (to_int(l1) >= 0 && to_int(l2) >= 0) || (to_int(l1) <= 0 && to_int(l2) <= 0);
    if (same) return {false, ti};
  }
  // (b) winding number of each closed link cycle around the line (projection along d, Sunday's crossing
  // rule with the reference ray along the projection of `ref`). After (a), the line avoids every link arc.
  for (const auto& cycle : fan.cycles) {
    int winding = 0;
    const int k = static_cast<int>(cycle.size());
    for (int i = 0; i < k; ++i) {
      const Point3& p = scene.vertices[cycle[i]];
      const Point3& q = scene.vertices[cycle[(i + 1) % k]];
      const int yp = to_int(det_dir_ref(d, ref, v, p));
      const int yq = to_int(det_dir_ref(d, ref, v, q));
      if (yp <= 0 && yq > 0) {
        if (det_dir(d, v, p, q) == Sign::Positive) ++winding;
      } else if (yp > 0 && yq <= 0) {
        if (det_dir(d, v, p, q) == Sign::Negative) --winding;
      }
    }
    if (winding != 0) return {false, -1};
  }
  return {true, -1};
}

}  // namespace exactvis
