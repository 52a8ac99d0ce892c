#include "aspect/triangle_contacts.hpp"

#include "kernel/predicates.hpp"
#include "kernel/triangle_index.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <array>

namespace exactvis {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Point_3 cp(const Point3& p) { return {p.x, p.y, p.z}; }

bool same(const Point3& a, const Point3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// Does the closed segment [a, b] meet the closed triangle t? Exact (Epick predicates on doubles).
bool segment_meets(const Point3& a, const Point3& b, const std::array<Point3, 3>& t) {
  return CGAL::do_intersect(K::Segment_3(cp(a), cp(b)), K::Triangle_3(cp(t[0]), cp(t[1]), cp(t[2])));
}

// Do t and u (which meet) meet in more than their shared corners and edges? By the rules of the header.
bool improper(const std::array<Point3, 3>& t, const std::array<Point3, 3>& u) {
  std::array<int, 3> match{-1, -1, -1};  // per corner of t, the equal corner of u
  int shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (same(t[i], u[j])) match[i] = j, ++shared;
  if (shared == 0 || shared == 3) return true;
  if (shared == 1) {
    const int i = match[0] >= 0 ? 0 : (match[1] >= 0 ? 1 : 2), j = match[i];
    return segment_meets(t[(i + 1) % 3], t[(i + 2) % 3], u) || segment_meets(u[(j + 1) % 3], u[(j + 2) % 3], t);
  }
  // Two shared corners: t's third corner p and u's third corner q.
  int pi = 0, qj = 0;
  while (match[pi] >= 0) ++pi;
  while (qj == match[0] || qj == match[1] || qj == match[2]) ++qj;
  const int a = (pi + 1) % 3, b = (pi + 2) % 3;
  const K::Point_3 pa = cp(t[a]), pb = cp(t[b]), p = cp(t[pi]), q = cp(u[qj]);
  return CGAL::orientation(pa, pb, p, q) == CGAL::COPLANAR && CGAL::coplanar_orientation(pa, pb, p, q) == CGAL::POSITIVE;
}

}  // namespace

std::string triangle_contact_problem(const Scene& scene) {
  const std::size_t n = scene.triangles.size();
  std::vector<std::array<Point3, 3>> corners(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = scene.triangles[i];
    for (int k = 0; k < 3; ++k) corners[i][k] = scene.corner(t, k);
    if (collinear(corners[i][0], corners[i][1], corners[i][2]))
      return "triangle " + std::to_string(t.id) + " is degenerate (its corners are collinear)";
  }
  const TriangleIndex index(scene);
  for (std::size_t i = 0; i < n; ++i)
    for (const std::int64_t u : index.triangles_meeting_triangle(corners[i][0], corners[i][1], corners[i][2]))
      if (static_cast<std::size_t>(u) > i && improper(corners[i], corners[u]))
        return "triangles " + std::to_string(scene.triangles[i].id) + " and " + std::to_string(scene.triangles[u].id) +
               " cross, overlap or touch away from a shared corner or edge (the triangles must meet only in shared "
               "corners and edges)";
  return "";
}

}  // namespace exactvis
