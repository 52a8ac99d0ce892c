#include "io/write_shadow_mesh.hpp"

#include "io/vtk_polydata_file.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <charconv>
#include <fstream>

namespace exactvis {
namespace {

int class_code(shadows::LightClass c) {
  switch (c) {
    case shadows::LightClass::Umbra: return 0;
    case shadows::LightClass::Penumbra: return 1;
    case shadows::LightClass::Lit: return 2;
  }
  return 2;
}

std::string shortest(double x) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace

bool write_shadow_mesh_vtp(const std::string& temp_path, const Scene& scene, const shadows::ShadowResult& result) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> irr;
  irr->SetName("irradiance");
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdTypeArray> cls, recv, face;
  cls->SetName("class");
  recv->SetName("receiver");
  face->SetName("face");
  vtkNew<vtkDoubleArray> frac, firr;
  frac->SetName("light_fraction");
  firr->SetName("face_irradiance");
  for (const auto& r : result.receivers) {
    const vtkIdType base = points->GetNumberOfPoints();
    for (std::size_t k = 0; k < r.vertices.size(); ++k) {
      const auto& v = r.vertices[k];
      points->InsertNextPoint(CGAL::to_double(v.x), CGAL::to_double(v.y), CGAL::to_double(v.z));
      irr->InsertNextValue(k < r.vertex_irradiance.size() ? r.vertex_irradiance[k] : 0.0);
    }
    for (std::size_t t = 0; t < r.mesh.triangles.size(); ++t) {
      const auto& tri = r.mesh.triangles[t];
      const vtkIdType ids[3] = {base + tri[0], base + tri[1], base + tri[2]};
      polys->InsertNextCell(3, ids);
      const auto& f = r.faces[r.mesh.triangle_face[t]];
      cls->InsertNextValue(class_code(f.light_class));
      recv->InsertNextValue(scene.triangles[r.triangle].id);
      face->InsertNextValue(r.mesh.triangle_face[t]);
      frac->InsertNextValue(f.fraction_value);
      firr->InsertNextValue(f.irradiance);
    }
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->GetPointData()->AddArray(irr);
  poly->GetPointData()->SetScalars(irr);
  poly->GetCellData()->AddArray(cls);
  poly->GetCellData()->AddArray(recv);
  poly->GetCellData()->AddArray(face);
  poly->GetCellData()->AddArray(frac);
  poly->GetCellData()->AddArray(firr);
  return write_polydata_file(temp_path, poly);
}

bool write_shadow_mesh_ply(const std::string& temp_path, const Scene& scene, const shadows::ShadowResult& result) {
  std::ofstream out(temp_path, std::ios::binary);
  if (!out) return false;
  std::size_t nv = 0, nf = 0;
  for (const auto& r : result.receivers) nv += r.vertices.size(), nf += r.mesh.triangles.size();
  out << "ply\nformat ascii 1.0\ncomment exactvis shadows: class 0 umbra, 1 penumbra, 2 lit\n"
      << "element vertex " << nv << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "property double irradiance\n"
      << "element face " << nf << "\nproperty list uchar int vertex_indices\nproperty int class\n"
      << "property int receiver\nproperty int face\nproperty double light_fraction\n"
      << "property double face_irradiance\nend_header\n";
  for (const auto& r : result.receivers)
    for (std::size_t k = 0; k < r.vertices.size(); ++k) {
      const auto& v = r.vertices[k];
      out << shortest(CGAL::to_double(v.x)) << ' ' << shortest(CGAL::to_double(v.y)) << ' '
          << shortest(CGAL::to_double(v.z)) << ' '
          << shortest(k < r.vertex_irradiance.size() ? r.vertex_irradiance[k] : 0.0) << '\n';
    }
  std::size_t base = 0;
  for (const auto& r : result.receivers) {
    for (std::size_t t = 0; t < r.mesh.triangles.size(); ++t) {
      const auto& tri = r.mesh.triangles[t];
      const auto& f = r.faces[r.mesh.triangle_face[t]];
      out << "3 " << base + tri[0] << ' ' << base + tri[1] << ' ' << base + tri[2] << ' ' << class_code(f.light_class)
          << ' ' << scene.triangles[r.triangle].id << ' ' << r.mesh.triangle_face[t] << ' '
          << shortest(f.fraction_value) << ' ' << shortest(f.irradiance) << '\n';
    }
    base += r.vertices.size();
  }
  out.flush();
  return static_cast<bool>(out);
}

}  // namespace exactvis
