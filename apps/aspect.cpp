// `exactvis aspect SCENE --orthographic | --perspective | --plane z=H [--json] [-o F] [--vtp F] [--png F]`:
// the aspect graph of a 3D model (docs/cli.md, docs/theory.md "Aspect graphs of polyhedra").
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "aspect/convex_aspect_graph.hpp"
#include "aspect/closed_solid_fronts.hpp"
#include "aspect/general_orthographic_aspect_graph.hpp"
#include "aspect/convex_model.hpp"
#include "aspect/orthographic_aspect_graph.hpp"
#include "aspect/partition_picture.hpp"
#include "aspect/plane_aspect_graph.hpp"
#include "aspect/triangle_contacts.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/render_partition_png.hpp"
#include "io/write_vtp.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

namespace {

using namespace exactvis;
using ojson = nlohmann::ordered_json;  // the documented key order

struct AspectOptions {
  std::vector<std::string> scenes;
  bool orthographic = false, perspective = false;
  std::string plane, output, vtp, png;
  bool json = false, quiet = false;
};

std::string scene_label(const std::vector<std::string>& files) {
  std::string s;
  for (const auto& f : files) s += (s.empty() ? "" : ",") + f;
  return s;
}

ojson event_json(const AspectAdjacency3& a) {
  ojson generators = ojson::array();
  std::string type;
  for (const AspectEvent3& e : a.events) {
    if (type.empty()) type = e.type;
    else if (type != e.type) type = "EV+EEE";
    if (e.type == "EEE")
      generators.push_back({{"type", e.type},
                            {"edges", {{e.edges[0][0], e.edges[0][1]}, {e.edges[1][0], e.edges[1][1]},
                                       {e.edges[2][0], e.edges[2][1]}}},
                            {"triangles", e.triangles}});
    else
      generators.push_back({{"type", e.type}, {"vertex", e.vertex}, {"edge", {e.edge[0], e.edge[1]}},
                            {"triangles", e.triangles}});
  }
  return {{"type", type}, {"generators", generators}};
}

ojson graph_json(const AspectGraph3& g) {
  ojson j;
  j["regions"] = ojson::array();
  for (std::size_t i = 0; i < g.regions.size(); ++i) {
    const AspectRegion3& r = g.regions[i];
    j["regions"].push_back({{"id", i},
                            {"dimension", r.dimension},
                            {"aspect", r.aspect},
                            {"sample", {app::exact_json(r.sample.x), app::exact_json(r.sample.y),
                                        app::exact_json(r.sample.z)}}});
  }
  j["adjacency"] = ojson::array();
  for (const AspectAdjacency3& a : g.adjacency) j["adjacency"].push_back({a.a, a.b, event_json(a)});
  j["counts"] = {{"regions", g.regions.size()}, {"edges", g.adjacency.size()}};
  return j;
}

std::string summary(const AspectGraph3& g, const std::string& what) {
  const bool ortho = g.view == ViewModel::Orthographic, plane = g.view == ViewModel::Plane;
  std::array<std::size_t, 4> per_dim{0, 0, 0, 0};
  for (const auto& r : g.regions) ++per_dim[r.dimension];
  std::string s = std::string(ortho ? "orthographic" : (plane ? "plane" : "perspective")) +
                  " aspect graph of " + what + ": " +
                  std::to_string(g.regions.size()) + " regions (";
  for (int d = ortho || plane ? 2 : 3; d >= 0; --d)
    s += std::to_string(per_dim[d]) + " of dimension " + std::to_string(d) + (d ? ", " : "");
  s += "), " + std::to_string(g.adjacency.size()) + " adjacencies; ";
  s += ortho ? "sphere cells " + std::to_string(g.cells[0]) + " vertices, " + std::to_string(g.cells[1]) + " arcs, " +
                   std::to_string(g.cells[2]) + " faces"
             : std::string(plane ? "cells of the plane" : "cells") + " outside the model " + std::to_string(g.cells[0]) + " vertices, " + std::to_string(g.cells[1]) +
                   " edges, " + std::to_string(g.cells[2]) + " faces" +
                   (plane ? std::string() : ", " + std::to_string(g.cells[3]) + " volumes");
  return s;
}

Point3 approx(const Vec3<Exact>& v) { return {CGAL::to_double(v.x), CGAL::to_double(v.y), CGAL::to_double(v.z)}; }

// The pictures of --png: the partition (sphere or plane; none for perspective space) and the model as seen
// from the samples of up to three regions of the largest dimension (first, middle, last).
// `values` colours the model's triangles; `partition` is the sphere or plane picture (none for perspective).
std::vector<PngPanel> png_panels(const Scene& scene, const std::vector<int>& values, const AspectGraph3& g,
                                 const PartitionPicture* partition, double h) {
  std::vector<PngPanel> panels;
  const Box3 b = bounding_box(scene);
  const Point3 centre{(b.lo.x + b.hi.x) / 2, (b.lo.y + b.hi.y) / 2, (b.lo.z + b.hi.z) / 2};
  const double size = std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z});
  const auto up_for = [](const Point3& d) {
    return std::abs(d.z) > 0.9 * std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) ? Point3{0, 1, 0} : Point3{0, 0, 1};
  };
  if (g.view == ViewModel::Orthographic) {
    const PartitionPicture& pic = *partition;
    PngPanel p{pic.points, pic.triangles, pic.triangle_region, pic.curves, {0, 0, 0}, {1, 0.8, 0.6}, true, {0, 0, 1}};
    panels.push_back(std::move(p));
  } else if (g.view == ViewModel::Plane) {
    const PartitionPicture& pic = *partition;
    panels.push_back({pic.points, pic.triangles, pic.triangle_region, pic.curves, {centre.x, centre.y, h},
                      {centre.x, centre.y, h + size}, true, {0, 1, 0}});
  }
  std::vector<int> top;
  for (std::size_t r = 0; r < g.regions.size(); ++r)
    if (g.regions[r].dimension == g.regions.front().dimension) top.push_back(static_cast<int>(r));
  std::vector<int> chosen{top.front()};
  if (top.size() > 2) chosen.push_back(top[top.size() / 2]);
  if (top.size() > 1) chosen.push_back(top.back());
  for (int r : chosen) {
    PngPanel p;
    p.points = scene.vertices;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
      p.triangles.push_back(scene.triangles[i].v);
      p.values.push_back(values[i]);
    }
    const Point3 s = approx(g.regions[r].sample);
    p.focal = centre;
    if (g.view == ViewModel::Orthographic) {
      p.eye = {centre.x + s.x, centre.y + s.y, centre.z + s.z};
      p.up = up_for(s);
    } else {
      p.eye = s;
      p.orthographic = false;
      // Wide enough to hold the model's bounding sphere, seen from the sample (which may be close to it).
      const double dist = std::sqrt((s.x - centre.x) * (s.x - centre.x) + (s.y - centre.y) * (s.y - centre.y) +
                                    (s.z - centre.z) * (s.z - centre.z));
      const double radius = 0.87 * size;
      p.view_angle = std::min(160.0, 1.2 * 2 * std::asin(std::min(1.0, radius / std::max(dist, 1e-300))) * 180 / M_PI);
      p.up = up_for({s.x - centre.x, s.y - centre.y, s.z - centre.z});
    }
    panels.push_back(std::move(p));
  }
  return panels;
}

