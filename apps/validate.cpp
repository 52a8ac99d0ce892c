// `exactvis validate SCENE... --cells cells.json --pvs other.json [--json] [-o report.json] [--vtp DIR]`:
// checks another tool's PVS exactly (issue #12): per cell the false visible triangles (listed, exactly
// hidden) and the false invisible ones (missing, visible, each with a witness), the exact and reported sizes.
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/reported_pvs.hpp"
#include "io/view_cells.hpp"
#include "io/write_pvs_check_vtp.hpp"
#include "kernel/triangle_index.hpp"
#include "region/pvs_check.hpp"
#include "util/progress_bar.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace {

using namespace exactvis;
using nlohmann::ordered_json;

struct ValidateOptions {
  std::vector<std::string> scenes;
  std::string cells;
  std::string pvs;
  bool json = false;
  std::string output;
  std::string vtp;
  int samples = 48;
  std::string seed = "1";
  int threads = 0;
  bool quiet = false;
};

ordered_json rational_point_json(const RationalPoint3& p) {
  return ordered_json::array({app::exact_json(p.x), app::exact_json(p.y), app::exact_json(p.z)});
}

ordered_json ids_json(const Scene& scene, const std::vector<std::int64_t>& indices) {
  ordered_json a = ordered_json::array();
  for (const std::int64_t i : indices) a.push_back(scene.triangles[static_cast<std::size_t>(i)].id);
  return a;
}

std::string ids_text(const Scene& scene, const std::vector<std::int64_t>& indices) {
  std::string s;
  for (const std::int64_t i : indices) s += " " + std::to_string(scene.triangles[static_cast<std::size_t>(i)].id);
  return s;
}

Point3 rounded(const RationalPoint3& p) { return {CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)}; }

