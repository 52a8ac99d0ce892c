// `exactvis visible SCENE... (--cell X0,Y0,Z0,X1,Y1,Z1 | --source-polygon "x,y,z;...") [--triangles all|ID,...]
//  [--json] [-o result.json] [--vtp out.vtp] [--png out.png [--png-size WxH] [--witnesses]] [-q]`: exact
//  from-region visibility with witnesses.
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "io/atomic_file.hpp"
#include "io/json_number.hpp"
#include "io/load_scene.hpp"
#include "io/result_pictures.hpp"
#include "io/write_visibility_vtp.hpp"
#include "kernel/triangle_index.hpp"
#include "region/cell_visibility.hpp"
#include "util/format_number.hpp"
#include "util/progress_bar.hpp"
#include "util/text_table.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>

namespace {

using namespace exactvis;
using app::split;
using app::trim;

struct VisibleOptions {
  std::vector<std::string> scenes;
  std::string cell;
  std::string polygon;
  std::string triangles = "all";
  bool json = false;
  std::string output;
  std::string vtp;
  std::string png;
  std::string png_size = "1280x960";
  bool witnesses = false;
  int samples = 48;
  std::string seed = "1";
  int threads = 0;
  bool quiet = false;
};

std::vector<std::int64_t> parse_targets(const std::string& text, const Scene& scene) {
  std::vector<std::int64_t> out;
  if (trim(text).empty())
    throw std::invalid_argument("--triangles: no triangle ids given (\"all\" or comma-separated ids)");
  if (trim(text) == "all") {
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) out.push_back(static_cast<std::int64_t>(i));
    return out;
  }
  for (const auto& part : split(text, ',')) {
    const std::string t = trim(part);
    std::size_t used = 0;
    long long id = 0;
    try {
      id = std::stoll(t, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (t.empty() || used != t.size()) throw std::invalid_argument("--triangles: '" + t + "' is not a triangle id");
    const std::int64_t index = scene.index_of_id(id);
    if (index < 0)
      throw std::invalid_argument("--triangles: triangle id " + t +
                                  " is not in the scene (out of range, or dropped as degenerate)");
    out.push_back(index);
  }
  return out;
}

nlohmann::json point_json(const RationalPoint3& p) {
  return nlohmann::json::array({exact_to_json(p.x), exact_to_json(p.y), exact_to_json(p.z)});
}

nlohmann::json stats_json(const region::VisibilityStats& s) {
  return {{"stabbing_pairs", s.stabbing_pairs},   {"occluders_considered", s.occluders_considered},
          {"effective_occluders", s.effective_occluders}, {"samples_cast", s.samples_cast},
          {"splits", s.splits},                   {"cones_created", s.cones_created},
          {"cones_alive_max", s.cones_alive_max}, {"real_line_tests", s.real_line_tests},
          {"face_tests", s.face_tests},           {"exact_evaluations", s.exact_evaluations},
          {"accepted_by_sampling", s.accepted_by_sampling}};
}

int run_visible(const VisibleOptions& o) {
  if (o.cell.empty() == o.polygon.empty())
    throw std::invalid_argument("give exactly one source: --cell or --source-polygon");
  if (o.samples < 0) throw std::invalid_argument("--samples must be >= 0");
  region::CellVisibilityOptions co;
  co.query.samples = o.samples;
  co.query.seed = app::parse_uint64(o.seed, "--seed");
  co.threads = app::check_thread_count(o.threads, "--threads");
  region::VisibilitySource source;
  if (!o.cell.empty()) source.cell = app::parse_cell(o.cell);
  else source.polygon = app::parse_source_polygon(o.polygon);
  const std::optional<region::RationalBox3>& cell = source.cell;
  const region::Polygon3& polygon = source.polygon;

  const std::array<int, 2> png_size = app::parse_png_size(o.png_size);
  OutputFiles outputs({o.output, o.vtp, o.png});  // checked now, written together at the end

  const Scene scene = load_scenes(o.scenes);
  const std::vector<std::int64_t> targets = parse_targets(o.triangles, scene);
  region::CellVisibility cv;
  {
    ProgressBar bar("visible", targets.size(), app::progress_wanted(o.quiet));
    co.on_target_done = [&bar] { bar.advance(); };
    cv = region::visibility_from_source(scene, TriangleIndex(scene), source, targets, co);
  }
  const std::vector<region::VisibilityResult>& results = cv.results;

  nlohmann::json j;
  if (cell)
    j["source"] = {{"cell", {exact_to_json(cell->lo.x), exact_to_json(cell->lo.y), exact_to_json(cell->lo.z),
                             exact_to_json(cell->hi.x), exact_to_json(cell->hi.y), exact_to_json(cell->hi.z)}}};
  else {
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& p : polygon) pts.push_back(point_json(p));
    j["source"] = {{"polygon", pts}};
  }
  j["results"] = nlohmann::json::array();
  const std::int64_t n_visible = cv.visible;
  for (const auto& r : results) {
    nlohmann::json e;
    e["triangle"] = scene.triangles[r.triangle_index].id;
    e["visible"] = r.visible;
    if (r.visible) e["witness"] = {point_json(r.witness->p), point_json(r.witness->q)};
    j["results"].push_back(e);
  }
  j["stats"] = stats_json(cv.stats);
  j["stats"].erase("accepted_by_sampling");
  j["stats"]["queries"] = results.size();
  j["stats"]["visible"] = n_visible;
  j["stats"]["accepted_by_sampling"] = cv.accepted_by_sampling;

  // The pictures (--vtp, --png): per-triangle state, witnesses and the source's faces (double approximations).
  std::vector<int> state(scene.triangles.size(), -1);
  std::vector<WitnessSegment> segs;
  for (const auto& r : results) {
    state[r.triangle_index] = r.visible ? 1 : 0;
    if (r.visible) {
      auto dbl = [](const RationalPoint3& p) {
        return Point3{CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)};
      };
      segs.push_back({scene.triangles[r.triangle_index].id, dbl(r.witness->p), dbl(r.witness->q)});
    }
  }
  std::vector<std::vector<Point3>> source_faces;  // the cell's 6 faces or the polygon, drawn with the result
  auto approx = [](const region::Polygon3& poly) {
    std::vector<Point3> out;
    for (const auto& p : poly) out.push_back({CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)});
    return out;
  };
  if (cell)
    for (int axis = 0; axis < 3; ++axis)
      for (const bool high : {false, true}) source_faces.push_back(approx(region::box_face(*cell, axis, high)));
  else
    source_faces.push_back(approx(polygon));
  if (!o.vtp.empty())
    outputs.write(o.vtp, [&](const std::string& temp) { return write_visibility_vtp(temp, scene, state, segs, source_faces), true; });
  if (!o.png.empty()) {
    const ScenePicture picture =
        visibility_picture(scene, state, o.witnesses ? segs : std::vector<WitnessSegment>{}, source_faces,
                           "exactvis visible: " + format_count(n_visible) + " of " +
                               format_count(static_cast<std::int64_t>(results.size())) + " triangles visible");
    outputs.write(o.png, [&](const std::string& temp) { return render_scene_png(temp, picture, png_size[0], png_size[1]); });
  }
  if (!o.output.empty()) {
    exactvis::app::write_json_output(outputs, o.output, j);
  }
  outputs.commit();
  if (o.json) {
    std::cout << exactvis::app::json_text(j);
  } else {
    std::vector<std::vector<std::string>> rows;
    for (const auto& r : results) {
      if (rows.size() == kSummaryRows) break;
      rows.push_back({format_count(scene.triangles[r.triangle_index].id), r.visible ? "visible" : "hidden"});
    }
    print_table(std::cout, {"triangle", "from the source"}, rows, static_cast<std::int64_t>(results.size()));
    for (const std::string& f : {o.output, o.vtp, o.png})
      if (!f.empty()) std::cout << "wrote " << f << "\n";
    std::cout << n_visible << " of " << results.size() << " triangles visible\n";
  }
  return 0;
}

