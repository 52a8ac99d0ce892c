#include "region/vertex_polygon_view.hpp"

#include "region/convex_polygon_3.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Cartesian.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <stdexcept>

namespace exactvis::region {
namespace {

using K = CGAL::Cartesian<Exact>;
using Point2 = K::Point_2;
using Polygon2 = CGAL::Polygon_2<K>;
using PolygonWithHoles2 = CGAL::Polygon_with_holes_2<K>;
using PolygonSet2 = CGAL::Polygon_set_2<K>;

// T's plane and the coordinate axis dropped for 2D work (the dominant axis of the normal).
struct PlaneFrame {
  Plane3 plane;
  int drop = 2;
  Point2 to2d(const RationalPoint3& p) const { return {p[(drop + 1) % 3], p[(drop + 2) % 3]}; }
  RationalPoint3 to3d(const Point2& q) const {
    RationalPoint3 p;
    const int a = (drop + 1) % 3, b = (drop + 2) % 3;
    p[a] = q.x();
    p[b] = q.y();
    p[drop] = (plane.offset - plane.normal[a] * q.x() - plane.normal[b] * q.y()) / plane.normal[drop];
    return p;
  }
};

PlaneFrame frame_of(const std::array<RationalPoint3, 3>& t) {
  PlaneFrame f{plane_through(t[0], t[1], t[2]), 0};
  Exact best = CGAL::abs(f.plane.normal[0]);
  for (int k = 1; k < 3; ++k)
    if (CGAL::abs(f.plane.normal[k]) > best) best = CGAL::abs(f.plane.normal[k]), f.drop = k;
  return f;
}

Polygon2 counterclockwise(Polygon2 p) {
  if (p.orientation() == CGAL::CLOCKWISE) p.reverse_orientation();
  return p;
}

}  // namespace

VertexPolygonView vertex_polygon_view(const Scene& scene, const TriangleIndex& index, int vertex, int triangle) {
  if (vertex < 0 || vertex >= static_cast<int>(scene.vertices.size()))
    throw std::out_of_range("vertex_polygon_view: vertex id out of range");
  if (triangle < 0 || triangle >= static_cast<int>(scene.triangles.size()))
    throw std::out_of_range("vertex_polygon_view: triangle index out of range");
  VertexPolygonView view;
  const Point3& vd = scene.vertices[vertex];
  const RationalPoint3 v{Exact(vd.x), Exact(vd.y), Exact(vd.z)};
  const auto t = triangle_points(scene, triangle);
  const PlaneFrame frame = frame_of(t);
  const Exact hv = frame.plane.value(v);
  if (CGAL::is_zero(hv)) {
    view.grazing = true;
    return view;
  }
  // The tetrahedron conv(V, T) as four closed half-spaces (value >= 0 inside).
  std::vector<Plane3> tetra;
  tetra.push_back(CGAL::sign(hv) > 0 ? frame.plane : frame.plane.flipped());
  for (int k = 0; k < 3; ++k) {
    Plane3 p = plane_through(v, t[k], t[(k + 1) % 3]);
    if (CGAL::sign(p.value(t[(k + 2) % 3])) < 0) p = p.flipped();
    tetra.push_back(p);
  }
  Box3 box{vd, vd};
  for (int k = 0; k < 3; ++k) {
    const Point3& c = scene.corner(scene.triangles[triangle], k);
    box.lo.x = std::min(box.lo.x, c.x), box.lo.y = std::min(box.lo.y, c.y), box.lo.z = std::min(box.lo.z, c.z);
    box.hi.x = std::max(box.hi.x, c.x), box.hi.y = std::max(box.hi.y, c.y), box.hi.z = std::max(box.hi.z, c.z);
  }
  PolygonSet2 shadows;
  for (const std::int64_t oi : index.candidates_in_box(box)) {
    if (oi == triangle) continue;
    const SceneTriangle& o = scene.triangles[oi];
    if (o.v[0] == vertex || o.v[1] == vertex || o.v[2] == vertex) continue;  // incident to V
    const auto corners = triangle_points(scene, oi);
    Polygon3 poly(corners.begin(), corners.end());
    // An occluder through V's position blocks only segments in its own plane: measure zero.
    if (in_closed_polygon(v, poly)) continue;
    for (const Plane3& p : tetra) poly = clip_polygon(poly, p);
    if (is_degenerate(poly) || lies_in_plane(poly, frame.plane)) continue;
    // Central projection from V onto T's plane (h(P) != h(V) inside the tetrahedron, V excluded).
    Polygon2 shadow;
    for (const RationalPoint3& p : poly) {
      const Exact s = hv / (hv - frame.plane.value(p));
      shadow.push_back(frame.to2d(v + s * (p - v)));
    }
    // Drop repeated consecutive points (clipping can repeat a vertex); degenerate shadows have no area.
    Polygon2 clean;
    for (auto it = shadow.vertices_begin(); it != shadow.vertices_end(); ++it)
      if (clean.is_empty() || *it != *(clean.vertices_end() - 1)) clean.push_back(*it);
    while (clean.size() > 1 && *clean.vertices_begin() == *(clean.vertices_end() - 1)) clean.erase(clean.vertices_end() - 1);
    if (clean.size() < 3 || CGAL::is_zero(clean.area())) continue;
    shadows.join(counterclockwise(clean));
    view.occluders.push_back(o.id);
  }
  Polygon2 tri;
  for (const auto& c : t) tri.push_back(frame.to2d(c));
  PolygonSet2 visible(counterclockwise(tri));
  visible.difference(shadows);
  std::vector<PolygonWithHoles2> parts;
  visible.polygons_with_holes(std::back_inserter(parts));
  for (const auto& pw : parts) {
    ViewPolygon vp;
    for (auto it = pw.outer_boundary().vertices_begin(); it != pw.outer_boundary().vertices_end(); ++it)
      vp.outer.push_back(frame.to3d(*it));
    for (auto h = pw.holes_begin(); h != pw.holes_end(); ++h) {
      std::vector<RationalPoint3> hole;
      for (auto it = h->vertices_begin(); it != h->vertices_end(); ++it) hole.push_back(frame.to3d(*it));
      vp.holes.push_back(std::move(hole));
    }
    view.visible.push_back(std::move(vp));
  }
  std::sort(view.occluders.begin(), view.occluders.end());
  return view;
}

Exact projected_area(const VertexPolygonView& view, const Scene& scene, int triangle) {
  const PlaneFrame frame = frame_of(triangle_points(scene, triangle));
  auto area = [&](const std::vector<RationalPoint3>& ring) {
    Polygon2 p;
    for (const auto& q : ring) p.push_back(frame.to2d(q));
    return CGAL::abs(p.area());
  };
  Exact total = 0;
  for (const auto& vp : view.visible) {
    total += area(vp.outer);
    for (const auto& h : vp.holes) total -= area(h);
  }
  return total;
}

}  // namespace exactvis::region
