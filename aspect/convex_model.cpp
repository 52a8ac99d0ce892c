#include "aspect/convex_model.hpp"

#include "kernel/predicates.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <map>
#include <sstream>

namespace exactvis {

namespace {

using Key3 = std::array<double, 3>;
Key3 key(const Point3& p) { return {p.x, p.y, p.z}; }

// Exact det[a, b, c] (six times the signed volume of the tetrahedron (0, a, b, c)).
Exact det3(const Point3& a, const Point3& b, const Point3& c) {
  const Vec3<Exact> A = to_rational(a), B = to_rational(b), C = to_rational(c);
  return dot(A, cross(B, C));
}

std::string point_text(const Key3& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return s.str();
}

// n scaled so that its first largest-|.| component is +1 (the same for n and -n: an unoriented key).
Vec3<Exact> unoriented_canonical(const Vec3<Exact>& n) {
  int m = 0;
  for (int i = 1; i < 3; ++i)
    if (CGAL::abs(n[i]) > CGAL::abs(n[m])) m = i;
  const Exact s = n[m];
  return {n.x / s, n.y / s, n.z / s};
}

}  // namespace

ConvexModel convex_model(const Scene& scene) {
  ConvexModel out;
  if (scene.triangles.empty()) return out.problem = "the model has no triangles", out;
  // Distinct corners.
  std::map<Key3, Point3> corner_map;
  for (const auto& t : scene.triangles)
    for (int k = 0; k < 3; ++k) corner_map.emplace(key(scene.corner(t, k)), scene.corner(t, k));
  std::vector<Point3> corners;
  for (const auto& [k, p] : corner_map) corners.push_back(p);

  // (a) Group triangles by plane (unoriented canonical normal and offset), then test each plane once.
  std::map<std::array<Exact, 4>, int> plane_index;
  std::vector<int> first_triangle;  // per plane: index into scene.triangles
  out.plane_of.assign(scene.triangles.size(), -1);
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    const auto& t = scene.triangles[i];
    const Vec3<Exact> a = to_rational(scene.corner(t, 0));
    const Vec3<Exact> n = unoriented_canonical(cross(to_rational(scene.corner(t, 1)) - a,
                                                     to_rational(scene.corner(t, 2)) - a));
    const std::array<Exact, 4> k{n.x, n.y, n.z, dot(n, a)};
    auto [it, fresh] = plane_index.emplace(k, static_cast<int>(first_triangle.size()));
    if (fresh) {
      first_triangle.push_back(static_cast<int>(i));
      ModelPlane p;
      p.normal = n;
      p.offset = k[3];
      out.planes.push_back(std::move(p));
    }
    out.plane_of[i] = it->second;
    out.planes[it->second].triangles.push_back(t.id);
  }
  for (std::size_t p = 0; p < out.planes.size(); ++p) {
    const auto& t = scene.triangles[first_triangle[p]];
    bool pos = false, neg = false;
    for (const Point3& c : corners) {
      const Sign s = orient3d(scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2), c);
      pos |= s == Sign::Positive;
      neg |= s == Sign::Negative;
    }
    if (pos && neg)
      return out.problem = "triangle " + std::to_string(t.id) + " has model corners on both sides of its plane",
             out.planes.clear(), out;
    if (!pos && !neg) return out.problem = "the model is flat (all its corners lie in one plane)", out.planes.clear(), out;
    // Orient the plane outward: the corners must satisfy normal . x <= offset.
    const Vec3<Exact> a = to_rational(scene.corner(t, 0));
    const Vec3<Exact> raw = cross(to_rational(scene.corner(t, 1)) - a, to_rational(scene.corner(t, 2)) - a);
    // raw points to the positive orient3d side; the corners are on the `pos` side, outward is the other.
    const bool flip = (CGAL::sign(dot(raw, out.planes[p].normal)) > 0) == pos;
    if (flip) out.planes[p].normal = -out.planes[p].normal, out.planes[p].offset = -out.planes[p].offset;
  }

  // (b) Directed edges of the outward-oriented triangles cancel; (c) volumes.
  std::map<std::pair<Key3, Key3>, int> edge_balance;
  Exact volume6(0);
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    const auto& t = scene.triangles[i];
    Point3 a = scene.corner(t, 0), b = scene.corner(t, 1), c = scene.corner(t, 2);
    // The triangle is outward as given iff its own normal points outward.
    const Vec3<Exact> ra = to_rational(a);
    const Vec3<Exact> raw = cross(to_rational(b) - ra, to_rational(c) - ra);
    if (CGAL::sign(dot(raw, out.planes[out.plane_of[i]].normal)) < 0) std::swap(b, c);
    const Point3 v[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) {
      const Key3 p = key(v[k]), q = key(v[(k + 1) % 3]);
      if (p < q) ++edge_balance[{p, q}];
      else --edge_balance[{q, p}];
    }
    volume6 += det3(a, b, c);
  }
  for (const auto& [e, balance] : edge_balance)
    if (balance != 0)
      return out.problem = "the model is not closed: the edge " + point_text(e.first) + " - " + point_text(e.second) +
                           " is not matched by an opposite edge (open boundary, T-junction or inconsistent faces)",
             out.planes.clear(), out;
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_3> pts;
  for (const Point3& c : corners) pts.emplace_back(c.x, c.y, c.z);
  CGAL::Surface_mesh<K::Point_3> hull;
  CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
  Exact hull6(0);
  for (auto f : hull.faces()) {
    std::vector<Point3> v;
    for (auto h : CGAL::halfedges_around_face(hull.halfedge(f), hull)) {
      const auto& p = hull.point(hull.target(h));
      v.push_back({p.x(), p.y(), p.z()});
    }
    for (std::size_t k = 1; k + 1 < v.size(); ++k) hull6 += det3(v[0], v[k], v[k + 1]);
  }
  if (volume6 != hull6)
    return out.problem = "the triangles do not cover the convex hull's boundary exactly once (overlapping or "
                         "duplicated triangles)",
           out.planes.clear(), out;
  // Order planes by their smallest triangle id (they already are: triangles are sorted by id) and name each
  // plane's EV generator.
  for (std::size_t p = 0; p < out.planes.size(); ++p) {
    const auto& t = scene.triangles[first_triangle[p]];
    out.planes[p].vertex = t.v[0];
    out.planes[p].edge = {t.v[1], t.v[2]};
  }
  out.convex = true;
  return out;
}

}  // namespace exactvis
