#include "io/write_vtp.hpp"

#include "io/atomic_file.hpp"
#include "io/vtk_polydata_file.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace exactvis {
namespace {

void add_arrays(vtkPolyData* poly, const CellArrays& arrays, std::size_t cells, const std::string& path) {
  for (const auto& a : arrays.ints) {
    if (a.values.size() != cells)
      throw OutputError(path + ": array '" + a.name + "' has " + std::to_string(a.values.size()) + " values for " +
                        std::to_string(cells) + " cells");
    vtkNew<vtkIdTypeArray> arr;  // 64-bit ids
    arr->SetName(a.name.c_str());
    arr->SetNumberOfValues(static_cast<vtkIdType>(cells));
    for (std::size_t i = 0; i < cells; ++i) arr->SetValue(static_cast<vtkIdType>(i), a.values[i]);
    poly->GetCellData()->AddArray(arr);
  }
  for (const auto& a : arrays.doubles) {
    if (a.values.size() != cells)
      throw OutputError(path + ": array '" + a.name + "' has " + std::to_string(a.values.size()) + " values for " +
                        std::to_string(cells) + " cells");
    vtkNew<vtkDoubleArray> arr;
    arr->SetName(a.name.c_str());
    arr->SetNumberOfValues(static_cast<vtkIdType>(cells));
    for (std::size_t i = 0; i < cells; ++i) arr->SetValue(static_cast<vtkIdType>(i), a.values[i]);
    poly->GetCellData()->AddArray(arr);
  }
}

void check_names(const CellArrays& arrays, const std::string& path) {
  for (const auto& a : arrays.ints)
    if (a.name == "id" || a.name == "object") throw OutputError(path + ": array name '" + a.name + "' is reserved");
  for (const auto& a : arrays.doubles)
    if (a.name == "id" || a.name == "object") throw OutputError(path + ": array name '" + a.name + "' is reserved");
}

}  // namespace

void write_scene_vtp(const std::string& path, const Scene& scene, const CellArrays& extra) {
  check_names(extra, path);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(scene.vertices.size()));
  for (std::size_t i = 0; i < scene.vertices.size(); ++i) {
    const Point3& p = scene.vertices[i];
    points->SetPoint(static_cast<vtkIdType>(i), p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& t : scene.triangles) {
    const vtkIdType ids[3] = {t.v[0], t.v[1], t.v[2]};
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(polys);
  CellArrays all;
  IntArray id{"id", {}}, object{"object", {}};
  for (const auto& t : scene.triangles) {
    id.values.push_back(t.id);
    object.values.push_back(t.object);
  }
  all.ints.push_back(std::move(id));
  all.ints.push_back(std::move(object));
  all.ints.insert(all.ints.end(), extra.ints.begin(), extra.ints.end());
  all.doubles = extra.doubles;
  add_arrays(poly, all, scene.triangles.size(), path);
  write_polydata_vtp(path, poly);
}

void write_polylines_vtp(const std::string& path, const std::vector<std::vector<Point3>>& polylines,
                         const CellArrays& per_line) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  for (const auto& line : polylines) {
    if (line.size() < 2) throw OutputError(path + ": a polyline needs at least 2 points");
    std::vector<vtkIdType> ids;
    for (const auto& p : line) ids.push_back(points->InsertNextPoint(p.x, p.y, p.z));
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  add_arrays(poly, per_line, polylines.size(), path);
  write_polydata_vtp(path, poly);
}

void write_segments_vtp(const std::string& path, const std::vector<std::pair<Point3, Point3>>& segments,
                        const CellArrays& per_segment) {
  std::vector<std::vector<Point3>> lines;
  lines.reserve(segments.size());
  for (const auto& s : segments) lines.push_back({s.first, s.second});
  write_polylines_vtp(path, lines, per_segment);
}

void write_surface_with_lines_vtp(const std::string& path, const std::vector<Point3>& points,
                                  const std::vector<std::array<int, 3>>& triangles,
                                  const std::vector<std::int64_t>& triangle_values,
                                  const std::vector<std::vector<Point3>>& polylines,
                                  const std::vector<std::int64_t>& polyline_values, const std::string& name) {
  if (triangle_values.size() != triangles.size() || polyline_values.size() != polylines.size())
    throw OutputError(path + ": one value per triangle and per polyline is needed");
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : points) pts->InsertNextPoint(p.x, p.y, p.z);
  vtkNew<vtkCellArray> lines, polys;
  for (const auto& line : polylines) {
    if (line.size() < 2) throw OutputError(path + ": a polyline needs at least 2 points");
    std::vector<vtkIdType> ids;
    for (const auto& p : line) ids.push_back(pts->InsertNextPoint(p.x, p.y, p.z));
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  for (const auto& t : triangles) {
    for (int k : t)
      if (k < 0 || k >= static_cast<int>(points.size())) throw OutputError(path + ": a triangle point index is out of range");
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->SetLines(lines);
  poly->SetPolys(polys);
  CellArrays arrays;
  IntArray values{name, polyline_values}, kind{"kind", std::vector<std::int64_t>(polylines.size(), 1)};
  values.values.insert(values.values.end(), triangle_values.begin(), triangle_values.end());
  kind.values.resize(polylines.size() + triangles.size(), 2);
  arrays.ints = {std::move(values), std::move(kind)};
  add_arrays(poly, arrays, polylines.size() + triangles.size(), path);
  write_polydata_vtp(path, poly);
}

}  // namespace exactvis
