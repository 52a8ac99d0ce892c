// _exactvis: the compiled part of the Python module (python/exactvis/__init__.py is the documented API;
// docs/python.md). Each binding is one job façade (api/) with the command line's option checks
// (apps/cli_util.hpp), so bad input raises ValueError with the message `exactvis SUB` prints after
// "error: ". Long calls release the GIL; progress callbacks are called with the GIL held.
#include "api/complex2d.hpp"
#include "api/events.hpp"
#include "api/pvs.hpp"
#include "api/shadows.hpp"
#include "api/skeleton.hpp"
#include "api/version.hpp"
#include "api/visible.hpp"
#include "apps/cli_util.hpp"
#include "io/load_scene.hpp"
#include "io/scene2d_json.hpp"
#include "io/view_cells_json.hpp"
#include "util/progress_observer.hpp"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <mpfr.h>

#include <mutex>
#include <set>
#include <optional>
#include <sstream>
#include <string>

namespace py = pybind11;
using namespace exactvis;

namespace {

// A Python callable called as progress(done, total) from the worker threads (under the GIL, one call at a
// time). The first exception it raises stops further calls and is raised again when the job returns.
class PythonProgress {
 public:
  explicit PythonProgress(py::object callback) : callback_(std::move(callback)) {}
  bool active() const { return !callback_.is_none(); }
  void operator()(std::int64_t done, std::int64_t total) {
    py::gil_scoped_acquire gil;
    if (error_) return;
    try {
      callback_(done, total);
    } catch (py::error_already_set& e) {
      error_ = std::move(e);
    } catch (const std::exception& e) {  // not expected from a call; never let it reach a worker thread
      PyErr_SetString(PyExc_RuntimeError, e.what());
      error_ = py::error_already_set();
    }
  }
  // Raises the callback's exception, if any (call with the GIL held).
  void rethrow() {
    if (error_) {
      py::error_already_set e = std::move(*error_);
      error_.reset();
      throw e;
    }
  }

 private:
  py::object callback_;
  std::optional<py::error_already_set> error_;
};

// The double nearest to x (ties to even), as Python's float(Fraction) gives it; CGAL::to_double(Gmpq)
// truncates. (Through MPFR at 53 bits: correct for normal doubles, witnesses' range.)
double nearest_double(const Exact& x) {
  double d = 0;
  if (exact_double(x, &d)) return d;
  mpfr_t f;
  mpfr_init2(f, 53);
  mpfr_set_q(f, x.mpq(), MPFR_RNDN);
  d = mpfr_get_d(f, MPFR_RNDN);
  mpfr_clear(f);
  return d;
}

std::string exact_text(const Exact& x) {
  std::ostringstream s;
  s << x.numerator() << "/" << x.denominator();
  return s.str();
}

Scene scene_from_numpy(const py::array_t<double, py::array::c_style | py::array::forcecast>& V,
                       const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& F) {
  if (V.ndim() != 2 || V.shape(1) != 3) throw std::invalid_argument("V: expected an n x 3 array of coordinates");
  if (F.ndim() != 2 || F.shape(1) != 3) throw std::invalid_argument("F: expected an m x 3 array of vertex indices");
  std::vector<Point3> vs(static_cast<std::size_t>(V.shape(0)));
  auto v = V.unchecked<2>();
  for (py::ssize_t i = 0; i < V.shape(0); ++i) vs[i] = Point3{v(i, 0), v(i, 1), v(i, 2)};
  std::vector<std::array<std::int64_t, 3>> fs(static_cast<std::size_t>(F.shape(0)));
  auto f = F.unchecked<2>();
  for (py::ssize_t i = 0; i < F.shape(0); ++i) fs[i] = {f(i, 0), f(i, 1), f(i, 2)};
  return scene_from_arrays(vs, fs);
}

py::array_t<double> scene_vertices(const Scene& s) {
  py::array_t<double> out({static_cast<py::ssize_t>(s.vertices.size()), py::ssize_t{3}});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < s.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) o(i, k) = s.vertices[i][k];
  return out;
}

py::array_t<std::int64_t> scene_faces(const Scene& s) {
  py::array_t<std::int64_t> out({static_cast<py::ssize_t>(s.triangles.size()), py::ssize_t{3}});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) o(i, k) = s.triangles[i].v[k];
  return out;
}

