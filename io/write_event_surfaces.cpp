#include "io/write_event_surfaces.hpp"

#include "events/eee_events.hpp"
#include "kernel/ray_first_hit.hpp"
#include "io/atomic_file.hpp"
#include "kernel/predicates.hpp"
#include "kernel/triangle_index.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace exactvis {
namespace {

using D3 = std::array<double, 3>;

D3 approx(const Vec3<Exact>& p) { return {CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)}; }

// Where the ray origin + s dir (s >= 0) leaves the box (display only: doubles).
D3 box_exit(const Box3& box, const D3& o, const D3& d) {
  double smax = std::numeric_limits<double>::infinity();
  const double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
  for (int k = 0; k < 3; ++k) {
    if (d[k] > 0) smax = std::min(smax, (hi[k] - o[k]) / d[k]);
    if (d[k] < 0) smax = std::min(smax, (lo[k] - o[k]) / d[k]);
  }
  if (!std::isfinite(smax) || smax < 0) smax = 0;
  return {o[0] + smax * d[0], o[1] + smax * d[1], o[2] + smax * d[2]};
}

struct Context {
  const Scene& scene;
  TriangleIndex spatial;
  Box3 box;
};

// End point of the maximal free segment on the ray from `origin` along `dir` (exact hit, double output).
D3 free_end(const Context& c, const Vec3<Exact>& origin, const Vec3<Exact>& dir) {
  const RayHit h = ray_first_hit(c.scene, c.spatial, c.box, origin, dir);
  if (h.triangle >= 0) return approx(origin + h.s * dir);
  return box_exit(c.box, approx(origin), approx(dir));
}

// Rational parameters across [t0, t1]: t0 + (t1 - t0) k / n, with irrational ends replaced by rationals inside.
template <class T>
std::vector<Exact> samples(const T& t0, const T& t1, int n);

template <>
std::vector<Exact> samples(const Exact& t0, const Exact& t1, int n) {
  std::vector<Exact> out;
  for (int k = 0; k <= n; ++k) out.push_back(t0 + (t1 - t0) * Exact(k) / Exact(n));
  return out;
}

template <>
std::vector<Exact> samples(const RootNumber& t0, const RootNumber& t1, int n) {
  auto inside = [&](const RootNumber& end, bool lower) {
    if (!end.is_extended() || CGAL::is_zero(end.a1())) return end.a0();
    // A rational near the end, moved towards the interior until it is inside (exact comparisons).
    const double w = CGAL::to_double(t1) - CGAL::to_double(t0);
    for (double f = 1e-9; f < 1; f *= 16) {
      const Exact q(CGAL::to_double(end) + (lower ? f : -f) * w);
      if (RootNumber(q) > t0 && RootNumber(q) < t1) return q;
    }
    return (Exact(CGAL::to_double(t0)) + Exact(CGAL::to_double(t1))) / 2;
  };
  return samples<Exact>(inside(t0, true), inside(t1, false), n);
}

}  // namespace

void write_event_surfaces_vtp(const std::string& path, const Scene& scene, const EvResult& ev,
                              const EeeResult& eee, int samples_per_interval) {
  const Context c{scene, TriangleIndex(scene), bounding_box(scene)};
  const int n = std::max(1, samples_per_interval);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  const char* id_names[] = {"kind", "event", "vertex", "edge0", "edge1", "edge2", "edge3", "edge4", "edge5", "interval"};
  std::vector<vtkIdTypeArray*> ids;
  for (const char* name : id_names) {
    vtkIdTypeArray* a = vtkIdTypeArray::New();
    a->SetName(name);
    ids.push_back(a);
  }
  vtkNew<vtkDoubleArray> t0a, t1a;
  t0a->SetName("t0");
  t1a->SetName("t1");

  // A strip between consecutive segments (back_k, front_k); one cell per triangle with the given ids.
  auto strip = [&](const std::vector<std::pair<D3, D3>>& segs, const std::array<vtkIdType, 10>& cell_ids, double t0,
                   double t1) {
    for (std::size_t k = 0; k + 1 < segs.size(); ++k) {
      const vtkIdType a = points->InsertNextPoint(segs[k].first.data());
      const vtkIdType b = points->InsertNextPoint(segs[k].second.data());
      const vtkIdType cc = points->InsertNextPoint(segs[k + 1].second.data());
      const vtkIdType d = points->InsertNextPoint(segs[k + 1].first.data());
      const vtkIdType tri1[3] = {a, b, cc}, tri2[3] = {a, cc, d};
      for (const vtkIdType* tri : {tri1, tri2}) {
        polys->InsertNextCell(3, tri);
        for (std::size_t i = 0; i < ids.size(); ++i) ids[i]->InsertNextValue(cell_ids[i]);
        t0a->InsertNextValue(t0);
        t1a->InsertNextValue(t1);
      }
    }
  };

  for (std::size_t ei = 0; ei < ev.events.size(); ++ei) {
    const auto& e = ev.events[ei];
    const Vec3<Exact> V = to_rational(scene.vertices[e.vertex]);
    for (std::size_t ii = 0; ii < e.intervals.size(); ++ii) {
      const auto& iv = e.intervals[ii];
      std::vector<std::pair<D3, D3>> segs;
      for (const Exact& t : samples(iv.t0, iv.t1, n)) {
        const Vec3<Exact> p = ev_edge_point(scene, e.edge, t);
        const Vec3<Exact> d = p - V;
        segs.emplace_back(free_end(c, V, -d), free_end(c, p, d));
      }
      strip(segs, {0, vtkIdType(ei), e.vertex, e.edge[0], e.edge[1], -1, -1, -1, -1, vtkIdType(ii)},
            CGAL::to_double(iv.t0), CGAL::to_double(iv.t1));
    }
  }
  for (std::size_t ei = 0; ei < eee.events.size(); ++ei) {
    const auto& e = eee.events[ei];
    for (std::size_t ii = 0; ii < e.intervals.size(); ++ii) {
      const auto& iv = e.intervals[ii];
      std::vector<std::pair<D3, D3>> segs;
      for (const Exact& t : samples(iv.t0, iv.t1, n)) {
        const auto g = eee_generator_segment(scene, e, t);
        if (!g) continue;  // singular parameter (not inside a free interval; defensive)
        segs.emplace_back(free_end(c, g->back, -g->direction), free_end(c, g->front, g->direction));
      }
      strip(segs,
            {1, vtkIdType(ei), -1, e.edges[0][0], e.edges[0][1], e.edges[1][0], e.edges[1][1], e.edges[2][0],
             e.edges[2][1], vtkIdType(ii)},
            CGAL::to_double(iv.t0), CGAL::to_double(iv.t1));
    }
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(polys);
  for (vtkIdTypeArray* a : ids) {
    poly->GetCellData()->AddArray(a);
    a->Delete();
  }
  poly->GetCellData()->AddArray(t0a);
  poly->GetCellData()->AddArray(t1a);
  write_atomically(path, [&](const std::string& temp) {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(temp.c_str());
    writer->SetInputData(poly);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToZLib();
    return writer->Write() == 1 && writer->GetErrorCode() == 0;
  });
}

}  // namespace exactvis
