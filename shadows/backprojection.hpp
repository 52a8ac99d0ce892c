#pragma once
// The backprojection of an area light at a point: the exact part of the light visible from the point
// (docs/theory.md section 11, "Backprojection").
//
// The light is a set of scene triangles (events/light_source.hpp). A light point q is *visible* from p iff
// the open segment (p, q) meets no closed scene triangle. The points hidden by one blocker T (p not in T's
// plane, T not in the light triangle's plane) are the light points in the closed cone from p over T beyond
// T's plane: the light triangle clipped by four planes (exact, region::clip_polygon). The visible part is
// the light triangle minus the union of these convex polygons (shadows/convex_difference, exact, in the
// triangle's PlaneChart), in the canonical form of shadows/cell_union_boundary (loops from their smallest
// chart vertex, no collinear vertices, pieces and holes sorted), which depends only on the point set. Sets of zero area are ignored (a blocker through p, or in the light's plane, hides
// at most a segment of the light): classes and fractions are by area.
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"
#include "region/convex_polygon_3.hpp"
#include "shadows/light_plane_2d.hpp"
#include "shadows/receiver_shaft.hpp"

#include <cstdint>
#include <vector>

namespace exactvis::shadows {

// A polygon with holes on a light triangle's plane: exact 3D vertices; `outer` counterclockwise seen from
// the side the triangle's normal (b - a) x (c - a) points to, `holes` clockwise.
struct VisiblePolygon {
  region::Polygon3 outer;
  std::vector<region::Polygon3> holes;
};

// The visible part of one light triangle.
struct VisibleLightPart {
  int light_triangle = -1;              // index into Scene::triangles
  std::vector<VisiblePolygon> pieces;   // disjoint interiors
  Exact visible_area_2d = 0;            // area of the pieces in the triangle's PlaneChart
  Exact area_2d = 0;                    // area of the whole triangle in that chart
  PlaneChart chart;                     // the triangle's chart (3D area = 2D area * chart.area_scale())
};

enum class LightClass { Umbra, Penumbra, Lit };
const char* light_class_name(LightClass c);  // "umbra", "penumbra", "lit"

struct Backprojection {
  std::vector<VisibleLightPart> parts;  // one per light triangle, in the order given
  std::vector<std::int64_t> blockers;   // stable ids of the triangles hiding a part of positive area, sorted
  LightClass light_class = LightClass::Lit;
  // Visible share of the light's area. Exact when all light triangles are coplanar (`fraction_exact`), else
  // fraction_value is a double computed from exact areas.
  bool fraction_exact = true;
  Exact fraction = 1;
  double fraction_value = 1;
};

// Input: scene, its index, the light (indices into Scene::triangles, each of positive area), a point p.
// Output: the backprojection (exact). Cost: per light triangle, O(k) clipping for the k triangles meeting
// the bounding box of p and the triangle, plus the convex difference of the hidden polygons (each splits the cells it meets).
Backprojection backproject(const Scene& scene, const TriangleIndex& index, const std::vector<int>& light,
                           const RationalPoint3& p);

// The same backprojection with the candidate blockers taken from a receiver's shaft
// (shadows/receiver_shaft.hpp) instead of the index: `shaft` built for the same `light`, p in the closed
// receiver triangle (the caller's precondition: then every triangle hiding light from p is in the shaft, and
// the result is identical to the indexed backproject, docs/theory.md section 11). Cost: per light triangle a
// box test per shaft candidate, then as above for those meeting the box of p and the triangle.
Backprojection backproject(const Scene& scene, const std::vector<int>& light, const RationalPoint3& p,
                           const ReceiverShaft& shaft);

// A point strictly inside the visible polygon (rational), found on a horizontal line of the chart avoiding
// every vertex. Exact.
RationalPoint3 interior_point(const PlaneChart& chart, const VisiblePolygon& piece);

}  // namespace exactvis::shadows
