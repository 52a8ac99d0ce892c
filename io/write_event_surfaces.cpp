#include "io/write_event_surfaces.hpp"

#include "io/atomic_file.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

namespace exactvis {

void write_event_surfaces_vtp(const std::string& path, const Scene& scene, const EvResult& result) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  auto id_array = [](const char* name) {
    vtkIdTypeArray* a = vtkIdTypeArray::New();
    a->SetName(name);
    return a;
  };
  vtkIdTypeArray* event = id_array("event");
  vtkIdTypeArray* kind = id_array("kind");
  vtkIdTypeArray* vertex = id_array("vertex");
  vtkIdTypeArray* edge0 = id_array("edge0");
  vtkIdTypeArray* edge1 = id_array("edge1");
  vtkNew<vtkDoubleArray> t0, t1;
  t0->SetName("t0");
  t1->SetName("t1");
  for (std::size_t ei = 0; ei < result.events.size(); ++ei) {
    const auto& ev = result.events[ei];
    const Point3& v = scene.vertices[ev.vertex];
    for (const auto& iv : ev.intervals) {
      const auto p0 = ev_edge_point(scene, ev.edge, iv.t0);
      const auto p1 = ev_edge_point(scene, ev.edge, iv.t1);
      const vtkIdType a = points->InsertNextPoint(v.x, v.y, v.z);
      const vtkIdType b = points->InsertNextPoint(CGAL::to_double(p0.x), CGAL::to_double(p0.y), CGAL::to_double(p0.z));
      const vtkIdType c = points->InsertNextPoint(CGAL::to_double(p1.x), CGAL::to_double(p1.y), CGAL::to_double(p1.z));
      const vtkIdType tri[3] = {a, b, c};
      polys->InsertNextCell(3, tri);
      event->InsertNextValue(static_cast<vtkIdType>(ei));
      kind->InsertNextValue(0);
      vertex->InsertNextValue(ev.vertex);
      edge0->InsertNextValue(ev.edge[0]);
      edge1->InsertNextValue(ev.edge[1]);
      t0->InsertNextValue(CGAL::to_double(iv.t0));
      t1->InsertNextValue(CGAL::to_double(iv.t1));
    }
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(polys);
  for (vtkIdTypeArray* a : {event, kind, vertex, edge0, edge1}) {
    poly->GetCellData()->AddArray(a);
    a->Delete();
  }
  poly->GetCellData()->AddArray(t0);
  poly->GetCellData()->AddArray(t1);
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
