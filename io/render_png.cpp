#include "io/render_png.hpp"

#include "io/atomic_file.hpp"
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
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <poll.h>
#include <set>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace exactvis {
namespace {

// An Xvfb process started for one render (DISPLAY set while it lives), or nothing when DISPLAY is set.
class VirtualDisplay {
 public:
  explicit VirtualDisplay(const std::string& path) {
    const char* d = std::getenv("DISPLAY");
    if (d && *d) return;
    int fds[2];
    if (pipe(fds) != 0) throw OutputError(path + ": cannot render: pipe failed");
    const std::string fd = std::to_string(fds[1]);
    std::vector<std::string> args{"Xvfb", "-displayfd", fd, "-screen", "0", "1600x1200x24", "-nolisten", "tcp",
                                  "-noreset"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);  // Xvfb's log
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    const int rc = posix_spawnp(&pid_, "Xvfb", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (rc != 0) {
      close(fds[0]);
      throw OutputError(path + ": cannot render: no DISPLAY and Xvfb could not be started (install xvfb)");
    }
    // Xvfb writes the display number followed by a newline once it accepts connections.
    std::string number;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (std::chrono::steady_clock::now() < deadline) {
      pollfd p{fds[0], POLLIN, 0};
      if (poll(&p, 1, 200) <= 0) continue;
      char c;
      const ssize_t n = read(fds[0], &c, 1);
      if (n <= 0) break;
      if (c == '\n') break;
      number += c;
    }
    close(fds[0]);
    if (number.empty()) {
      stop();
      throw OutputError(path + ": cannot render: Xvfb did not start");
    }
    display_ = ":" + number;
    setenv("DISPLAY", display_.c_str(), 1);
  }
  ~VirtualDisplay() {
    if (pid_ > 0) {
      unsetenv("DISPLAY");
      stop();
    }
  }
  VirtualDisplay(const VirtualDisplay&) = delete;
  VirtualDisplay& operator=(const VirtualDisplay&) = delete;

 private:
  void stop() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
  }
  pid_t pid_ = -1;
  std::string display_;
};

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
  VirtualDisplay display(temp_path);
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

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(width, height);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(temp_path.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

}  // namespace exactvis
