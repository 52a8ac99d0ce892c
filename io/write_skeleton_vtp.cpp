#include "io/write_skeleton_vtp.hpp"

#include "events/eee_events.hpp"
#include "events/ev_events.hpp"
#include "io/vtk_polydata_file.hpp"
#include "kernel/rational_between.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <array>
#include <optional>

namespace exactvis {
namespace {

std::array<double, 3> approx(const Vec3<RootNumber>& p) {
  return {CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)};
}
std::array<double, 3> approx(const Vec3<Exact>& p) {
  return {CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)};
}

// The generator segment of an arc's line at the rational parameter t (nullopt at a singular EEE t).
std::optional<std::array<std::array<double, 3>, 2>> arc_segment(const Scene& scene, const SkeletonArc& a,
                                                                const Exact& t) {
  if (a.kind == SkeletonArcKind::EV) {
    const Point3& v = scene.vertices[a.vertex];
    return std::array<std::array<double, 3>, 2>{{{v.x, v.y, v.z}, approx(ev_edge_point(scene, a.edges[0], t))}};
  }
  EeeEvent e;
  e.edges = a.edges;
  const auto g = eee_generator_segment(scene, e, t);
  if (!g) return std::nullopt;
  return std::array<std::array<double, 3>, 2>{{approx(g->back), approx(g->front)}};
}

// A rational in [t0, t1]: the end itself when rational, else a rational just inside.
Exact inside(const RootNumber& t, const RootNumber& other, const Exact& sample) {
  Exact q;
  if (root_number_rational(t, &q)) return q;
  return rational_strictly_between(t < other ? t : RootNumber(sample), t < other ? RootNumber(sample) : t);
}

}  // namespace

void write_skeleton_vtp(const std::string& path, const Scene& scene, const Skeleton3D& sk,
                        const SkeletonSelection& sel, int samples) {
  if (samples < 1) samples = 1;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines, polys;
  const char* names[] = {"element", "kind", "index", "vertex", "edge0", "edge1", "edge2", "edge3",
                         "edge4", "edge5", "edge6", "edge7", "end0", "end1"};
  // VTK orders cells verts, lines, polys: node (line) cells come first, so two value lists are kept.
  std::vector<std::array<vtkIdType, 14>> line_values, poly_values;
  for (std::size_t i = 0; i < sel.nodes.size(); ++i) {
    const SkeletonNode& n = sk.nodes[sel.nodes[i]];
    const auto p = approx(n.from), q = approx(n.to);
    const vtkIdType ids[2] = {points->InsertNextPoint(p.data()), points->InsertNextPoint(q.data())};
    lines->InsertNextCell(2, ids);
    std::array<vtkIdType, 14> v{};
    v.fill(-1);
    v[0] = 0, v[1] = static_cast<vtkIdType>(n.key.kind), v[2] = static_cast<vtkIdType>(i);
    if (n.key.vertex_count() > 0) v[3] = n.key.vertices[0];
    for (int e = 0; e < n.key.edge_count(); ++e) v[4 + 2 * e] = n.key.edges[e][0], v[5 + 2 * e] = n.key.edges[e][1];
    v[12] = n.ends[0], v[13] = n.ends[1];
    line_values.push_back(v);
  }
  for (std::size_t i = 0; i < sel.arcs.size(); ++i) {
    const SkeletonArc& a = sk.arcs[sel.arcs[i]];
    std::array<vtkIdType, 14> v{};
    v.fill(-1);
    v[0] = 1, v[1] = a.kind == SkeletonArcKind::EV ? 0 : 1, v[2] = static_cast<vtkIdType>(i), v[3] = a.vertex;
    const int ne = a.kind == SkeletonArcKind::EV ? 1 : 3;
    for (int e = 0; e < ne; ++e) v[4 + 2 * e] = a.edges[e][0], v[5 + 2 * e] = a.edges[e][1];
    v[12] = a.ends[0], v[13] = a.ends[1];
    const Exact lo = inside(a.t0, a.t1, a.sample_t), hi = inside(a.t1, a.t0, a.sample_t);
    std::vector<std::array<std::array<double, 3>, 2>> segs;
    for (int k = 0; k <= samples; ++k) {
      const Exact t = lo + (hi - lo) * Exact(k) / Exact(samples);
      if (auto s = arc_segment(scene, a, t)) segs.push_back(*s);
    }
    for (std::size_t k = 0; k + 1 < segs.size(); ++k) {
      const vtkIdType p0 = points->InsertNextPoint(segs[k][0].data()), p1 = points->InsertNextPoint(segs[k][1].data());
      const vtkIdType p2 = points->InsertNextPoint(segs[k + 1][1].data());
      const vtkIdType p3 = points->InsertNextPoint(segs[k + 1][0].data());
      const vtkIdType t1[3] = {p0, p1, p2}, t2[3] = {p0, p2, p3};
      polys->InsertNextCell(3, t1);
      polys->InsertNextCell(3, t2);
      poly_values.push_back(v);
      poly_values.push_back(v);
    }
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  poly->SetPolys(polys);
  for (std::size_t c = 0; c < std::size(names); ++c) {
    vtkNew<vtkIdTypeArray> arr;
    arr->SetName(names[c]);
    for (const auto& v : line_values) arr->InsertNextValue(v[c]);
    for (const auto& v : poly_values) arr->InsertNextValue(v[c]);
    poly->GetCellData()->AddArray(arr);
  }
  write_polydata_vtp(path, poly);
}

}  // namespace exactvis
