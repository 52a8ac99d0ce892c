#include "shadows/receiver_faces.hpp"

#include "shadows/exact_planar_kernel.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <algorithm>
#include <map>
#include <optional>

namespace exactvis::shadows {
namespace {

using Vb = CGAL::Triangulation_vertex_base_2<PlanarKernel>;
using Fb0 = CGAL::Constrained_triangulation_face_base_2<PlanarKernel>;
using Fb = CGAL::Triangulation_face_base_with_info_2<int, PlanarKernel, Fb0>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<PlanarKernel, Tds, CGAL::Exact_intersections_tag>;

// The part of segment [a, b] in the closed unit triangle u >= 0, v >= 0, u + v <= 1 (Liang-Barsky, exact),
// or std::nullopt when that part is empty or a point.
std::optional<std::pair<std::array<Exact, 2>, std::array<Exact, 2>>> clip_to_unit_triangle(const std::array<Exact, 2>& a,
                                                                                         const std::array<Exact, 2>& b) {
  const std::array<Exact, 2> d{b[0] - a[0], b[1] - a[1]};
  Exact lo = 0, hi = 1;
  const std::array<std::pair<Exact, Exact>, 3> lin{{{a[0], d[0]}, {a[1], d[1]}, {1 - a[0] - a[1], -d[0] - d[1]}}};
  for (const auto& [val, slope] : lin) {  // val + s * slope >= 0
    if (CGAL::is_zero(slope)) {
      if (val < 0) return std::nullopt;
    } else if (slope > 0) {
      lo = std::max(lo, -val / slope);
    } else {
      hi = std::min(hi, -val / slope);
    }
  }
  if (!(lo < hi)) return std::nullopt;
  if (lo == 0 && hi == 1) return std::pair{a, b};
  return std::pair{std::array<Exact, 2>{a[0] + lo * d[0], a[1] + lo * d[1]},
                   std::array<Exact, 2>{a[0] + hi * d[0], a[1] + hi * d[1]}};
}

}  // namespace

ReceiverFaces receiver_faces(const std::vector<std::vector<std::array<Exact, 2>>>& polylines) {
  Cdt cdt;
  const PlanarPoint c0(0, 0), c1(1, 0), c2(0, 1);
  cdt.insert_constraint(c0, c1);
  cdt.insert_constraint(c1, c2);
  cdt.insert_constraint(c2, c0);
  for (const auto& pl : polylines)
    for (std::size_t k = 0; k + 1 < pl.size(); ++k) {
      const auto part = clip_to_unit_triangle(pl[k], pl[k + 1]);
      if (!part) continue;
      const PlanarPoint a = to_planar(part->first), b = to_planar(part->second);
      if (a != b) cdt.insert_constraint(a, b);
    }
  ReceiverFaces out;
  std::map<Cdt::Vertex_handle, int> vid;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    vid[v] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(from_planar(v->point()));
  }
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  // Flood fill across unconstrained edges (all finite faces lie in the unit triangle: its sides are
  // constraints and every point is inside it).
  std::vector<PlanarKernel::FT> best_area;
  std::vector<Cdt::Face_handle> best_face;
  for (auto f0 = cdt.finite_faces_begin(); f0 != cdt.finite_faces_end(); ++f0) {
    if (f0->info() >= 0) continue;
    const int id = static_cast<int>(out.faces.size());
    out.faces.emplace_back();
    best_area.push_back(-1);
    best_face.push_back(f0);
    PlanarKernel::FT area = 0;
    std::vector<Cdt::Face_handle> stack{f0};
    f0->info() = id;
    while (!stack.empty()) {
      const Cdt::Face_handle f = stack.back();
      stack.pop_back();
      const PlanarKernel::FT a = CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
      area += a;
      ++out.faces[id].triangles;
      if (a > best_area[id]) best_area[id] = a, best_face[id] = f;
      for (int k = 0; k < 3; ++k) {
        const Cdt::Face_handle g = f->neighbor(k);
        if (cdt.is_infinite(g) || f->is_constrained(k) || g->info() >= 0) continue;
        g->info() = id;
        stack.push_back(g);
      }
    }
    out.faces[id].area_uv = from_planar_ft(area);
  }
  for (std::size_t id = 0; id < out.faces.size(); ++id) {
    const auto f = best_face[id];
    out.faces[id].sample = from_planar(CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(),
                                                      f->vertex(2)->point()));
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    out.triangles.push_back({vid[f->vertex(0)], vid[f->vertex(1)], vid[f->vertex(2)]});
    out.triangle_face.push_back(f->info());
  }
  return out;
}

}  // namespace exactvis::shadows
