#pragma once
// The exact visible part of a scene triangle seen from a scene vertex (the point-to-polygon view, the
// backprojection the shadows work builds on; docs/theory.md section 9, "Queries").
//
// A point X of the closed triangle T is *seen* from vertex V iff the open segment (V, X) meets no closed
// scene triangle other than T and the triangles incident to V (as in the EV sets; V's own fan is taken as
// open: a vertex of a closed mesh is not kept from looking through its own solid, which matters only for V
// on a closed mesh and T behind it). The visible part is the closure of the interior of the seen set
// (regularised: measure-zero pieces, e.g. single blocked lines, are dropped): T minus the union of the
// central projections from V onto T's plane of the occluders clipped to the tetrahedron conv(V, T).
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"

#include <vector>

namespace exactvis::region {

// A polygon with holes in T's plane, exact rational 3D vertices (the rings as CGAL's 2D Boolean operations
// return them in the projection that drops the dominant axis of T's normal).
struct ViewPolygon {
  std::vector<Vec3<Exact>> outer;
  std::vector<std::vector<Vec3<Exact>>> holes;
};

struct VertexPolygonView {
  std::vector<ViewPolygon> visible;  // disjoint interiors; empty when nothing of T is seen
  bool grazing = false;              // V lies in T's plane: every segment grazes T, the view is empty
  std::vector<std::int64_t> occluders;  // stable ids of the triangles casting a shadow of positive area on T
};

// Input: the scene, its spatial index, vertex id `vertex`, the index (into Scene::triangles) of T.
// Output: the visible part of T from V (above), exact. Cost: one box query, an exact clip and projection
// per candidate, CGAL's exact 2D Boolean union and difference (Gmpq). Throws std::out_of_range for bad ids.
VertexPolygonView vertex_polygon_view(const Scene& scene, const TriangleIndex& index, int vertex, int triangle);

// Exact area of the view's polygons measured in T's projection onto the coordinate plane that drops the
// dominant axis of T's normal (a fixed positive multiple of the true area, for comparisons and tests).
Exact projected_area(const VertexPolygonView& view, const Scene& scene, int triangle);

}  // namespace exactvis::region
