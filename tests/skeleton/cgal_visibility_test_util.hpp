#pragma once
// Test helpers: CGAL's visibility (Triangular_expansion_visibility_2, regularized, exact kernel) as an
// independent reference for visibility polygons, and exact comparison of polygons up to start vertex and
// collinear vertices.
#include "tests/planar/scene2d_test_util.hpp"

#include <CGAL/Arr_naive_point_location.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <type_traits>
#include <utility>
#include <string>
#include <vector>

namespace exactvis::test2d {

using CgalK = CGAL::Exact_predicates_exact_constructions_kernel;
using CgalTraits = CGAL::Arr_segment_traits_2<CgalK>;
using CgalArr = CGAL::Arrangement_2<CgalTraits>;

// The kernel's exact number type (a GMP rational), built from our exact coordinates without rounding.
using CgalExact = std::decay_t<decltype(CGAL::exact(std::declval<CgalK::FT>()))>;
inline CgalK::Point_2 to_cgal(const Point2& p) {
  return CgalK::Point_2(CgalK::FT(CgalExact(p.x.mpq())), CgalK::FT(CgalExact(p.y.mpq())));
}

inline oracle2d::Pt to_pt(const CgalK::Point_2& p) {
  return {mpq_class(CGAL::exact(p.x())), mpq_class(CGAL::exact(p.y()))};
}

// Cyclic polygon without repeated or collinear vertices, starting at its lexicographically smallest vertex.
inline std::vector<oracle2d::Pt> normalize(std::vector<oracle2d::Pt> p) {
  auto orient = [](const oracle2d::Pt& a, const oracle2d::Pt& b, const oracle2d::Pt& c) {
    return mpq_sgn(mpq_class((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)).get_mpq_t());
  };
  bool changed = true;
  while (changed && p.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < p.size() && p.size() >= 3; ++i) {
      const oracle2d::Pt &a = p[(i + p.size() - 1) % p.size()], &b = p[i], &c = p[(i + 1) % p.size()];
      if (a == b || orient(a, b, c) == 0) {
        p.erase(p.begin() + i);
        changed = true;
        break;
      }
    }
  }
  std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
  return p;
}

// Vertices of the outer boundary of a face of an arrangement.
inline std::vector<oracle2d::Pt> face_polygon(CgalArr::Face_handle f) {
  std::vector<oracle2d::Pt> out;
  auto c = f->outer_ccb();
  do out.push_back(to_pt(c->source()->point()));
  while (++c != f->outer_ccb());
  return out;
}

// Exact coordinates, for failure messages.
inline std::string show(const std::vector<oracle2d::Pt>& p) {
  std::string s;
  for (const auto& q : p) s.append("(").append(q.x.get_str()).append(",").append(q.y.get_str()).append(") ");
  return s;
}

// The arrangement of all ring edges of a scene (exact coordinates).
inline void insert_scene_edges(const Scene2D& scene, CgalArr& arr) {
  std::vector<CgalTraits::Segment_2> segs;
  for (int v = 0; v < scene.num_vertices(); ++v)
    segs.emplace_back(to_cgal(scene.points[v]), to_cgal(scene.points[scene.next[v]]));
  CGAL::insert(arr, segs.begin(), segs.end());
}

}  // namespace exactvis::test2d
