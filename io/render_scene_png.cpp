#include "io/render_scene_png.hpp"

#include "io/atomic_file.hpp"
#include "io/headless_display.hpp"
#include "io/render_png.hpp"
#include "io/vtk_quiet.hpp"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace exactvis {

// A well-spread palette: hues by the golden angle, alternating lightness.
Rgb palette_colour(std::int64_t v) {
  if (v < 0) return {170, 170, 170};
  const double h = std::fmod(v * 0.618033988749895, 1.0) * 6, l = v % 2 ? 0.55 : 0.75, s = 0.65;
  const double c = (1 - std::abs(2 * l - 1)) * s, x = c * (1 - std::abs(std::fmod(h, 2) - 1)), m = l - c / 2;
  double r = 0, g = 0, b = 0;
  const int k = static_cast<int>(h);
  if (k == 0) r = c, g = x;
  else if (k == 1) r = x, g = c;
  else if (k == 2) g = c, b = x;
  else if (k == 3) g = x, b = c;
  else if (k == 4) r = x, b = c;
  else r = c, b = x;
  return {static_cast<unsigned char>(255 * (r + m)), static_cast<unsigned char>(255 * (g + m)),
          static_cast<unsigned char>(255 * (b + m))};
}

PictureMesh scene_mesh(const Scene& scene, const std::vector<Rgb>& colours) {
  PictureMesh m;
  m.triangles.reserve(scene.triangles.size());
  for (const auto& t : scene.triangles) m.triangles.push_back({scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2)});
  m.colours = colours;
  m.colours.resize(m.triangles.size(), Rgb{170, 170, 170});
  return m;
}

std::vector<std::array<Point3, 2>> box_edges(const Point3& lo, const Point3& hi) {
  std::vector<std::array<Point3, 2>> out;
  auto corner = [&](int bits) {
    return Point3{bits & 1 ? hi.x : lo.x, bits & 2 ? hi.y : lo.y, bits & 4 ? hi.z : lo.z};
  };
  for (int a = 0; a < 8; ++a)
    for (int axis = 0; axis < 3; ++axis)
      if (!(a & (1 << axis))) out.push_back({corner(a), corner(a | (1 << axis))});
  return out;
}

namespace {

struct Bounds {
  Point3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
  Point3 hi{-lo.x, -lo.y, -lo.z};
  void add(const Point3& p) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p[k])) return;
    }
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  bool empty() const { return !(lo.x <= hi.x); }
};

vtkSmartPointer<vtkActor> mesh_actor(const PictureMesh& m) {
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k) ids[k] = pts->InsertNextPoint(m.triangles[t][k].x, m.triangles[t][k].y, m.triangles[t][k].z);
    polys->InsertNextCell(3, ids);
    const Rgb c = t < m.colours.size() ? m.colours[t] : Rgb{170, 170, 170};
    rgb->InsertNextTypedTuple(c.data());
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->SetPolys(polys);
  poly->GetCellData()->SetScalars(rgb);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetOpacity(m.opacity);
  if (m.cull_back_faces) actor->GetProperty()->BackfaceCullingOn();
  if (!m.lit) {
    actor->GetProperty()->SetAmbient(1.0);
    actor->GetProperty()->SetDiffuse(0.0);
  } else {
    actor->GetProperty()->SetAmbient(0.35);
    actor->GetProperty()->SetDiffuse(0.65);
  }
  return actor;
}

vtkSmartPointer<vtkActor> lines_actor(const PictureLines& l) {
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  for (const auto& s : l.segments) {
    const vtkIdType ids[2] = {pts->InsertNextPoint(s[0].x, s[0].y, s[0].z), pts->InsertNextPoint(s[1].x, s[1].y, s[1].z)};
    cells->InsertNextCell(2, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->SetLines(cells);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(l.colour[0] / 255.0, l.colour[1] / 255.0, l.colour[2] / 255.0);
  actor->GetProperty()->SetLineWidth(static_cast<float>(l.width));
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  return actor;
}

// A filled square of `size` pixels at display position (x, y) (lower-left corner).
vtkSmartPointer<vtkActor2D> swatch(double x, double y, double size, const Rgb& c) {
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(x, y, 0);
  pts->InsertNextPoint(x + size, y, 0);
  pts->InsertNextPoint(x + size, y + size, 0);
  pts->InsertNextPoint(x, y + size, 0);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[4] = {0, 1, 2, 3};
  cells->InsertNextCell(4, ids);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->SetPolys(cells);
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
  return actor;
}

vtkSmartPointer<vtkTextActor> text(const std::string& s, double x, double y, int size) {
  auto t = vtkSmartPointer<vtkTextActor>::New();
  t->SetInput(s.c_str());
  t->SetDisplayPosition(static_cast<int>(x), static_cast<int>(y));
  t->GetTextProperty()->SetFontSize(size);
  t->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  return t;
}

}  // namespace

bool render_scene_png(const std::string& temp_path, const ScenePicture& picture, int width, int height) {
  if (width < 16 || height < 16 || width > 8192 || height > 8192)
    throw OutputError(temp_path + ": cannot render: picture size must be 16 .. 8192 pixels each way");
  HeadlessDisplay display(temp_path);
  QuietVtk quiet;
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);
  Bounds b;
  for (const auto& m : picture.meshes) {
    for (const auto& t : m.triangles)
      for (const auto& p : t) b.add(p);
    if (!m.triangles.empty()) renderer->AddActor(mesh_actor(m));
  }
  for (const auto& l : picture.lines) {
    for (const auto& s : l.segments) {
      b.add(s[0]);
      b.add(s[1]);
    }
    if (!l.segments.empty()) renderer->AddActor(lines_actor(l));
  }
  // Legend: top-left, one row per entry; the title above it.
  const int font = std::max(12, height / 45);
  double y = height - 1.6 * font;
  if (!picture.title.empty()) {
    renderer->AddActor2D(text(picture.title, 0.8 * font, y, font));
    y -= 1.5 * font;
  }
  for (const auto& e : picture.legend) {
    renderer->AddActor2D(swatch(0.8 * font, y, font, e.colour));
    renderer->AddActor2D(text(e.label, 2.3 * font, y, font));
    y -= 1.4 * font;
  }
  if (!b.empty()) {
    const Point3 c{(b.lo.x + b.hi.x) / 2, (b.lo.y + b.hi.y) / 2, (b.lo.z + b.hi.z) / 2};
    const Point3 ext = b.hi - b.lo;
    const double diag = std::max(std::sqrt(dot(ext, ext)), 1e-300);
    vtkCamera* cam = renderer->GetActiveCamera();
    cam->SetFocalPoint(c.x, c.y, c.z);
    // From above the (-x, -y) corner, looking down at about 35 degrees.
    cam->SetPosition(c.x - 0.9 * diag, c.y - 1.3 * diag, c.z + 1.1 * diag);
    cam->SetViewUp(0, 0, 1);
    renderer->ResetCamera();
    cam->Zoom(1.25);  // ResetCamera fits the bounding sphere; the box's corners are well inside the view
    renderer->ResetCameraClippingRange();
  }
  return save_renderer_png(renderer, width, height, temp_path);
}

}  // namespace exactvis
