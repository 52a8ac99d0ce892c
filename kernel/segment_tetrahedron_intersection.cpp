#include "kernel/segment_tetrahedron_intersection.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace exactvis {

bool segment_meets_tetrahedron(const Point3& p, const Point3& q, const Point3& a, const Point3& b,
                               const Point3& c, const Point3& d) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto pt = [](const Point3& x) { return K::Point_3(x.x, x.y, x.z); };
  const K::Tetrahedron_3 t(pt(a), pt(b), pt(c), pt(d));
  if (p.x == q.x && p.y == q.y && p.z == q.z) return !t.has_on_unbounded_side(pt(p));
  return CGAL::do_intersect(K::Segment_3(pt(p), pt(q)), t);
}

}  // namespace exactvis