// visible: (ids, visible, witnesses (k x 2 x 3 nearest doubles), exact witnesses ("num/den" texts, k x 6)
// or None, stats as the CLI's "stats").
py::tuple run_visible(const Scene& scene, std::optional<std::string> cell, std::optional<std::string> polygon,
                      std::optional<std::vector<std::int64_t>> triangles, int samples, const std::string& seed,
                      int threads, bool exact, py::object progress) {
  if (cell.has_value() == polygon.has_value())
    throw std::invalid_argument("give exactly one source: --cell or --source-polygon");
  api::VisibleRequest request;
  if (cell) request.source.cell = app::parse_cell(*cell);
  else request.source.polygon = app::parse_source_polygon(*polygon);
  request.triangle_ids = std::move(triangles);
  request.samples = samples;
  request.seed = app::parse_uint64(seed, "--seed");
  request.threads = app::check_thread_count(threads, "--threads");
  PythonProgress report(progress);
  if (report.active()) request.progress = [&report](std::int64_t d, std::int64_t t) { report(d, t); };
  api::VisibleAnswer answer;
  {
    py::gil_scoped_release release;
    answer = api::visible(scene, request);
  }
  report.rethrow();
  const auto n = static_cast<py::ssize_t>(answer.triangles.size());
  py::array_t<std::int64_t> ids(n);
  py::array_t<bool> vis(n);
  py::array_t<double> wit({static_cast<py::ssize_t>(answer.visible), py::ssize_t{2}, py::ssize_t{3}});
  py::list exact_wit;
  auto id = ids.mutable_unchecked<1>();
  auto vi = vis.mutable_unchecked<1>();
  auto w = wit.mutable_unchecked<3>();
  py::ssize_t k = 0;
  for (py::ssize_t i = 0; i < n; ++i) {
    const api::VisibleTriangle& t = answer.triangles[i];
    id(i) = t.id;
    vi(i) = t.visible;
    if (!t.visible) continue;
    const RationalPoint3* ends[2] = {&t.witness->p, &t.witness->q};
    py::list row;
    for (int e = 0; e < 2; ++e)
      for (int c = 0; c < 3; ++c) {
        w(k, e, c) = nearest_double((*ends[e])[c]);
        if (exact) row.append(exact_text((*ends[e])[c]));
      }
    if (exact) exact_wit.append(row);
    ++k;
  }
  const region::VisibilityStats& s = answer.stats;
  py::dict stats;
  stats["stabbing_pairs"] = s.stabbing_pairs;
  stats["occluders_considered"] = s.occluders_considered;
  stats["effective_occluders"] = s.effective_occluders;
  stats["samples_cast"] = s.samples_cast;
  stats["splits"] = s.splits;
  stats["cones_created"] = s.cones_created;
  stats["cones_alive_max"] = s.cones_alive_max;
  stats["real_line_tests"] = s.real_line_tests;
  stats["face_tests"] = s.face_tests;
  stats["exact_evaluations"] = s.exact_evaluations;
  stats["queries"] = n;
  stats["visible"] = answer.visible;
  stats["accepted_by_sampling"] = answer.accepted_by_sampling;
  return py::make_tuple(ids, vis, wit, exact ? py::object(exact_wit) : py::object(py::none()), stats);
}

// The enumerations report progress only through ProgressBar: a process-wide observer forwards it, one
// observed call at a time.
struct BarsToPython : ProgressObserver {
  explicit BarsToPython(PythonProgress& p) : progress(p) {}
  void report(const std::string&, std::uint64_t done, std::uint64_t total) override {
    progress(static_cast<std::int64_t>(done), static_cast<std::int64_t>(total));
  }
  PythonProgress& progress;
};
std::mutex observed_call_mutex;

// events: the JSON text of `exactvis events --json`.
std::string run_events(Scene scene, const std::string& kinds, std::optional<std::string> light, bool split,
                       py::object progress) {
  api::EventsRequest request;
  std::tie(request.ev, request.eee) = api::parse_event_kinds(kinds);
  if (light) request.light = app::parse_light(scene, *light);
  request.split_at_end_objects = split;
  PythonProgress report(progress);
  BarsToPython observer(report);
  std::string text;
  {
    py::gil_scoped_release release;
    std::unique_lock<std::mutex> lock(observed_call_mutex, std::defer_lock);
    if (report.active()) {
      lock.lock();
      set_progress_observer(&observer);
    }
    try {
      text = api::events_json(scene, api::events(scene, request)).dump();
    } catch (...) {
      if (report.active()) set_progress_observer(nullptr);
      throw;
    }
    if (report.active()) set_progress_observer(nullptr);
  }
  report.rethrow();
  return text;
}