// The partition picture (sphere or plane) as .vtp, one cell value "region" per triangle, staged in `outputs`.
void write_partition_vtp(OutputFiles& outputs, const std::string& path, const PartitionPicture& pic) {
  outputs.write(path, [&](const std::string& temp) {
    write_surface_with_lines_vtp(temp, pic.points, pic.triangles, pic.triangle_region, pic.curves,
                                 std::vector<std::int64_t>(pic.curves.size(), -1), "region");
    return true;
  });
}

// The --png panels rendered side by side (480 pixels each), staged in `outputs`.
void write_partition_png(OutputFiles& outputs, const std::string& path, const std::vector<PngPanel>& panels) {
  outputs.write(path, [&](const std::string& temp) { return render_panels_png(temp, panels, 480), true; });
}

// 0, 1, ..., n-1: each triangle its own colour in the model panels.
std::vector<int> triangle_indices(const Scene& scene) {
  std::vector<int> values(scene.triangles.size());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<int>(i);
  return values;
}

// Cost warning before the work (docs/cli.md): time scaled from docs/performance.md (bench_aspect: convex
// models 3.9 CPU s for 186 face planes orthographic, growth below m^3; 7.7 s for 62 planes perspective, below
// m^4; non-convex closed solids 41 CPU s for 988 great circles, about 4 m^2 cells at 10 us each).
// Non-convex models on a plane (trace lines): 14.9 CPU s for 324 lines (docs/performance.md), O(m^2) cells at O(m) each.
std::string cost_warning(std::size_t m, ViewModel view, const char* what = "face planes") {
  const bool ortho = view == ViewModel::Orthographic, circles = std::string(what) == "great circles",
             lines = std::string(what) == "trace lines";
  const double seconds = circles ? 41.0 * std::pow(m / 988.0, 2)
                         : lines ? 14.9 * std::pow(m / 324.0, 3)
                                 : (ortho ? 3.9 * std::pow(m / 186.0, 3) : 7.7 * std::pow(m / 62.0, 4));
  if (seconds < 60) return "";
  std::ostringstream w;
  w.precision(2);
  w << "aspect: warning: " << m << " " << what << ": the "
    << (ortho ? "orthographic" : (lines ? "plane's" : "perspective")) << " arrangement has O(m^"
    << (ortho || lines ? 2 : 3) << ") cells at " << (circles ? "O(1)" : "O(m)") << " each; roughly " << seconds
    << " s (scaled from docs/performance.md)";
  return w.str();
}

