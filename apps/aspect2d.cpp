// `exactvis aspect2d SCENE2D [--slice z=V] [--json] [--svg out.svg] [--vtp out.vtp] [--margin R] [-q]`: the
// aspect graph of a planar scene: viewpoint regions of equal visible-edge sets (docs/cli.md).
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "aspect/aspect_graph_2d.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/scene2d_json.hpp"
#include "io/svg_2d.hpp"
#include "io/vtp_2d.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace {

using namespace exactvis;

struct Aspect2DOptions {
  std::string scene, slice, svg, vtp;
  bool json = false, quiet = false;
  double margin = 0.25;
};

using ojson = nlohmann::ordered_json;  // keeps the documented key order ("counts" first)

using app::exact_json;  // exact values: a JSON number when exactly a double, else "num/den"
using app::point_json;

// Above this many scene vertices aspect2d warns about its cost before it starts (docs/cli.md).
constexpr int kLargeScene = 200;
// Once the arrangement is built, it warns when the face stage is estimated to take longer than this.
constexpr double kLongFaceStageSeconds = 60;
// Cost of the face stage: one visibility sweep per face, about 4 microseconds per face and scene vertex on
// the benchmark machine (docs/performance.md: 2.7 on a 1000-vertex polygon, 4.4 on the 96-vertex grid).
constexpr double kSecondsPerFaceVertex = 4e-6;

// The first warning: the worst-case growth, scaled from the benchmark grids (docs/performance.md: 215 s and
// 0.73 GB at 216 vertices).
std::string size_warning(int n) {
  const double f = std::pow(n / 216.0, 4);
  std::ostringstream w;
  w.precision(2);
  w << "aspect2d: warning: " << n << " vertices (more than " << kLargeScene
    << "): the aspect graph costs up to O(n^4) time and memory; the benchmark grids' 215 s and 0.73 GB at 216 "
       "vertices (docs/performance.md) scale to roughly "
    << 215 * f << " s and " << 0.73 * f << " GB here";
  return w.str();
}

// The second warning: the face stage's estimated time, from the number of faces.
std::string faces_warning(std::size_t faces, int n, double seconds) {
  std::ostringstream w;
  w.precision(2);
  w << "aspect2d: warning: " << faces << " arrangement faces, one visibility sweep each over " << n
    << " vertices: roughly " << seconds << " s more (about " << kSecondsPerFaceVertex * 1e6
    << " us per face and vertex, docs/performance.md)";
  return w.str();
}

std::vector<std::array<double, 2>> approx(const std::vector<Point2>& r) {
  std::vector<std::array<double, 2>> out;
  for (const Point2& p : r) out.push_back({p.ax, p.ay});
  return out;
}