// pvs: the JSON text of `exactvis pvs --json`. The cells: `cells_json` (the text of a cells file, named
// "cells" in messages), a cells file `cells_file`, or `grid` ("NX,NY,NZ") with an optional `box` (the
// --box text); exactly one of cells_json, cells_file and grid.
std::string run_pvs(const Scene& scene, py::object scene_label, std::optional<std::string> cells_json,
                    std::optional<std::string> cells_file, std::optional<std::string> grid,
                    std::optional<std::string> box, const std::string& method, int samples, std::int64_t rays,
                    const std::string& seed, int threads, bool witnesses, bool hierarchy, py::object progress) {
  if (static_cast<int>(cells_json.has_value()) + cells_file.has_value() + grid.has_value() != 1)
    throw std::invalid_argument("give exactly one of --grid and --cells");
  if (box && !grid) throw std::invalid_argument("--box: only with --grid");
  api::PvsRequest request;
  try {
    request.method = region::parse_pvs_method(method);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--method: ") + e.what());
  }
  if (samples < 0) throw std::invalid_argument("--samples must be >= 0");
  if (rays < -1) throw std::invalid_argument("--rays must be >= 0");
  region::PvsOptions& po = request.options;
  po.query.samples = samples;
  po.query.seed = app::parse_uint64(seed, "--seed");
  po.hierarchy = hierarchy;
  if (request.method == region::PvsMethod::sampled) po.cell_rays = rays >= 0 ? rays : 100000;
  else if (rays > 1000000) throw std::invalid_argument("--rays: at most 1000000 rays per triangle");
  else po.rays = rays >= 0 ? static_cast<int>(rays) : 8;
  po.threads = app::check_thread_count(threads, "--threads");
  if (grid) {
    const std::array<long, 3> n = app::parse_grid(*grid);
    std::optional<region::RationalBox3> b;
    if (box) b = app::parse_box(*box, "--box");
    request.cells = api::grid_view_cells(scene, n, b);
  } else if (cells_file) {
    request.cells = read_view_cells(*cells_file);
  } else {
    request.cells = view_cells_from_json_text(*cells_json, "cells");
  }
  const nlohmann::ordered_json label = scene_label.is_none() ? nlohmann::ordered_json(nullptr)
                                                             : nlohmann::ordered_json::parse(py::str(scene_label).cast<std::string>());
  PythonProgress report(progress);
  if (report.active()) request.progress = [&report](std::int64_t d, std::int64_t t) { report(d, t); };
  std::string text;
  {
    py::gil_scoped_release release;
    text = api::pvs_json(scene, api::pvs(scene, request), label, witnesses).dump();
  }
  report.rethrow();
  return text;
}

// skeleton: the JSON text of `exactvis skeleton --json` (of the pair's slice with `pair` "A,B").
std::string run_skeleton(const Scene& scene, std::optional<std::string> pair, py::object progress) {
  api::SkeletonRequest request;
  if (pair) request.pair = api::parse_skeleton_pair(scene, *pair);
  PythonProgress report(progress);
  BarsToPython observer(report);
  std::string text;
  {
    py::gil_scoped_release release;
    std::unique_lock<std::mutex> lock(observed_call_mutex, std::defer_lock);
    if (report.active()) {
      lock.lock();
      set_progress_observer(&observer);
    }
    try {
      text = api::skeleton_json(scene, api::skeleton(scene, request)).dump();
    } catch (...) {
      if (report.active()) set_progress_observer(nullptr);
      throw;
    }
    if (report.active()) set_progress_observer(nullptr);
  }
  report.rethrow();
  return text;
}

// shadows: the JSON text of `exactvis shadows --json`; `lights` as repeated --light SPEC, `receivers` as
// --receivers (the scene is a copy: a polygon light is appended to it).
std::string run_shadows(Scene scene, const std::string& scene_name, const std::vector<std::string>& lights,
                        const std::string& receivers, py::object progress) {
  if (lights.empty()) throw std::invalid_argument("--light is required");
  shadows::ShadowOptions options;
  std::set<int> light;
  for (const auto& spec : lights)
    for (int t : app::parse_light(scene, spec).triangles)
      if (light.insert(t).second) options.light.push_back(t);
  options.receivers = api::parse_receivers(scene, receivers, options.light);
  if (options.receivers.empty() && light.size() == scene.triangles.size())
    throw std::invalid_argument(scene_name + ": no receiver triangles (every triangle is part of the light)");
  options.vertex_irradiance = false;  // only the mesh files need it
  PythonProgress report(progress);
  BarsToPython observer(report);
  std::string text;
  {
    py::gil_scoped_release release;
    std::unique_lock<std::mutex> lock(observed_call_mutex, std::defer_lock);
    if (report.active()) {
      lock.lock();
      set_progress_observer(&observer);
    }
    try {
      text = api::shadows_json(scene, api::shadows(scene, options), options.light).dump();
    } catch (...) {
      if (report.active()) set_progress_observer(nullptr);
      throw;
    }
    if (report.active()) set_progress_observer(nullptr);
  }
  report.rethrow();
  return text;
}