// The outputs of an orthographic graph of a non-convex model: JSON (-o, --json), the sphere pictures
// (--vtp, --png) from its sampled cells, and the text summary naming `model`. Returns the exit status 0.
int write_sphere_graph(const AspectOptions& o, const Scene& scene, const AspectGraph3& g, OutputFiles& outputs,
                       const std::string& model) {
  const ojson j = graph_json(g);
  if (!o.output.empty()) exactvis::app::write_json_output(outputs, o.output, j);
  if (!o.vtp.empty() || !o.png.empty()) {
    const PartitionPicture pic = sphere_picture_of_cells(g, o.vtp.empty() ? 5 : 6);
    if (!o.vtp.empty()) write_partition_vtp(outputs, o.vtp, pic);
    if (!o.png.empty()) write_partition_png(outputs, o.png, png_panels(scene, triangle_indices(scene), g, &pic, 0));
  }
  outputs.commit();
  if (o.json) std::cout << app::json_text(j);
  else std::cout << summary(g, model) << "\n";
  return 0;
}

// Orthographic, a model outside the class of docs/theory.md 10.5: a closed solid whose front parts are not all
// convex, or (`open`) a model that is not a closed solid at all, its triangles two-sided (10.10):
// aspect/general_orthographic_aspect_graph, from the free EV and EEE arcs and exact per-direction aspects; a
// model with free EEE arcs outside the subset of 10.11 gets a one-line error.
int run_outside_class_orthographic(const AspectOptions& o, const Scene& scene, const std::string& label,
                                   OutputFiles& outputs, bool open) {
  // Cost (docs/performance.md): the free arcs grow like e^3 n (0.7 CPU s for a 3 x 3 terrain of 33 edges and
  // 18 triangles, the costlier per triple of the models measured; rows of boxes 4x less), the cells like m^2.
  if (scene.triangles.size() > 60 && !o.quiet) {
    std::set<std::pair<int, int>> edges;
    for (const auto& t : scene.triangles)
      for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t.v[k], t.v[(k + 1) % 3]));
    const double e = static_cast<double>(edges.size()), n = static_cast<double>(scene.triangles.size());
    std::ostringstream w;
    w.precision(2);
    w << "aspect: warning: " << scene.triangles.size()
      << (open ? " two-sided triangles of a model that is not a closed solid"
               : " triangles outside the class of docs/theory.md 10.5")
      << ": the free EEE arcs take O(e^3 n^2) exact tests, roughly " << 0.7 * std::pow(e / 33, 3) * (n / 18)
      << " s for its " << edges.size()
      << " edges (scaled like e^3 n from docs/performance.md), then every cell an exact aspect";
    std::cerr << w.str() << std::endl;
  }
  const bool pictures = !o.vtp.empty() || !o.png.empty();
  const GeneralOrthographicResult r = [&] {
    app::FractionProgress bar("aspect: arrangement", app::progress_wanted(o.quiet));
    return general_orthographic_aspect_graph(scene, bar.callback(), pictures);
  }();
  if (!r.ok) throw InputError(label + ": " + r.problem);
  return write_sphere_graph(o, scene, r.graph, outputs,
                            std::string(open ? "a model that is not a closed solid (two-sided triangles)"
                                             : "a closed model outside the convex-front class") +
                                " with " + std::to_string(scene.triangles.size()) + " triangles (" +
                                std::to_string(r.circles) + " great circles of free EV arcs)");
}

