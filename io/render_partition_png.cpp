#include "io/render_partition_png.hpp"

#include "io/atomic_file.hpp"
#include "io/headless_display.hpp"
#include "io/render_png.hpp"
#include "io/render_scene_png.hpp"
#include "io/vtk_quiet.hpp"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

namespace exactvis {


void render_panels_png(const std::string& path, const std::vector<PngPanel>& panels, int panel_pixels) {
  if (panels.empty()) throw OutputError(path + ": nothing to render");
  HeadlessDisplay display(path);
  write_atomically(path, [&](const std::string& temp) {
    QuietVtk quiet;
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetSize(panel_pixels * static_cast<int>(panels.size()), panel_pixels);
    for (std::size_t i = 0; i < panels.size(); ++i) {
      const PngPanel& p = panels[i];
      vtkNew<vtkRenderer> renderer;
      renderer->SetViewport(double(i) / panels.size(), 0, double(i + 1) / panels.size(), 1);
      renderer->SetBackground(1, 1, 1);
      vtkNew<vtkPoints> pts;
      for (const auto& q : p.points) pts->InsertNextPoint(q.x, q.y, q.z);
      vtkNew<vtkCellArray> polys;
      vtkNew<vtkUnsignedCharArray> rgb;
      rgb->SetNumberOfComponents(3);
      for (std::size_t t = 0; t < p.triangles.size(); ++t) {
        const vtkIdType ids[3] = {p.triangles[t][0], p.triangles[t][1], p.triangles[t][2]};
        polys->InsertNextCell(3, ids);
        const Rgb c = palette_colour(t < p.values.size() ? p.values[t] : -1);
        rgb->InsertNextTypedTuple(c.data());
      }
      vtkNew<vtkPolyData> surface;
      surface->SetPoints(pts);
      surface->SetPolys(polys);
      surface->GetCellData()->SetScalars(rgb);
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(surface);
      mapper->SetScalarModeToUseCellData();
      mapper->SetColorModeToDirectScalars();
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      renderer->AddActor(actor);
      vtkNew<vtkPoints> cpts;
      vtkNew<vtkCellArray> lines;
      for (const auto& curve : p.curves) {
        std::vector<vtkIdType> ids;
        for (const auto& q : curve) ids.push_back(cpts->InsertNextPoint(q.x, q.y, q.z));
        lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      }
      vtkNew<vtkPolyData> curves;
      curves->SetPoints(cpts);
      curves->SetLines(lines);
      vtkNew<vtkPolyDataMapper> cmapper;
      cmapper->SetInputData(curves);
      vtkNew<vtkActor> cactor;
      cactor->SetMapper(cmapper);
      cactor->GetProperty()->SetColor(0, 0, 0);
      cactor->GetProperty()->SetLineWidth(2);
      renderer->AddActor(cactor);
      vtkCamera* cam = renderer->GetActiveCamera();
      cam->SetFocalPoint(p.focal.x, p.focal.y, p.focal.z);
      cam->SetPosition(p.eye.x, p.eye.y, p.eye.z);
      cam->SetViewUp(p.up.x, p.up.y, p.up.z);
      cam->SetParallelProjection(p.orthographic ? 1 : 0);
      if (p.orthographic) {
        renderer->ResetCamera();
      } else {
        cam->SetViewAngle(p.view_angle);
        renderer->ResetCameraClippingRange();
      }
      window->AddRenderer(renderer);
    }
    return save_render_window_png(window, temp);
  });
}

}  // namespace exactvis
