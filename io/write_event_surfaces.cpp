#include "io/write_event_surfaces.hpp"

#include "events/event_surfaces.hpp"
#include "io/vtk_polydata_file.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>

namespace exactvis {

void write_event_surfaces_vtp(const std::string& path, const Scene& scene, const EvResult& ev,
                              const EeeResult& eee, int samples_per_interval) {
  const std::vector<EventSurface> surfaces = event_surfaces(scene, ev, eee, samples_per_interval);
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

  // The strip between consecutive samples' segments (back_k, front_k); one cell per triangle with the ids.
  for (const EventSurface& surface : surfaces) {
    std::array<vtkIdType, 10> cell_ids;
    double t0 = 0, t1 = 0;
    if (surface.kind == EventSurface::Kind::EV) {
      const auto& e = ev.events[surface.event];
      const auto& iv = e.intervals[surface.interval];
      cell_ids = {0, vtkIdType(surface.event), e.vertex, e.edge[0], e.edge[1], -1, -1, -1, -1, vtkIdType(surface.interval)};
      t0 = CGAL::to_double(iv.t0);
      t1 = CGAL::to_double(iv.t1);
    } else {
      const auto& e = eee.events[surface.event];
      const auto& iv = e.intervals[surface.interval];
      cell_ids = {1, vtkIdType(surface.event), -1, e.edges[0][0], e.edges[0][1], e.edges[1][0], e.edges[1][1],
                  e.edges[2][0], e.edges[2][1], vtkIdType(surface.interval)};
      t0 = CGAL::to_double(iv.t0);
      t1 = CGAL::to_double(iv.t1);
    }
    const auto& smp = surface.samples;
    for (std::size_t k = 0; k + 1 < smp.size(); ++k) {
      const vtkIdType a = points->InsertNextPoint(smp[k].back.x, smp[k].back.y, smp[k].back.z);
      const vtkIdType b = points->InsertNextPoint(smp[k].front.x, smp[k].front.y, smp[k].front.z);
      const vtkIdType cc = points->InsertNextPoint(smp[k + 1].front.x, smp[k + 1].front.y, smp[k + 1].front.z);
      const vtkIdType d = points->InsertNextPoint(smp[k + 1].back.x, smp[k + 1].back.y, smp[k + 1].back.z);
      const vtkIdType tri1[3] = {a, b, cc}, tri2[3] = {a, cc, d};
      for (const vtkIdType* tri : {tri1, tri2}) {
        polys->InsertNextCell(3, tri);
        for (std::size_t i = 0; i < ids.size(); ++i) ids[i]->InsertNextValue(cell_ids[i]);
        t0a->InsertNextValue(t0);
        t1a->InsertNextValue(t1);
      }
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
  write_polydata_vtp(path, poly);
}

}  // namespace exactvis