// Orthographic, a model that is not convex: a closed solid whose front parts are convex
// (aspect/orthographic_aspect_graph), else run_outside_class_orthographic: other closed solids, and models that
// are not closed solids (open, non-manifold or inconsistently oriented) whose triangles meet only in shared
// corners and edges (aspect/triangle_contacts; each triangle then a two-sided occluder, theory 10.10).
int run_general_orthographic(const AspectOptions& o, const Scene& scene, const std::string& label,
                             OutputFiles& outputs) {
  const ClosedSolidFronts fronts = closed_solid_fronts(scene);
  if (!fronts.ok && fronts.outside_class) return run_outside_class_orthographic(o, scene, label, outputs, false);
  if (!fronts.ok && fronts.not_solid) {
    if (const std::string p = triangle_contact_problem(scene); !p.empty()) throw InputError(label + ": " + p);
    return run_outside_class_orthographic(o, scene, label, outputs, true);
  }
  if (!fronts.ok) throw InputError(label + ": " + fronts.problem);
  const std::size_t circles = orthographic_aspect_circles(scene, fronts);
  if (const std::string w = cost_warning(circles, ViewModel::Orthographic, "great circles"); !w.empty() && !o.quiet)
    std::cerr << w << std::endl;
  const AspectGraph3 g = [&] {
    app::FractionProgress bar("aspect: arrangement", app::progress_wanted(o.quiet));
    // Every cell's sample and sign vector is kept only for the pictures (O(circles) memory per cell).
    return orthographic_aspect_graph(scene, fronts, bar.callback(), !o.vtp.empty() || !o.png.empty());
  }();
  return write_sphere_graph(o, scene, g, outputs,
                            "a non-convex closed model with " + std::to_string(scene.triangles.size()) +
                                " triangles (" + std::to_string(circles) + " great circles)");
}

// Perspective viewpoints on z = H, a closed solid that is not convex (aspect/plane_aspect_graph: its front
// parts must be convex, else a one-line error).
int run_general_plane(const AspectOptions& o, const Scene& scene, const Exact& height, const std::string& label,
                      OutputFiles& outputs) {
  const ClosedSolidFronts fronts = closed_solid_fronts(scene);
  if (!fronts.ok && fronts.not_solid)
    throw InputError(label + ": " + fronts.problem +
                     "; --plane z=H needs a closed solid (--orthographic takes such models, docs/theory.md 10.10)");
  if (!fronts.ok) throw InputError(label + ": " + fronts.problem);
  const std::size_t lines = plane_aspect_lines(scene, fronts, height);
  if (const std::string w = cost_warning(lines, ViewModel::Plane, "trace lines"); !w.empty() && !o.quiet)
    std::cerr << w << std::endl;
  const bool pictures = !o.vtp.empty() || !o.png.empty();
  const AspectGraph3 g = [&] {
    app::FractionProgress bar("aspect: arrangement", app::progress_wanted(o.quiet));
    return plane_aspect_graph(scene, fronts, height, bar.callback(), pictures);
  }();
  const ojson j = graph_json(g);
  if (!o.output.empty()) exactvis::app::write_json_output(outputs, o.output, j);
  if (pictures) {
    const Box3 b = bounding_box(scene);
    const double w = std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y), h = CGAL::to_double(height);
    const PartitionPicture pic =
        plane_picture_of_cells(g, h, b.lo.x - w, b.lo.y - w, b.hi.x + w, b.hi.y + w, o.vtp.empty() ? 120 : 240);
    if (!o.vtp.empty()) write_partition_vtp(outputs, o.vtp, pic);
    if (!o.png.empty()) write_partition_png(outputs, o.png, png_panels(scene, triangle_indices(scene), g, &pic, h));
  }
  outputs.commit();
  if (o.json) std::cout << app::json_text(j);
  else
    std::cout << summary(g, "a non-convex closed model with " + std::to_string(scene.triangles.size()) +
                                " triangles (" + std::to_string(lines) + " trace lines)")
              << "\n";
  return 0;
}

