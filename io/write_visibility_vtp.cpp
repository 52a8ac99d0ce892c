#include "io/write_visibility_vtp.hpp"

#include "io/atomic_file.hpp"
#include "io/vtk_polydata_file.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <limits>

namespace exactvis {

void write_visibility_vtp(const std::string& path, const Scene& scene, const std::vector<int>& state,
                          const std::vector<WitnessSegment>& witnesses,
                          const std::vector<std::vector<Point3>>& source_faces) {
  if (state.size() != scene.triangles.size())
    throw OutputError(path + ": visibility state does not match the scene's triangles");
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : scene.vertices) points->InsertNextPoint(p.x, p.y, p.z);
  vtkNew<vtkCellArray> polys, lines;
  // vtkPolyData orders cell data as lines before polygons.
  vtkNew<vtkIdTypeArray> id;
  vtkNew<vtkIdTypeArray> object;
  vtkNew<vtkFloatArray> visible;  // NaN where a cell is not a scene triangle
  vtkNew<vtkIntArray> kind;
  const float no_value = std::numeric_limits<float>::quiet_NaN();
  id->SetName("id");
  object->SetName("object");
  visible->SetName("visible");
  kind->SetName("kind");
  for (const auto& w : witnesses) {
    const vtkIdType ids[2] = {points->InsertNextPoint(w.p.x, w.p.y, w.p.z), points->InsertNextPoint(w.q.x, w.q.y, w.q.z)};
    lines->InsertNextCell(2, ids);
    id->InsertNextValue(w.triangle_id);
    object->InsertNextValue(-1);
    visible->InsertNextValue(no_value);
    kind->InsertNextValue(1);
  }
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    const auto& t = scene.triangles[i];
    const vtkIdType ids[3] = {t.v[0], t.v[1], t.v[2]};
    polys->InsertNextCell(3, ids);
    id->InsertNextValue(t.id);
    object->InsertNextValue(t.object);
    visible->InsertNextValue(static_cast<float>(state[i]));
    kind->InsertNextValue(0);
  }
  for (const auto& face : source_faces) {  // polygons after the scene's triangles
    std::vector<vtkIdType> ids;
    for (const auto& p : face) ids.push_back(points->InsertNextPoint(p.x, p.y, p.z));
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    id->InsertNextValue(-1);
    object->InsertNextValue(-1);
    visible->InsertNextValue(no_value);
    kind->InsertNextValue(2);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  poly->SetPolys(polys);
  poly->GetCellData()->AddArray(id);
  poly->GetCellData()->AddArray(object);
  poly->GetCellData()->AddArray(visible);
  poly->GetCellData()->AddArray(kind);
  poly->GetCellData()->SetActiveScalars("visible");
  write_polydata_vtp(path, poly);
}

}  // namespace exactvis