// The 2D complex's progress: a plain function pointer, so one Python callback at a time per process.
std::mutex complex2d_mutex;
PythonProgress* complex2d_progress = nullptr;
void complex2d_report(double fraction) {
  if (complex2d_progress) (*complex2d_progress)(static_cast<std::int64_t>(fraction * 1000.0 + 0.5), 1000);
}

// complex2d: the JSON text of `exactvis complex2d --json`; the scene is a 2D scene JSON text (named `name`
// in messages) or a file (2D JSON, or a 3D mesh with `slice`).
std::string run_complex2d(std::optional<std::string> json_text, const std::string& name, const std::string& slice,
                          py::object progress) {
  Scene2D scene;
  if (json_text) {
    const std::vector<PolygonInput2D> polys = polygons2d_from_json(nlohmann::json::parse(*json_text), name);
    try {
      scene = make_scene2d(polys);
    } catch (const Scene2DError& e) {
      throw InputError(name + ": " + e.what());
    }
  } else {
    scene = load_scene2d(name, slice);
  }
  PythonProgress report(progress);
  std::string text;
  {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(complex2d_mutex);
    complex2d_progress = report.active() ? &report : nullptr;
    try {
      text = api::complex2d_json(scene, visibility_complex(scene, report.active() ? complex2d_report : nullptr)).dump();
    } catch (...) {
      complex2d_progress = nullptr;
      throw;
    }
    complex2d_progress = nullptr;
  }
  report.rethrow();
  return text;
}

}  // namespace

PYBIND11_MODULE(_exactvis, m) {
  m.doc() = "exactvis compiled core (use the exactvis package: docs/python.md)";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const Scene2DError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.attr("__version__") = EXACTVIS_VERSION;

  py::class_<Scene>(m, "Scene", "A triangle scene with stable triangle ids (docs/theory.md section 4)")
      .def(py::init([](const std::vector<std::string>& paths) { return load_scenes(paths); }), py::arg("paths"))
      .def(py::init(&scene_from_numpy), py::arg("V"), py::arg("F"))
      .def_property_readonly("vertices", &scene_vertices, "n x 3 float64: the vertices")
      .def_property_readonly("faces", &scene_faces, "m x 3 int64: vertex indices of the kept triangles")
      .def_property_readonly("ids", [](const Scene& s) {
        py::array_t<std::int64_t> out(static_cast<py::ssize_t>(s.triangles.size()));
        auto o = out.mutable_unchecked<1>();
        for (std::size_t i = 0; i < s.triangles.size(); ++i) o(i) = s.triangles[i].id;
        return out;
      }, "m int64: stable id of each kept triangle (row of faces)")
      .def_property_readonly("objects", [](const Scene& s) {
        py::array_t<std::int64_t> out(static_cast<py::ssize_t>(s.triangles.size()));
        auto o = out.mutable_unchecked<1>();
        for (std::size_t i = 0; i < s.triangles.size(); ++i) o(i) = s.triangles[i].object;
        return out;
      }, "m int64: object index of each kept triangle")
      .def_property_readonly("object_names", [](const Scene& s) {
        std::vector<std::string> names;
        for (const auto& o : s.objects) names.push_back(o.name);
        return names;
      })
      .def_readonly("faces_read", &Scene::faces_read, "triangles before dropping zero-area ones (ids 0 .. faces_read-1)")
      .def_readonly("degenerate_dropped", &Scene::degenerate_dropped);

  m.def("_visible", &run_visible, py::arg("scene"), py::arg("cell"), py::arg("polygon"), py::arg("triangles"),
        py::arg("samples"), py::arg("seed"), py::arg("threads"), py::arg("exact"), py::arg("progress"));
  m.def("_events", &run_events, py::arg("scene"), py::arg("kinds"), py::arg("light"), py::arg("split"),
        py::arg("progress"));
  m.def("_pvs", &run_pvs, py::arg("scene"), py::arg("scene_label"), py::arg("cells_json"), py::arg("cells_file"),
        py::arg("grid"), py::arg("box"), py::arg("method"), py::arg("samples"), py::arg("rays"), py::arg("seed"),
        py::arg("threads"), py::arg("witnesses"), py::arg("hierarchy"), py::arg("progress"));
  m.def("_skeleton", &run_skeleton, py::arg("scene"), py::arg("pair"), py::arg("progress"));
  m.def("_shadows", &run_shadows, py::arg("scene"), py::arg("scene_name"), py::arg("lights"), py::arg("receivers"),
        py::arg("progress"));
  m.def("_complex2d", &run_complex2d, py::arg("json_text"), py::arg("name"), py::arg("slice"), py::arg("progress"));
}