int run_validate(const ValidateOptions& o) {
  if (o.cells.empty()) throw std::invalid_argument("--cells: required (the view cells the PVS was computed for)");
  if (o.pvs.empty()) throw std::invalid_argument("--pvs: required (the PVS to check)");
  if (o.samples < 0) throw std::invalid_argument("--samples must be >= 0");
  region::CellVisibilityOptions co;
  co.query.samples = o.samples;
  co.query.seed = app::parse_uint64(o.seed, "--seed");
  co.threads = app::check_thread_count(o.threads, "--threads");

  const std::vector<region::RationalBox3> cells = read_view_cells(o.cells);
  const Scene scene = load_scenes(o.scenes);
  const ReportedPvs pvs = read_reported_pvs(o.pvs);
  const std::vector<std::vector<std::int64_t>> reported = reported_indices(pvs, scene, cells);
  {
    std::vector<bool> mentioned(cells.size(), false);
    for (const ReportedCell& c : pvs.cells) mentioned[static_cast<std::size_t>(c.cell)] = true;
    for (std::size_t k = 0; k < cells.size(); ++k)
      if (!mentioned[k]) std::cerr << o.pvs << ": cell " << k << " is not listed (checked as reported empty)\n";
  }

  // Every output is checked before the work (a missing directory fails now, not after hours).
  std::vector<std::string> vtp_paths;
  if (!o.vtp.empty()) {
    std::error_code ec;
    if (std::filesystem::exists(o.vtp, ec) && !std::filesystem::is_directory(o.vtp, ec))
      throw std::invalid_argument("--vtp: " + o.vtp + " exists and is not a directory");
    std::filesystem::create_directories(o.vtp, ec);
    if (ec) throw std::invalid_argument("--vtp: cannot create directory " + o.vtp + " (" + ec.message() + ")");
    for (std::size_t k = 0; k < cells.size(); ++k)
      vtp_paths.push_back((std::filesystem::path(o.vtp) / ("cell_" + std::to_string(k) + ".vtp")).string());
  }
  std::vector<std::string> all_outputs = vtp_paths;
  all_outputs.push_back(o.output);
  OutputFiles outputs(all_outputs);

  const TriangleIndex index(scene);
  std::vector<region::PvsCheck> checks;
  {
    ProgressBar bar("validate", cells.size() * scene.triangles.size(), app::progress_wanted(o.quiet));
    co.on_target_done = [&bar] { bar.advance(); };
    for (std::size_t k = 0; k < cells.size(); ++k)
      checks.push_back(region::check_reported_pvs(scene, index, cells[k], reported[k], co));
  }

  ordered_json j;
  j["cells"] = ordered_json::array();
  std::int64_t fv = 0, fi = 0, exact = 0, rep = 0;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const region::RationalBox3& b = cells[k];
    const region::PvsCheck& c = checks[k];
    ordered_json e;
    e["box"] = ordered_json::array({app::exact_json(b.lo.x), app::exact_json(b.lo.y), app::exact_json(b.lo.z),
                                    app::exact_json(b.hi.x), app::exact_json(b.hi.y), app::exact_json(b.hi.z)});
    e["false_visible"] = ids_json(scene, c.false_visible);
    e["false_invisible"] = ids_json(scene, c.false_invisible);
    e["witnesses"] = ordered_json::object();
    for (std::size_t i = 0; i < c.false_invisible.size(); ++i)
      e["witnesses"][std::to_string(scene.triangles[static_cast<std::size_t>(c.false_invisible[i])].id)] =
          ordered_json::array({rational_point_json(c.false_invisible_witness[i].p),
                               rational_point_json(c.false_invisible_witness[i].q)});
    e["exact"] = c.exact;
    e["reported"] = c.reported;
    j["cells"].push_back(e);
    fv += static_cast<std::int64_t>(c.false_visible.size());
    fi += static_cast<std::int64_t>(c.false_invisible.size());
    exact += c.exact;
    rep += c.reported;
  }
  j["totals"] = {{"false_visible", fv}, {"false_invisible", fi}, {"exact", exact}, {"reported", rep}};

  for (std::size_t k = 0; k < vtp_paths.size(); ++k) {
    const region::PvsCheck& c = checks[k];
    std::vector<int> status(scene.triangles.size());
    for (std::size_t i = 0; i < status.size(); ++i) {
      const bool ex = c.exactly_visible[i], re = c.reported_visible[i];
      status[i] = ex == re ? (ex ? kStatusVisible : kStatusHidden) : (re ? kStatusFalseVisible : kStatusFalseInvisible);
    }
    std::vector<StatusSegment> segs;
    for (std::size_t i = 0; i < c.false_invisible.size(); ++i)
      segs.push_back({scene.triangles[static_cast<std::size_t>(c.false_invisible[i])].id,
                      rounded(c.false_invisible_witness[i].p), rounded(c.false_invisible_witness[i].q)});
    outputs.write(vtp_paths[k], [&](const std::string& temp) {
      write_pvs_check_vtp(temp, scene, status, segs, cells[k]);
      return true;
    });
  }
  if (!o.output.empty())
    outputs.write(o.output, [&](const std::string& temp) {
      std::ofstream out(temp);
      out << j.dump(2) << "\n";
      return static_cast<bool>(out);
    });
  outputs.commit();

  if (o.json) {
    std::cout << j.dump(2) << "\n";
  } else {
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const region::PvsCheck& c = checks[k];
      std::cout << "cell " << k << ": exact " << c.exact << ", reported " << c.reported << ", false visible "
                << c.false_visible.size() << (c.false_visible.empty() ? "" : " (" + ids_text(scene, c.false_visible).substr(1) + ")")
                << ", false invisible " << c.false_invisible.size()
                << (c.false_invisible.empty() ? "" : " (" + ids_text(scene, c.false_invisible).substr(1) + ")") << "\n";
    }
    std::cout << "total over " << cells.size() << " cells: exact " << exact << ", reported " << rep
              << ", false visible " << fv << ", false invisible " << fi << "\n";
  }
  return 0;
}

const exactvis::app::CommandRegistration registration("validate", 110, [](CLI::App& parent) {
  auto o = std::make_shared<ValidateOptions>();
  CLI::App* sub = parent.add_subcommand(
      "validate",
      "Check another tool's PVS exactly: per view cell the false visible triangles (listed, exactly hidden) and "
      "the false invisible ones (missing, visible, with a witness segment each)");
  sub->add_option("scene", o->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene")->required();
  sub->add_option("--cells", o->cells, "View cells file {\"cells\": [[x0,y0,z0,x1,y1,z1], ...]}");
  sub->add_option("--pvs", o->pvs,
                  "The PVS to check: exactvis pvs JSON (or its JSON lines), or text lines 'cell_index: id id ...'");
  sub->add_flag("--json", o->json, "Print the JSON report on stdout (instead of the summary)");
  sub->add_option("-o,--output", o->output, "Write the JSON report to this file");
  sub->add_option("--vtp", o->vtp, "Write DIR/cell_K.vtp per cell: the scene coloured by status, with the cell box");
  sub->add_option("--samples", o->samples, "Random segments cast per source/target pair before the exact query")
      ->capture_default_str();
  sub->add_option("--seed", o->seed, "Seed of the sampling (answers do not depend on it)")->capture_default_str();
  sub->add_option("--threads", o->threads, "Worker threads: 0 = all cores (default), else 1 .. 1024");
  sub->add_flag("-q,--quiet", o->quiet, "No progress bar on stderr");
  return [o]() { return run_validate(*o); };
});

}  // namespace
