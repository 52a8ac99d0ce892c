#include "io/render_png.hpp"

#include "io/atomic_file.hpp"
#include "io/headless_display.hpp"
#include "io/vtk_quiet.hpp"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>


namespace exactvis {
namespace {

vtkSmartPointer<vtkActor> triangles_actor(const Scene& scene, const std::vector<int>& which, double r, double g,
                                          double b) {
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> cells;
  for (int ti : which) {
    const auto& t = scene.triangles[ti];
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k) {
      const Point3& p = scene.corner(t, k);
      ids[k] = pts->InsertNextPoint(p.x, p.y, p.z);
    }
    cells->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->SetPolys(cells);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->BackfaceCullingOn();
  return actor;
}

}  // namespace

bool render_shadows_png(const std::string& temp_path, const Scene& scene, const shadows::ShadowResult& result,
                        const std::vector<int>& light, int width, int height) {
  HeadlessDisplay display(temp_path);
  QuietVtk quiet;
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> irr;
  irr->SetName("irradiance");
  vtkNew<vtkCellArray> cells;
  double emax = 0;
  std::set<std::int64_t> meshed;
  for (const auto& r : result.receivers) {
    meshed.insert(r.triangle);
    const vtkIdType base = pts->GetNumberOfPoints();
    for (std::size_t k = 0; k < r.vertices.size(); ++k) {
      const auto& v = r.vertices[k];
      pts->InsertNextPoint(CGAL::to_double(v.x), CGAL::to_double(v.y), CGAL::to_double(v.z));
      const double e = k < r.vertex_irradiance.size() ? r.vertex_irradiance[k] : 0.0;
      irr->InsertNextValue(e);
      emax = std::max(emax, e);
    }
    for (const auto& t : r.mesh.triangles) {
      const vtkIdType ids[3] = {base + t[0], base + t[1], base + t[2]};
      cells->InsertNextCell(3, ids);
    }
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(pts);
  mesh->SetPolys(cells);
  mesh->GetPointData()->SetScalars(irr);
  vtkNew<vtkLookupTable> lut;
  lut->SetNumberOfTableValues(256);
  for (int i = 0; i < 256; ++i) {
    const double x = i / 255.0;  // black -> orange -> white
    lut->SetTableValue(i, std::min(1.0, 1.6 * x), std::min(1.0, 1.1 * x * x + 0.3 * x), x * x * x, 1.0);
  }
  lut->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->SetLookupTable(lut);
  std::vector<double> values;
  for (vtkIdType i = 0; i < irr->GetNumberOfValues(); ++i) values.push_back(irr->GetValue(i));
  double top = emax;
  if (!values.empty()) {
    const std::size_t k = values.size() * 95 / 100;
    std::nth_element(values.begin(), values.begin() + k, values.end());
    top = values[std::min(k, values.size() - 1)];
  }
  mapper->SetScalarRange(0, top > 0 ? top : (emax > 0 ? emax : 1));
  mapper->SetInterpolateScalarsBeforeMapping(true);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(1.0);  // show irradiance, not VTK's own lighting
  actor->GetProperty()->SetDiffuse(0.0);
  // Back faces are culled so that a closed room whose faces point inwards is seen through its outer walls.
  actor->GetProperty()->BackfaceCullingOn();

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  const std::set<int> light_set(light.begin(), light.end());
  std::vector<int> others;
  for (std::size_t i = 0; i < scene.triangles.size(); ++i)
    if (!light_set.count(static_cast<int>(i)) && !meshed.count(static_cast<std::int64_t>(i)))
      others.push_back(static_cast<int>(i));
  if (!others.empty()) renderer->AddActor(triangles_actor(scene, others, 0.55, 0.55, 0.6));
  auto light_actor = triangles_actor(scene, light, 1.0, 0.95, 0.4);
  light_actor->GetProperty()->SetAmbient(1.0);
  light_actor->GetProperty()->SetDiffuse(0.0);
  renderer->AddActor(light_actor);
  renderer->SetBackground(0.12, 0.14, 0.18);
  // Camera: "up" is the first light triangle's normal, oriented from the scene's centre towards the light
  // (lights usually hang from a ceiling); the view comes from above one side of the scene box.
  const Box3 box = bounding_box(scene);
  const Point3 centre{(box.lo.x + box.hi.x) / 2, (box.lo.y + box.hi.y) / 2, (box.lo.z + box.hi.z) / 2};
  Point3 up{0, 0, 1};
  if (!light.empty()) {
    const auto& lt = scene.triangles[light.front()];
    const Point3 a = scene.corner(lt, 0), b = scene.corner(lt, 1), c = scene.corner(lt, 2);
    Point3 n = cross(b - a, c - a);
    const Point3 lc{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3};
    if (dot(n, lc - centre) < 0) n = -n;
    const double l = std::sqrt(dot(n, n));
    if (l > 0) up = {n.x / l, n.y / l, n.z / l};
  }
  Point3 side = cross(up, Point3{0.3, 0.5, 0.8});
  if (dot(side, side) < 1e-6) side = cross(up, Point3{1, 0, 0});
  const double sl = std::sqrt(dot(side, side));
  side = {side.x / sl, side.y / sl, side.z / sl};
  const Point3 ext = box.hi - box.lo;
  const double diag = std::sqrt(dot(ext, ext));
  vtkCamera* cam = renderer->GetActiveCamera();
  cam->SetFocalPoint(centre.x, centre.y, centre.z);
  cam->SetPosition(centre.x + diag * (1.1 * up.x + side.x), centre.y + diag * (1.1 * up.y + side.y),
                   centre.z + diag * (1.1 * up.z + side.z));
  cam->SetViewUp(up.x, up.y, up.z);
  renderer->ResetCamera();
  renderer->ResetCameraClippingRange();

  return save_renderer_png(renderer, width, height, temp_path);
}

bool save_renderer_png(vtkRenderer* renderer, int width, int height, const std::string& path) {
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(width, height);
  return save_render_window_png(window, path);
}

bool save_render_window_png(vtkRenderWindow* window, const std::string& path) {
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

}  // namespace exactvis