int run(const Aspect2DOptions& o) {
  if (!(o.margin >= 0) || !std::isfinite(o.margin)) throw std::invalid_argument("--margin must be a finite number >= 0");
  OutputFiles outputs({o.svg, o.vtp});  // fails now, not after the work, when an output cannot be created
  const Scene2D scene = load_scene2d(o.scene, o.slice);
  if (!frame_box(scene, o.margin).representable)
    throw InputError(o.scene + ": the viewpoint frame (the scene's box widened by --margin times its size) would "
                     "reach beyond the largest double (1.8e308); use a smaller --margin");
  const int n = scene.num_vertices();
  if (n > kLargeScene && !o.quiet) std::cerr << size_warning(n) << std::endl;
  const auto warn_faces = [&](std::size_t faces) {
    const double seconds = kSecondsPerFaceVertex * static_cast<double>(faces) * n;
    if (seconds > kLongFaceStageSeconds && !o.quiet) std::cerr << faces_warning(faces, n, seconds) << std::endl;
  };
  const AspectGraph2D g = aspect_graph(scene, o.margin, app::progress_wanted(o.quiet), warn_faces);
  if (o.json) {
    ojson j;
    j["counts"] = {{"regions", g.regions.size()}, {"adjacencies", g.adjacency.size()},
                   {"arrangement_faces", g.arrangement_faces}, {"event_segments", g.event_segments}};
    j["edges"] = ojson::array();
    for (int e = 0; e < scene.num_vertices(); ++e)
      j["edges"].push_back({{"id", e}, {"object", scene.object_of(e)}, {"a", point_json(scene.points[e])},
                            {"b", point_json(scene.points[scene.next[e]])}});
    j["regions"] = ojson::array();
    for (const auto& r : g.regions) {
      ojson faces = ojson::array();
      for (int f : r.faces) {
        ojson outer = ojson::array();
        for (const Point2& p : g.faces[f].outer) outer.push_back(point_json(p));
        ojson holes = ojson::array();
        for (const auto& h : g.faces[f].holes) {
          holes.push_back(ojson::array());
          for (const Point2& p : h) holes.back().push_back(point_json(p));
        }
        faces.push_back({{"outer", outer}, {"holes", holes}, {"sample", point_json(g.faces[f].sample)}});
      }
      j["regions"].push_back({{"aspect", r.aspect}, {"faces", faces}});
    }
    j["adjacency"] = g.adjacency;
    const Ring2D& fr = g.framed.rings[g.framed.frame_ring];
    j["frame"] = {point_json(g.framed.points[fr.first]), point_json(g.framed.points[fr.first + 2])};
    std::cout << app::json_text(j);
  } else {
    std::cout << "regions " << g.regions.size() << ", adjacencies " << g.adjacency.size() << ", arrangement faces "
              << g.arrangement_faces << ", candidate event segments " << g.event_segments << "\n";
  }
  if (!o.svg.empty()) {
    SvgDocument2D doc = svg_document(g.framed);
    for (const auto& f : g.faces) {
      if (f.region < 0) continue;
      std::vector<std::vector<std::array<double, 2>>> rings{approx(f.outer)};
      for (const auto& h : f.holes) rings.push_back(approx(h));
      svg_rings(doc, rings, svg_colour(f.region), "none", 0.85);
    }
    for (const auto& b : g.boundaries) svg_segment(doc, {b[0].ax, b[0].ay}, {b[1].ax, b[1].ay}, "#404040", 0.4);
    svg_scene(doc, g.framed);
    // Each region's id at the exact interior sample of its first face (rounded for drawing).
    std::vector<bool> labelled(g.regions.size(), false);
    for (const auto& f : g.faces) {
      if (f.region < 0 || labelled[f.region]) continue;
      labelled[f.region] = true;
      svg_label(doc, {f.sample.ax, f.sample.ay}, std::to_string(f.region));
    }
    svg_legend(doc, SvgLegendEntry::Swatch::Area, svg_colour(0), "aspect region (one colour each, id as in --json)");
    svg_legend(doc, SvgLegendEntry::Swatch::Line, "#404040", "visual event boundary between regions");
    svg_legend(doc, SvgLegendEntry::Swatch::Area, "#9a9a9a", "obstacle");
    outputs.write(o.svg, [&](const std::string& temp) { return svg_write(doc, temp), true; });
  }
  if (!o.vtp.empty()) {
    VtpCells2D cells;
    for (const auto& f : g.faces) {
      if (f.region < 0) continue;
      cells.polygons.push_back({approx(f.outer)});
      for (const auto& h : f.holes) cells.polygons.back().push_back(approx(h));
      cells.polygon_values.push_back(f.region);
    }
    for (const auto& b : g.boundaries) {
      cells.lines.push_back({{{b[0].ax, b[0].ay}, {b[1].ax, b[1].ay}}});
      cells.line_values.push_back(-1);
    }
    outputs.write(o.vtp, [&](const std::string& temp) { return write_vtp_2d(temp, cells), true; });
  }
  outputs.commit();  // all output files appear together, or none
  return 0;
}

const exactvis::app::CommandRegistration registration(
    "aspect2d", 220, [](CLI::App& parent) -> std::function<int()> {
      auto opts = std::make_shared<Aspect2DOptions>();
      CLI::App* sub = parent.add_subcommand("aspect2d", "aspect graph of a 2D scene (viewpoint regions by visible edges)");
      sub->add_option("scene", opts->scene, "2D scene JSON, or a 3D mesh with --slice")->required();
      sub->add_option("--slice", opts->slice, "section of a 3D scene by a plane: x=V, y=V or z=V");
      exactvis::app::add_json_flag(*sub, opts->json, "print regions, aspects and adjacency as JSON on stdout");
      sub->add_option("--svg", opts->svg, "write a picture: regions coloured by aspect");
      sub->add_option("--vtp", opts->vtp, "write regions (cell value = region) as VTK PolyData");
      sub->add_option("--margin", opts->margin, "viewpoint frame margin, relative to the scene size (default 0.25)");
      exactvis::app::add_quiet_flag(*sub, opts->quiet, "no progress bars and no cost warning on stderr");
      return [opts] { return run(*opts); };
    });

}  // namespace
