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
#include <vtkSmartPointer.h>

#include <limits>

namespace exactvis {

void write_triangle_state_vtp(const std::string& path, const Scene& scene, const std::vector<int>& values,
                              const TriangleStateArray& array, const std::vector<WitnessSegment>& witnesses,
                              const std::vector<std::vector<Point3>>& source_faces) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : scene.vertices) points->InsertNextPoint(p.x, p.y, p.z);
  vtkNew<vtkCellArray> polys, lines;
  // vtkPolyData orders cell data as lines before polygons.
  vtkNew<vtkIdTypeArray> id;
  vtkNew<vtkIdTypeArray> object;
  vtkSmartPointer<vtkDataArray> value;
  if (array.is_float)
    value = vtkSmartPointer<vtkFloatArray>::New();
  else
    value = vtkSmartPointer<vtkIntArray>::New();
  vtkNew<vtkIntArray> kind;
  id->SetName("id");
  object->SetName("object");
  value->SetName(array.name.c_str());
  kind->SetName("kind");
  for (const auto& w : witnesses) {
    const vtkIdType ids[2] = {points->InsertNextPoint(w.p.x, w.p.y, w.p.z), points->InsertNextPoint(w.q.x, w.q.y, w.q.z)};
    lines->InsertNextCell(2, ids);
    id->InsertNextValue(w.triangle_id);
    object->InsertNextValue(-1);
    value->InsertNextTuple1(array.witness_value);
    kind->InsertNextValue(1);
  }
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    const auto& t = scene.triangles[i];
    const vtkIdType ids[3] = {t.v[0], t.v[1], t.v[2]};
    polys->InsertNextCell(3, ids);
    id->InsertNextValue(t.id);
    object->InsertNextValue(t.object);
    value->InsertNextTuple1(values[i]);
    kind->InsertNextValue(0);
  }
  for (const auto& face : source_faces) {  // polygons after the scene's triangles
    std::vector<vtkIdType> ids;
    for (const auto& p : face) ids.push_back(points->InsertNextPoint(p.x, p.y, p.z));
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    id->InsertNextValue(-1);
    object->InsertNextValue(-1);
    value->InsertNextTuple1(array.source_value);
    kind->InsertNextValue(2);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  poly->SetPolys(polys);
  poly->GetCellData()->AddArray(id);
  poly->GetCellData()->AddArray(object);
  poly->GetCellData()->AddArray(value);
  poly->GetCellData()->AddArray(kind);
  poly->GetCellData()->SetActiveScalars(array.name.c_str());
  write_polydata_vtp(path, poly);
}

void write_visibility_vtp(const std::string& path, const Scene& scene, const std::vector<int>& state,
                          const std::vector<WitnessSegment>& witnesses,
                          const std::vector<std::vector<Point3>>& source_faces) {
  if (state.size() != scene.triangles.size())
    throw OutputError(path + ": visibility state does not match the scene's triangles");
  const double no_value = std::numeric_limits<double>::quiet_NaN();  // NaN where a cell is not a scene triangle
  write_triangle_state_vtp(path, scene, state, {"visible", true, no_value, no_value}, witnesses, source_faces);
}

}  // namespace exactvis