int run(const AspectOptions& o) {
  const int views = int(o.orthographic) + int(o.perspective) + int(!o.plane.empty());
  if (views != 1) throw std::invalid_argument("--orthographic, --perspective or --plane z=H: give exactly one");
  Exact height(0);
  if (!o.plane.empty()) {
    const std::string p = app::trim(o.plane);
    if (p.size() < 3 || p.compare(0, 2, "z=") != 0)
      throw std::invalid_argument("--plane: '" + o.plane + "' is not z=H (H a number or num/den)");
    height = app::parse_exact(p.substr(2), "--plane");
  }
  if (!o.vtp.empty() && o.perspective)
    throw std::invalid_argument("--vtp: pictures of the perspective partition of space are not implemented; use "
                                "--orthographic (the viewing sphere) or --plane z=H");
  OutputFiles outputs({o.output, o.vtp, o.png});
  const Scene scene = load_scenes(o.scenes);
  const std::string label = scene_label(o.scenes);
  const ConvexModel model = convex_model(scene);
  if (!model.convex) {
    if (o.perspective)
      throw InputError(label + ": not a closed convex model (" + model.problem +
                       "); --perspective takes convex models only: use --plane z=H for perspective viewpoints on a "
                       "plane");
    if (!o.plane.empty()) return run_general_plane(o, scene, height, label, outputs);
    return run_general_orthographic(o, scene, label, outputs);
  }
  const ViewModel view =
      o.orthographic ? ViewModel::Orthographic : (o.perspective ? ViewModel::Perspective : ViewModel::Plane);
  if (const std::string w = cost_warning(model.planes.size(), view); !w.empty() && !o.quiet) std::cerr << w << std::endl;
  const AspectGraph3 g = [&] {
    app::FractionProgress bar("aspect: arrangement", app::progress_wanted(o.quiet));
    return !o.plane.empty() ? convex_aspect_graph_on_plane(scene, model, Vec3<Exact>(0, 0, 1), height, bar.callback())
                            : convex_aspect_graph(scene, model,
                                                  o.orthographic ? ViewModel::Orthographic : ViewModel::Perspective,
                                                  bar.callback());
  }();
  const ojson j = graph_json(g);
  if (!o.output.empty())
    exactvis::app::write_json_output(outputs, o.output, j);
  if (!o.vtp.empty()) {
    PartitionPicture pic;
    if (o.orthographic) {
      pic = sphere_picture(model, g, 6);
    } else {
      // The model's box widened by its size on each side.
      const Box3 b = bounding_box(scene);
      const double w = std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y);
      pic = plane_picture(model, g, CGAL::to_double(height), b.lo.x - w, b.lo.y - w, b.hi.x + w, b.hi.y + w, 240);
    }
    write_partition_vtp(outputs, o.vtp, pic);
  }
  if (!o.png.empty()) {
    PartitionPicture partition;
    if (o.orthographic) {
      partition = sphere_picture(model, g, 5);
    } else if (!o.plane.empty()) {
      const Box3 b = bounding_box(scene);
      const double w = std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y);
      partition = plane_picture(model, g, CGAL::to_double(height), b.lo.x - w, b.lo.y - w, b.hi.x + w, b.hi.y + w, 120);
    }
    write_partition_png(outputs, o.png, png_panels(scene, model.plane_of, g, &partition, CGAL::to_double(height)));
  }
  outputs.commit();
  if (o.json) std::cout << app::json_text(j);
  else std::cout << summary(g, "a convex model with " + std::to_string(model.planes.size()) + " face planes") << "\n";
  return 0;
}

const exactvis::app::CommandRegistration registration(
    "aspect", 230, [](CLI::App& parent) -> std::function<int()> {
      auto opts = std::make_shared<AspectOptions>();
      CLI::App* sub = parent.add_subcommand(
          "aspect", "exact aspect graph of a 3D model: regions of viewpoints with one set of visible triangles");
      sub->add_option("scene", opts->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene")->required();
      auto* ort = sub->add_flag("--orthographic", opts->orthographic, "viewpoints are directions (the viewing sphere); convex models, closed solids whose front parts are convex "
                                "(docs/theory.md 10.5), and other closed solids and open models (two-sided triangles), "
                                "bounded by free EV arcs (10.10) and free EEE arcs in the subset of 10.11");
      auto* per = sub->add_flag("--perspective", opts->perspective,
                                "viewpoints are points outside the model (convex models only)");
      auto* pla = sub->add_option("--plane", opts->plane, "viewpoints on the plane z=H (H a number or num/den); convex models and closed solids whose front parts are convex (docs/theory.md 10.8)");
      ort->excludes(per)->excludes(pla);
      per->excludes(pla);
      exactvis::app::add_json_flag(*sub, opts->json, "print regions, aspects, adjacency and counts as JSON on stdout");
      exactvis::app::add_output_option(*sub, opts->output, "write the JSON to this file");
      sub->add_option("--vtp", opts->vtp, "write the partition as VTK PolyData: the viewing sphere (or the plane) coloured by region (cell array "
                    "\"region\"), with the boundary curves (region -1)");
      sub->add_option("--png", opts->png, "render a PNG: the partition (sphere or plane) and the model seen from a few regions "
                    "(VTK offscreen; starts a private Xvfb when DISPLAY is unset)");
      exactvis::app::add_quiet_flag(*sub, opts->quiet, "no progress bar on stderr");
      return [opts] { return run(*opts); };
    });

}  // namespace
