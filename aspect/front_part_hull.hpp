#pragma once
// The convex hull of a triangle's front part and the EV planes it spans (docs/theory.md §10.5, §10.8): shared
// by the orthographic aspect graph of closed solids (aspect/orthographic_aspect_graph) and their partition of
// a plane of viewpoints (aspect/plane_aspect_graph).
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <utility>
#include <vector>

namespace exactvis {

// The convex hull of a front part's points (CGAL convex_hull_3 over exact rationals): its facet planes
// (outward: n . x <= c inside) and its edges as index pairs into the points; `full` = false when the points
// are coplanar (then facets and edges are empty).
struct FrontHull {
  bool full = false;
  std::vector<std::pair<Vec3<Exact>, Exact>> facets;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  // Closed: a point on the boundary is contained.
  bool contains(const Vec3<Exact>& a) const;
};

// Input: distinct exact points. Output: their hull. Cost: one exact 3D hull of |P| points (expected
// O(|P| log |P|) exact orientation tests).
FrontHull front_hull(const std::vector<Vec3<Exact>>& P);

// The closed side of the plane {x : normal . (x - origin) = 0} that holds all of P: +1 or -1 (points on the
// plane allowed), 0 when P has points strictly on both sides or lies in the plane. Exact signs; cost O(|P|).
int supporting_side(const Vec3<Exact>& normal, const Vec3<Exact>& origin, const std::vector<Vec3<Exact>>& P);

// The scene edge naming the EV plane through the vertex `vertex` (index into vx) and the segment uw (two
// points of a front part) with normal `normal`: an edge lying in the plane, not through the vertex and not on
// one line with it, preferring one on the line uw; {-1, -1} when the plane holds none. `edges` are scene
// vertex index pairs. Cost: O(|edges|) exact signs.
std::array<int, 2> ev_plane_edge(const Vec3<Exact>& normal, int vertex, const Vec3<Exact>& u, const Vec3<Exact>& w,
                                 const std::vector<std::array<int, 2>>& edges, const std::vector<Vec3<Exact>>& vx);

// The tables ev_plane_edge searches: the scene's distinct edges (vertex index pairs {a, b} with a < b, in
// ascending order) and its vertices as exact rationals (vx[i] is scene.vertices[i]). Cost O(n log n), n the
// number of triangles.
struct SceneEdgeTable {
  std::vector<std::array<int, 2>> edges;
  std::vector<Vec3<Exact>> vx;
};
SceneEdgeTable scene_edge_table(const Scene& scene);

}  // namespace exactvis
