// `exactvis validate SCENE... --cells cells.json --pvs other.json [--json] [-o report.json] [--vtp DIR]`:
// checks another tool's PVS exactly (issue #12): per cell the false visible triangles (listed, exactly
// hidden) and the false invisible ones (missing, visible, each with a witness), the exact and reported sizes.
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/quake3_bsp.hpp"
#include "io/quake3_cluster_visibility.hpp"
#include "io/reported_pvs.hpp"
#include "io/view_cells_json.hpp"
#include "io/write_pvs_check_vtp.hpp"
#include "region/pvs_check.hpp"
#include "util/progress_bar.hpp"

#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <random>
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
  // Quake 3 maps
  std::string bsp;
  std::int64_t pairs = -1;  // -1: not given
  std::string clusters;
  std::string occluders = "leaves";
  std::string obj;
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
  region::PvsOptions co;
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

  const region::PvsContext context(scene);
  std::vector<region::PvsCheck> checks;
  {
    const std::uint64_t n = scene.triangles.size();
    ProgressBar bar("validate", cells.size() * n, app::progress_wanted(o.quiet));
    for (std::size_t k = 0; k < cells.size(); ++k) {
      co.on_progress = [&bar, k, n](std::int64_t decided) { bar.set_done(k * n + static_cast<std::uint64_t>(decided)); };
      checks.push_back(region::check_reported_pvs(context, cells[k], reported[k], co));
    }
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
    std::vector<WitnessSegment> segs;
    for (std::size_t i = 0; i < c.false_invisible.size(); ++i)
      segs.push_back({scene.triangles[static_cast<std::size_t>(c.false_invisible[i])].id,
                      rounded(c.false_invisible_witness[i].p), rounded(c.false_invisible_witness[i].q)});
    outputs.write(vtp_paths[k], [&](const std::string& temp) {
      write_pvs_check_vtp(temp, scene, status, segs, cells[k]);
      return true;
    });
  }
  if (!o.output.empty())
    exactvis::app::write_json_output(outputs, o.output, j);
  outputs.commit();

  if (o.json) {
    std::cout << exactvis::app::json_text(j);
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

// The ordered cluster pairs to check: --clusters (all ordered pairs of the listed clusters), or --pairs N
// sampled with the seed among the pairs of non-empty clusters, the pairs the map marks invisible first.
std::vector<std::pair<int, int>> chosen_pairs(const ValidateOptions& o, const quake3::BspMap& map,
                                              const quake3::ClusterVisibilityChecker& checker, std::uint64_t seed,
                                              std::int64_t* eligible) {
  const int n = checker.cluster_count();
  std::vector<std::pair<int, int>> out;
  if (!o.clusters.empty()) {
    std::vector<int> list;
    for (const auto& part : app::split(o.clusters, ',')) {
      const std::string t = app::trim(part);
      std::size_t used = 0;
      long long c = -1;
      try {
        c = std::stoll(t, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (t.empty() || used != t.size() || c < 0 || c >= n)
        throw std::invalid_argument("--clusters: '" + t + "' is not a cluster of the map (0 .. " + std::to_string(n - 1) + ")");
      if (std::find(list.begin(), list.end(), static_cast<int>(c)) == list.end()) list.push_back(static_cast<int>(c));
    }
    if (list.size() < 2) throw std::invalid_argument("--clusters: give at least two different clusters");
    for (const int a : list)
      for (const int b : list)
        if (a != b) out.emplace_back(a, b);
    *eligible = static_cast<std::int64_t>(n) * (n - 1);
    return out;
  }
  const std::int64_t want = o.pairs < 0 ? 100 : o.pairs;
  std::vector<std::pair<int, int>> hidden, shown;
  for (int a = 0; a < n; ++a) {
    if (checker.region_empty(a)) continue;
    for (int b = 0; b < n; ++b)
      if (b != a && !checker.region_empty(b)) (map.cluster_visible(a, b) ? shown : hidden).emplace_back(a, b);
  }
  *eligible = static_cast<std::int64_t>(hidden.size() + shown.size());
  std::mt19937_64 rng(seed);
  std::shuffle(hidden.begin(), hidden.end(), rng);
  std::shuffle(shown.begin(), shown.end(), rng);
  for (auto* list : {&hidden, &shown})
    for (const auto& p : *list) {
      if (static_cast<std::int64_t>(out.size()) >= want) return out;
      out.push_back(p);
    }
  return out;
}

int run_validate_bsp(const ValidateOptions& o) {
  if (!o.scenes.empty() || !o.cells.empty() || !o.pvs.empty() || !o.vtp.empty())
    throw std::invalid_argument("--bsp: give no SCENE, --cells, --pvs or --vtp with a map");
  if (o.pairs >= 0 && !o.clusters.empty()) throw std::invalid_argument("--pairs: give either --pairs or --clusters");
  if (o.pairs == 0) throw std::invalid_argument("--pairs: must be at least 1");
  if (o.samples < 0) throw std::invalid_argument("--samples must be >= 0");
  quake3::Occluders occluders;
  if (o.occluders == "leaves") occluders = quake3::Occluders::Leaves;
  else if (o.occluders == "brushes") occluders = quake3::Occluders::Brushes;
  else throw std::invalid_argument("--occluders: '" + o.occluders + "' is not leaves or brushes");
  region::VisibilityOptions vo;
  vo.samples = o.samples;
  vo.seed = app::parse_uint64(o.seed, "--seed");
  const int threads = app::check_thread_count(o.threads, "--threads");

  const quake3::BspMap map = quake3::read_bsp(o.bsp);
  OutputFiles outputs({o.output, o.obj});
  const quake3::ClusterVisibilityChecker checker(map, occluders);
  std::int64_t eligible = 0;
  const std::vector<std::pair<int, int>> pairs = chosen_pairs(o, map, checker, vo.seed, &eligible);

  std::vector<quake3::ClusterVisibility> results(pairs.size());
  {
    ProgressBar bar("validate --bsp", pairs.size(), app::progress_wanted(o.quiet));
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    arena.execute([&] {
      tbb::parallel_for(std::size_t(0), pairs.size(), [&](std::size_t i) {
        results[i] = checker.check(pairs[i].first, pairs[i].second, vo);
        bar.advance();
      });
    });
  }

  ordered_json j;
  j["map"] = map.source;
  j["clusters"] = checker.cluster_count();
  j["occluders"] = quake3::occluders_name(occluders);
  j["pairs"] = ordered_json::array();
  std::int64_t false_invisible = 0, false_visible = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const bool vis = map.cluster_visible(pairs[i].first, pairs[i].second);
    const quake3::ClusterVisibility& r = results[i];
    ordered_json e;
    e["from"] = pairs[i].first;
    e["to"] = pairs[i].second;
    e["visdata"] = vis;
    e["exact"] = r.visible;
    e["witness"] = r.witness ? ordered_json::array({rational_point_json(r.witness->p), rational_point_json(r.witness->q)})
                             : ordered_json(nullptr);
    j["pairs"].push_back(e);
    false_invisible += (r.visible && !vis) ? 1 : 0;
    false_visible += (!r.visible && vis) ? 1 : 0;
  }
  j["totals"] = {{"pairs", pairs.size()}, {"false_invisible", false_invisible}, {"false_visible", false_visible}};

  if (!o.output.empty())
    exactvis::app::write_json_output(outputs, o.output, j);
  if (!o.obj.empty())
    outputs.write(o.obj, [&](const std::string& temp) {
      quake3::write_opaque_obj(temp, map, occluders);
      return true;
    });
  outputs.commit();

  if (o.json) {
    std::cout << exactvis::app::json_text(j);
  } else {
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const bool vis = map.cluster_visible(pairs[i].first, pairs[i].second);
      if (vis == results[i].visible) continue;
      std::cout << "cluster " << pairs[i].first << " -> " << pairs[i].second << ": "
                << (results[i].visible ? "false invisible (visdata hides it, exactly visible)"
                                       : "false visible (visdata shows it, exactly hidden)")
                << "\n";
    }
    std::cout << map.source << ": " << checker.cluster_count() << " clusters, occluders "
              << quake3::occluders_name(occluders) << "; checked " << pairs.size() << " of " << eligible
              << " ordered pairs (" << (eligible > 0 ? 100.0 * static_cast<double>(pairs.size()) / static_cast<double>(eligible) : 0.0)
              << "%): false invisible " << false_invisible << ", false visible " << false_visible << "\n";
  }
  return 0;
}

int run_validate_any(const ValidateOptions& o) {
  if (!o.bsp.empty()) return run_validate_bsp(o);
  if (o.pairs >= 0 || !o.clusters.empty() || !o.obj.empty() || o.occluders != "leaves")
    throw std::invalid_argument("--pairs, --clusters, --occluders and --obj need --bsp MAP");
  if (o.scenes.empty()) throw std::invalid_argument("give SCENE... --cells --pvs, or --bsp MAP");
  return run_validate(o);
}

const exactvis::app::CommandRegistration registration("validate", 110, [](CLI::App& parent) {
  auto o = std::make_shared<ValidateOptions>();
  CLI::App* sub = parent.add_subcommand(
      "validate",
      "Check another tool's PVS exactly: per view cell the false visible triangles (listed, exactly hidden) and "
      "the false invisible ones (missing, visible, with a witness segment each); or with --bsp a Quake 3 map's "
      "visdata, cluster pair by cluster pair");
  sub->add_option("scene", o->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene");
  sub->add_option("--cells", o->cells, "View cells file {\"cells\": [[x0,y0,z0,x1,y1,z1], ...]}");
  sub->add_option("--pvs", o->pvs,
                  "The PVS to check: exactvis pvs JSON (or its JSON lines), or text lines 'cell_index: id id ...'");
  exactvis::app::add_json_flag(*sub, o->json, "Print the JSON report on stdout (instead of the summary)");
  exactvis::app::add_output_option(*sub, o->output, "Write the JSON report to this file");
  sub->add_option("--vtp", o->vtp, "Write DIR/cell_K.vtp per cell: the scene coloured by status, with the cell box");
  sub->add_option("--bsp", o->bsp, "Quake 3 map (.bsp, ARCHIVE.pk3:MEMBER or a .pk3 with one map): check its visdata");
  sub->add_option("--pairs", o->pairs,
                  "With --bsp: check N ordered cluster pairs sampled with --seed, those the map marks invisible first "
                  "(default 100)");
  sub->add_option("--clusters", o->clusters, "With --bsp: check every ordered pair of these clusters A,B,...");
  sub->add_option("--occluders", o->occluders,
                  "With --bsp: leaves (the compiled solid space, default) or brushes (the world model's solid brushes, detail brushes included)")
      ->capture_default_str();
  sub->add_option("--obj", o->obj, "With --bsp: write the map's opaque geometry as OBJ");
  exactvis::app::add_samples_option(*sub, o->samples);
  exactvis::app::add_seed_option(*sub, o->seed, "Seed of the sampling and of --pairs (answers do not depend on it)");
  exactvis::app::add_threads_option(*sub, o->threads);
  exactvis::app::add_quiet_flag(*sub, o->quiet);
  return [o]() { return run_validate_any(*o); };
});

}  // namespace
