#include "io/write_pvs_check_vtp.hpp"

#include "io/atomic_file.hpp"
#include "io/vtk_polydata_file.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace exactvis {

void write_pvs_check_vtp(const std::string& path, const Scene& scene, const std::vector<int>& status,
                         const std::vector<StatusSegment>& witnesses, const region::RationalBox3& cell) {
  if (status.size() != scene.triangles.size())
    throw OutputError(path + ": status does not match the scene's triangles");
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : scene.vertices) points->InsertNextPoint(p.x, p.y, p.z);
  vtkNew<vtkCellArray> polys, lines;
  vtkNew<vtkIdTypeArray> id, object;
  vtkNew<vtkIntArray> state, kind;
  id->SetName("id");
  object->SetName("object");
  state->SetName("status");
  kind->SetName("kind");
  // vtkPolyData orders cell data as lines before polygons.
  for (const auto& w : witnesses) {
    const vtkIdType ids[2] = {points->InsertNextPoint(w.p.x, w.p.y, w.p.z), points->InsertNextPoint(w.q.x, w.q.y, w.q.z)};
    lines->InsertNextCell(2, ids);
    id->InsertNextValue(w.triangle_id);
    object->InsertNextValue(-1);
    state->InsertNextValue(kStatusFalseInvisible);
    kind->InsertNextValue(1);
  }
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    const auto& t = scene.triangles[i];
    const vtkIdType ids[3] = {t.v[0], t.v[1], t.v[2]};
    polys->InsertNextCell(3, ids);
    id->InsertNextValue(t.id);
    object->InsertNextValue(t.object);
    state->InsertNextValue(status[i]);
    kind->InsertNextValue(0);
  }
  for (int axis = 0; axis < 3; ++axis)
    for (bool high : {false, true}) {
      vtkIdType ids[4];
      int k = 0;
      for (const auto& c : region::box_face(cell, axis, high))
        ids[k++] = points->InsertNextPoint(CGAL::to_double(c.x), CGAL::to_double(c.y), CGAL::to_double(c.z));
      polys->InsertNextCell(4, ids);
      id->InsertNextValue(-1);
      object->InsertNextValue(-1);
      state->InsertNextValue(-1);
      kind->InsertNextValue(2);
    }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  poly->SetPolys(polys);
  poly->GetCellData()->AddArray(id);
  poly->GetCellData()->AddArray(object);
  poly->GetCellData()->AddArray(state);
  poly->GetCellData()->AddArray(kind);
  poly->GetCellData()->SetActiveScalars("status");
  write_polydata_vtp(path, poly);
}

}  // namespace exactvis
