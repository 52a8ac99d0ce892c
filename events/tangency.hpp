#pragma once
// Tangency rules of EV critical lines at their generators (docs/theory.md section 6, "Tangency").
//
// Edge rule: a line crossing edge E in its relative interior is tangent at E iff the opposite vertices of all
//   triangles incident to E lie strictly on one side of the plane spanned by the line and E.
// Vertex rule: a line through vertex V with direction d is tangent at V iff (a) it meets no triangle incident
//   to V in more than V, and (b) for every closed link cycle of V's fan, the fan does not wind around the line
//   (winding number 0). Open fans (soup boundary vertices) only use (a).
#include "events/scene_adjacency.hpp"
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"

#include <vector>

namespace exactvis {

// The triangles around a vertex and, when every link vertex has degree 2, the link cycles in order.
struct VertexFan {
  int vertex = -1;
  std::vector<int> triangles;              // indices into Scene::triangles
  std::vector<std::vector<int>> cycles;    // vertex ids of each closed link cycle; empty for an open fan
};

// Builds the fan of vertex id `v`.
VertexFan build_vertex_fan(const Scene& scene, const SceneAdjacency& adj, int v);

// Edge rule for the wedge plane through edge `e` and point `v` (not collinear with e). Exact.
bool edge_tangent_in_plane(const Scene& scene, const SceneEdge& e, const Point3& v);

struct VertexTangency {
  bool tangent = true;
  int triangle = -1;  // rule (a) failure: index of the triangle the line meets in a segment; else -1
};

// Vertex rule for the line through fan.vertex with direction d (d != 0). `ref` is any vector not parallel
// to d (the winding count's reference ray); the EV code passes the wedge normal. Exact.
VertexTangency line_tangent_at_vertex(const Scene& scene, const VertexFan& fan, const Vec3<Exact>& d,
                                      const Vec3<Exact>& ref);

}  // namespace exactvis
