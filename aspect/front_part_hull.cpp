#include "aspect/front_part_hull.hpp"

#include "kernel/predicates.hpp"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <map>
#include <set>

namespace exactvis {

bool FrontHull::contains(const Vec3<Exact>& a) const {
  for (const auto& [nv, c] : facets)
    if (dot(nv, a) > c) return false;
  return true;
}

FrontHull front_hull(const std::vector<Vec3<Exact>>& P) {
  FrontHull h;
  if (P.empty()) return h;
  // Full-dimensional iff some four points are not coplanar.
  std::size_t i1 = 1, i2 = 0, i3 = 0;
  for (; i1 < P.size() && P[i1] == P[0]; ++i1) {}
  Vec3<Exact> normal{Exact(0), Exact(0), Exact(0)};
  for (std::size_t j = i1 + 1; j < P.size() && i2 == 0; ++j) {
    const Vec3<Exact> c = cross(P[i1] - P[0], P[j] - P[0]);
    if (!(c.x == 0 && c.y == 0 && c.z == 0)) i2 = j, normal = c;
  }
  for (std::size_t j = 0; j < P.size() && i2 != 0 && i3 == 0; ++j)
    if (dot(normal, P[j] - P[0]) != 0) i3 = j;
  if (i3 == 0) return h;
  using K = CGAL::Simple_cartesian<Exact>;
  std::vector<K::Point_3> pts;
  std::map<std::array<Exact, 3>, std::size_t> index;
  for (std::size_t i = 0; i < P.size(); ++i) {
    pts.emplace_back(P[i].x, P[i].y, P[i].z);
    index.emplace(std::array<Exact, 3>{P[i].x, P[i].y, P[i].z}, i);
  }
  CGAL::Surface_mesh<K::Point_3> mesh;
  CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
  const auto id = [&](auto v) {
    const K::Point_3& p = mesh.point(v);
    return index.at({p.x(), p.y(), p.z()});
  };
  Vec3<Exact> centroid{Exact(0), Exact(0), Exact(0)};
  for (const auto& p : P) centroid = centroid + p;
  const Exact count(static_cast<int>(P.size()));
  centroid = Vec3<Exact>{centroid.x / count, centroid.y / count, centroid.z / count};
  for (auto f : mesh.faces()) {
    std::vector<std::size_t> c;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) c.push_back(id(v));
    Vec3<Exact> nv = cross(P[c[1]] - P[c[0]], P[c[2]] - P[c[0]]);
    if (dot(nv, centroid - P[c[0]]) > 0) nv = -nv;  // outward (the centroid is interior)
    h.facets.push_back({nv, dot(nv, P[c[0]])});
  }
  for (auto e : mesh.edges()) h.edges.push_back({id(mesh.vertex(e, 0)), id(mesh.vertex(e, 1))});
  h.full = true;
  return h;
}

int supporting_side(const Vec3<Exact>& normal, const Vec3<Exact>& origin, const std::vector<Vec3<Exact>>& P) {
  int side = 0;
  for (const auto& p : P) {
    const int sp = CGAL::sign(dot(normal, p - origin));
    if (sp == 0) continue;
    if (side == 0) side = sp;
    else if (sp != side) return 0;
  }
  return side;
}

std::array<int, 2> ev_plane_edge(const Vec3<Exact>& normal, int vertex, const Vec3<Exact>& u, const Vec3<Exact>& w,
                                 const std::vector<std::array<int, 2>>& edges, const std::vector<Vec3<Exact>>& vx) {
  const Vec3<Exact>& a = vx[vertex];
  std::array<int, 2> edge{-1, -1};
  bool on_line = false;
  for (const auto& e : edges) {
    if (e[0] == vertex || e[1] == vertex) continue;
    const Vec3<Exact>& A = vx[e[0]];
    const Vec3<Exact>& B = vx[e[1]];
    if (dot(normal, A - a) != 0 || dot(normal, B - a) != 0) continue;
    const Vec3<Exact> c = cross(B - A, a - A);
    if (c.x == 0 && c.y == 0 && c.z == 0) continue;  // a on the edge's line: no EV set
    const Vec3<Exact> d1 = cross(w - u, A - u), d2 = cross(w - u, B - u);
    const bool collinear_uw = d1.x == 0 && d1.y == 0 && d1.z == 0 && d2.x == 0 && d2.y == 0 && d2.z == 0;
    if (edge[0] < 0 || (collinear_uw && !on_line)) edge = e, on_line = collinear_uw;
    if (on_line) break;
  }
  return edge;
}

SceneEdgeTable scene_edge_table(const Scene& scene) {
  std::set<std::pair<int, int>> edge_set;
  for (const auto& t : scene.triangles)
    for (int k = 0; k < 3; ++k) edge_set.insert(std::minmax(t.v[k], t.v[(k + 1) % 3]));
  SceneEdgeTable table;
  for (const auto& [a, b] : edge_set) table.edges.push_back({a, b});
  table.vx.resize(scene.vertices.size());
  for (std::size_t i = 0; i < table.vx.size(); ++i) table.vx[i] = to_rational(scene.vertices[i]);
  return table;
}

}  // namespace exactvis