const exactvis::app::CommandRegistration registration("visible", 100, [](CLI::App& parent) {
  auto o = std::make_shared<VisibleOptions>();
  CLI::App* sub = parent.add_subcommand(
      "visible",
      "Exact from-region visibility: which triangles are visible from a view cell or a convex polygon, with a "
      "witness segment for each visible one (positive-measure definition; docs/theory.md section 5)");
  sub->add_option("scene", o->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene")->required();
  auto* c = sub->add_option("--cell", o->cell,
                            "Axis-aligned view cell X0,Y0,Z0,X1,Y1,Z1 (X0<X1, Y0<Y1, Z0<Z1; numbers or num/den)");
  auto* p = sub->add_option("--source-polygon", o->polygon,
                            "Convex planar source polygon \"x,y,z;x,y,z;...\" (numbers or num/den)");
  c->excludes(p);
  sub->add_option("--triangles", o->triangles, "\"all\" or comma-separated scene triangle ids")->capture_default_str();
  exactvis::app::add_json_flag(*sub, o->json, "Print the JSON result on stdout");
  exactvis::app::add_output_option(*sub, o->output, "Write the JSON result to this file");
  sub->add_option("--vtp", o->vtp, "Write the scene coloured visible/hidden with the witnesses as lines (.vtp)");
  sub->add_option("--png", o->png,
                  "Render a picture (VTK offscreen; starts Xvfb when DISPLAY is unset): the scene coloured "
                  "visible/hidden, the cell or polygon as a blue wire frame, a legend");
  sub->add_option("--png-size", o->png_size, "Size of the --png picture in pixels, WxH")->capture_default_str();
  sub->add_flag("--witnesses", o->witnesses, "Draw the witness segments in the --png picture as thin lines");
  exactvis::app::add_samples_option(*sub, o->samples);
  exactvis::app::add_seed_option(*sub, o->seed);
  exactvis::app::add_threads_option(*sub, o->threads);
  exactvis::app::add_quiet_flag(*sub, o->quiet);
  return [o]() { return run_visible(*o); };
});

}  // namespace
