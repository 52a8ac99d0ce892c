#include "io/vtp_2d.hpp"

#include "io/vtk_quiet.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkErrorCode.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstring>
#include <stdexcept>

namespace exactvis {

void write_vtp_2d(const std::string& path, const VtpCells2D& c) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();  // coordinates beyond float's range stay finite
  vtkNew<vtkCellArray> polys, lines;
  vtkNew<vtkIntArray> value, kind;
  value->SetName("value");
  kind->SetName("kind");
  // vtkPolyData numbers cells verts, lines, polys, strips: cell data must follow that order.
  std::vector<int> line_value, line_kind, poly_value, poly_kind;
  for (std::size_t i = 0; i < c.lines.size(); ++i) {
    const vtkIdType a = points->InsertNextPoint(c.lines[i][0][0], c.lines[i][0][1], 0);
    const vtkIdType b = points->InsertNextPoint(c.lines[i][1][0], c.lines[i][1][1], 0);
    const vtkIdType ids[2] = {a, b};
    lines->InsertNextCell(2, ids);
    line_value.push_back(i < c.line_values.size() ? c.line_values[i] : 0);
    line_kind.push_back(2);
  }
  for (std::size_t i = 0; i < c.polygons.size(); ++i)
    for (std::size_t r = 0; r < c.polygons[i].size(); ++r) {
      std::vector<vtkIdType> ids;
      for (const auto& p : c.polygons[i][r]) ids.push_back(points->InsertNextPoint(p[0], p[1], 0));
      polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      poly_value.push_back(r == 0 ? (i < c.polygon_values.size() ? c.polygon_values[i] : 0) : -1);
      poly_kind.push_back(r == 0 ? 0 : 1);
    }
  for (int v : line_value) value->InsertNextValue(v);
  for (int v : poly_value) value->InsertNextValue(v);
  for (int v : line_kind) kind->InsertNextValue(v);
  for (int v : poly_kind) kind->InsertNextValue(v);
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->SetLines(lines);
  pd->SetPolys(polys);
  pd->GetCellData()->AddArray(value);
  pd->GetCellData()->AddArray(kind);
  QuietVtk quiet;
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetFileName(path.c_str());
  w->SetInputData(pd);
  // Write() returns 1 even when the file could not be written; the error code tells.
  if (w->Write() != 1 || w->GetErrorCode() != 0) {
    const unsigned long code = w->GetErrorCode();
    // Codes below FirstVTKErrorCode are errno values (VTK passes system errors through).
    const std::string why = code < vtkErrorCode::FirstVTKErrorCode        ? std::string(std::strerror(static_cast<int>(code)))
                            : code == vtkErrorCode::OutOfDiskSpaceError  ? "out of disk space"
                            : code == vtkErrorCode::CannotOpenFileError ? "cannot open the file"
                                                                        : "VTK error " + std::to_string(code);
    throw std::runtime_error(path + ": cannot write (" + why + ")");
  }
}

}  // namespace exactvis
