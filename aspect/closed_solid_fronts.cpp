#include "aspect/closed_solid_fronts.hpp"

#include "kernel/predicates.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <map>
#include <set>

namespace exactvis {

namespace {

using Key3 = std::array<double, 3>;
using ExactKey = std::array<Exact, 3>;

Vec3<Exact> ex(const Point3& p) { return to_rational(p); }

}  // namespace

ClosedSolidFronts closed_solid_fronts(const Scene& scene) {
  ClosedSolidFronts out;
  const std::size_t n = scene.triangles.size();
  if (n == 0) return out.problem = "the model has no triangles", out;

  // The surface mesh, vertices merged by exact coordinates; faces in scene order (face i = triangle i).
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  Mesh mesh;
  std::map<Key3, Mesh::Vertex_index> vertex_of;
  const auto vertex = [&](const Point3& p) {
    auto [it, fresh] = vertex_of.emplace(Key3{p.x, p.y, p.z}, Mesh::Vertex_index());
    if (fresh) it->second = mesh.add_vertex(K::Point_3(p.x, p.y, p.z));
    return it->second;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = scene.triangles[i];
    const auto a = vertex(scene.corner(t, 0)), b = vertex(scene.corner(t, 1)), c = vertex(scene.corner(t, 2));
    if (mesh.add_face(a, b, c) == Mesh::null_face())
      return out.problem = "triangle " + std::to_string(t.id) +
                           " makes the surface non-manifold or inconsistently oriented (a closed oriented "
                           "2-manifold is required)",
             out.not_solid = true, out;
  }
  if (!CGAL::is_closed(mesh))
    return out.problem = "the model is not closed (an edge has only one triangle)", out.not_solid = true, out;
  if (CGAL::Polygon_mesh_processing::does_self_intersect(mesh))
    return out.problem = "the surface intersects itself (triangles cross or overlap)", out;

  // Outward orientation per connected component: the sign of its signed volume.
  auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first;
  const std::size_t components = CGAL::Polygon_mesh_processing::connected_components(mesh, component);
  std::vector<Exact> volume6(components, Exact(0));
  std::vector<Vec3<Exact>> raw(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = scene.triangles[i];
    const Vec3<Exact> a = ex(scene.corner(t, 0)), b = ex(scene.corner(t, 1)), c = ex(scene.corner(t, 2));
    raw[i] = cross(b - a, c - a);
    volume6[component[Mesh::Face_index(static_cast<Mesh::size_type>(i))]] += dot(a, cross(b, c));
  }
  out.fronts.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool flip = volume6[component[Mesh::Face_index(static_cast<Mesh::size_type>(i))]] < 0;
    out.fronts[i].outward = flip ? -raw[i] : raw[i];
  }

  // Front parts and the convexity certificate.
  std::vector<std::array<Vec3<Exact>, 3>> corners(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) corners[i][k] = ex(scene.corner(scene.triangles[i], k));
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3<Exact>& nt = out.fronts[i].outward;
    const Exact ct = dot(nt, corners[i][0]);
    std::set<ExactKey> points;
    std::vector<std::size_t> meeting;  // triangles with a point strictly in front
    for (std::size_t u = 0; u < n; ++u) {
      std::array<Exact, 3> f;
      bool ahead = false;
      for (int k = 0; k < 3; ++k) f[k] = dot(nt, corners[u][k]) - ct, ahead |= f[k] > 0;
      if (!ahead) continue;
      meeting.push_back(u);
      for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3;
        const Vec3<Exact>& p = corners[u][k];
        const Vec3<Exact>& q = corners[u][j];
        if (f[k] >= 0) points.insert({p.x, p.y, p.z});
        if ((f[k] > 0 && f[j] < 0) || (f[k] < 0 && f[j] > 0)) {
          const Vec3<Exact> x = p + Exact(f[k] / (f[k] - f[j])) * (q - p);
          points.insert({x.x, x.y, x.z});
        }
      }
    }
    for (const auto& k : points) out.fronts[i].points.push_back({k[0], k[1], k[2]});
    for (std::size_t u : meeting) {
      const Exact cu = dot(raw[u], corners[u][0]);
      bool pos = false, neg = false;
      for (const auto& p : out.fronts[i].points) {
        const int s = CGAL::sign(dot(raw[u], p) - cu);
        pos |= s > 0;
        neg |= s < 0;
      }
      if (pos && neg)
        return out.problem = "the part of the model in front of triangle " + std::to_string(scene.triangles[i].id) +
                             " is not convex (triangle " + std::to_string(scene.triangles[u].id) +
                             "'s plane cuts it): EEE events may change the aspect there, and the orthographic "
                             "aspect graph of such models is not implemented yet",
               out.outside_class = true, out.fronts.clear(), out;
    }
  }
  out.ok = true;
  return out;
}

}  // namespace exactvis
