// `exactvis pvs SCENE... (--grid NX,NY,NZ [--box X0,Y0,Z0,X1,Y1,Z1] | --cells cells.json) [--json] [-o FILE]
//  [--jsonl] [--resume] [--no-witnesses] [--vtp DIR] [--png F [--png-cell K] [--png-size WxH] [--witnesses]]
//  [--method exact|sampled|conservative] [--coherence] [--shard K/N] [--threads N] [-q]`:
// the exact potentially visible set of every view cell, with a witness per visible triangle (docs/cli.md).
#include "api/pvs.hpp"
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "apps/pvs_run.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/json_number.hpp"
#include "io/pvs_json.hpp"
#include "io/result_pictures.hpp"
#include "io/view_cells_json.hpp"
#include "io/write_visibility_vtp.hpp"
#include "region/exact_pvs.hpp"
#include "region/pvs_method.hpp"
#include "util/cells_progress.hpp"
#include "util/format_number.hpp"
#include "util/text_table.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

namespace {

using namespace exactvis;
using app::split;
using app::trim;

struct PvsCliOptions {
  std::vector<std::string> scenes;
  std::string grid, box, cells;
  bool json = false, jsonl = false, resume = false, no_witnesses = false, quiet = false, no_hierarchy = false;
  bool coherence = false;
  std::string output, vtp, method = "exact", shard, seed = "1";
  std::string png, png_size = "1280x960";
  std::int64_t png_cell = 0;
  bool witnesses = false;
  int samples = 48, threads = 0;
  std::int64_t rays = -1;  // -1: the method's default (exact: 8 per triangle; sampled: 100000 per cell)
};

app::Shard parse_shard(const std::string& text) {
  const std::string msg = "--shard: need K/N with whole numbers 0 <= K < N";
  const auto parts = split(text, '/');
  if (parts.size() != 2) throw std::invalid_argument(msg);
  const std::uint64_t k = app::parse_uint64(trim(parts[0]), "--shard");
  const std::uint64_t n = app::parse_uint64(trim(parts[1]), "--shard");
  if (n < 1 || k >= n || n > 1'000'000'000) throw std::invalid_argument(msg + " ('" + text + "')");
  return {static_cast<std::int64_t>(k), static_cast<std::int64_t>(n)};
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

void write_cell_vtp(const std::string& dir, const Scene& scene, std::int64_t cell, const region::CellPvs& pvs) {
  std::vector<int> state(scene.triangles.size(), 0);
  std::vector<WitnessSegment> segs;
  auto dbl = [](const RationalPoint3& p) {
    return Point3{CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)};
  };
  for (const auto& v : pvs.visible) {
    state[v.index] = 1;
    if (v.witness) segs.push_back({scene.triangles[v.index].id, dbl(v.witness->p), dbl(v.witness->q)});
  }
  write_visibility_vtp((std::filesystem::path(dir) / ("cell_" + std::to_string(cell) + ".vtp")).string(), scene,
                       state, segs);
}

// The --png picture of one CELL (its JSON, so a cell finished by an earlier --resume run is drawn too):
// visible triangles green, the others hidden (a PVS decides every triangle), the cell's box, and the witnesses
// when asked for and present.
ScenePicture cell_picture(const Scene& scene, const OrderedJson& cell, bool draw_witnesses) {
  std::vector<int> state(scene.triangles.size(), 0);
  for (const auto& id : cell["visible"]) {
    const std::int64_t i = scene.index_of_id(id.get<std::int64_t>());
    if (i >= 0) state[i] = 1;
  }
  auto dbl = [](const nlohmann::ordered_json& v) { return CGAL::to_double(exact_from_json(nlohmann::json(v))); };
  std::vector<WitnessSegment> segs;
  if (draw_witnesses && cell.contains("witnesses"))
    for (const auto& [id, w] : cell["witnesses"].items())
      segs.push_back({std::stoll(id), Point3{dbl(w[0][0]), dbl(w[0][1]), dbl(w[0][2])},
                      Point3{dbl(w[1][0]), dbl(w[1][1]), dbl(w[1][2])}});
  const auto& b = cell["box"];
  const Point3 lo{dbl(b[0]), dbl(b[1]), dbl(b[2])}, hi{dbl(b[3]), dbl(b[4]), dbl(b[5])};
  std::vector<std::vector<Point3>> faces;
  for (const auto& e : box_edges(lo, hi)) faces.push_back({e[0], e[1]});
  const std::int64_t visible = static_cast<std::int64_t>(cell["visible"].size());
  ScenePicture pic = visibility_picture(
      scene, state, segs, faces,
      "exactvis pvs, cell " + format_count(cell["cell"].get<std::int64_t>()) + ": " + format_count(visible) + " of " +
          format_count(static_cast<std::int64_t>(scene.triangles.size())) + " triangles visible");
  return pic;
}

int run_pvs(const PvsCliOptions& o) {
  // ---- options (all checked before any work)
  if (o.grid.empty() == o.cells.empty()) throw std::invalid_argument("give exactly one of --grid and --cells");
  if (!o.box.empty() && o.grid.empty()) throw std::invalid_argument("--box: only with --grid");
  const region::PvsMethod method = [&] {
    try {
      return region::parse_pvs_method(o.method);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--method: ") + e.what());
    }
  }();
  if (o.samples < 0) throw std::invalid_argument("--samples must be >= 0");
  if (o.coherence && method != region::PvsMethod::exact) throw std::invalid_argument("--coherence: only with --method exact");
  if (o.rays < -1) throw std::invalid_argument("--rays must be >= 0");
  region::PvsOptions po;
  po.query.samples = o.samples;
  po.query.seed = app::parse_uint64(o.seed, "--seed");
  po.hierarchy = !o.no_hierarchy;
  if (method == region::PvsMethod::sampled) po.cell_rays = o.rays >= 0 ? o.rays : 100000;
  else if (o.rays > 1000000) throw std::invalid_argument("--rays: at most 1000000 rays per triangle");
  else po.rays = o.rays >= 0 ? static_cast<int>(o.rays) : 8;
  po.threads = app::check_thread_count(o.threads, "--threads");
  const bool sharded = !o.shard.empty();
  const app::Shard shard = sharded ? parse_shard(o.shard) : app::Shard{};
  const bool lines = o.jsonl || ends_with(o.output, ".jsonl");
  if (o.resume && (!lines || o.output.empty()))
    throw std::invalid_argument("--resume: needs the JSON-lines output -o FILE.jsonl (or --jsonl -o FILE)");
  if (o.json && o.jsonl) throw std::invalid_argument("--json and --jsonl: choose one output form");
  const std::array<long, 3> grid = o.grid.empty() ? std::array<long, 3>{} : app::parse_grid(o.grid);
  std::optional<region::RationalBox3> box;
  if (!o.box.empty()) box = app::parse_box(o.box, "--box");

  const std::array<int, 2> png_size = app::parse_png_size(o.png_size);
  if (o.png_cell < 0) throw std::invalid_argument("--png-cell: must be a cell number >= 0");

  app::CellScheduler scheduler;  // MPI_Init here when started by mpirun

  // ---- input
  const Scene scene = load_scenes(o.scenes);
  std::vector<region::RationalBox3> cells;
  if (!o.cells.empty()) {
    cells = read_view_cells(o.cells);
  } else {
    cells = api::grid_view_cells(scene, grid, box);
  }
  const OrderedJson scene_label = o.scenes.size() == 1 ? OrderedJson(o.scenes[0]) : OrderedJson(o.scenes);
  const auto cell_count = static_cast<std::int64_t>(cells.size());
  std::optional<OrderedJson> shard_json;
  if (sharded) shard_json = OrderedJson{{"index", shard.index}, {"count", shard.count}, {"cell_count", cell_count}};
  std::vector<std::int64_t> mine;
  for (std::int64_t c = shard.index; c < cell_count; c += shard.count) mine.push_back(c);
  if (!o.png.empty() && (o.png_cell >= cell_count || (o.png_cell - shard.index) % shard.count != 0))
    throw std::invalid_argument("--png-cell: cell " + std::to_string(o.png_cell) + " is not among the cells of this run (" +
                                std::to_string(cell_count) + " cells" + (sharded ? ", --shard " + o.shard : "") + ")");

  // ---- outputs: the document is staged and committed at the end; JSON lines are appended as cells finish
  const bool with_witnesses = !o.no_witnesses;
  OrderedJson header = pvs_lines_header(scene_label, static_cast<std::int64_t>(scene.triangles.size()), cell_count,
                                        region::pvs_method_name(method), with_witnesses);
  if (shard_json) header["shard"] = *shard_json;
  std::vector<OrderedJson> done_cells;  // CELLs of this shard (finished earlier or now)
  std::vector<char> finished(cells.size(), 0);
  std::unique_ptr<OutputFiles> doc_output;
  std::ofstream lines_out;
  const bool writer = scheduler.writer();
  // The document and the picture appear together (JSON lines are appended as cells finish, not staged).
  if (writer && ((!lines && !o.output.empty()) || !o.png.empty()))
    doc_output = std::make_unique<OutputFiles>(std::vector<std::string>{lines ? std::string() : o.output, o.png});
  if (lines && !o.output.empty()) {  // every rank reads what is finished; only the writer touches the file
    std::uint64_t keep = 0;
    if (o.resume && std::filesystem::exists(o.output)) {
      const PvsLines old = read_pvs_lines(o.output);
      if (old.header != header)
        throw std::invalid_argument(o.output + ": --resume: the file was written by a different run (header " +
                                    old.header.dump() + ", this run " + header.dump() + ")");
      for (const auto& [c, j] : old.cells) {
        if (!j.contains("box") || j["box"] != box_json(cells[c]))
          throw std::invalid_argument(o.output + ": --resume: cell " + std::to_string(c) + " has a different box");
        finished[c] = 1;
        done_cells.push_back(j);
      }
      keep = old.valid_bytes;
    }
    if (!writer) {
    } else if (keep > 0) {
      std::filesystem::resize_file(o.output, keep);  // drops a partial last line
      lines_out.open(o.output, std::ios::app);
    } else {
      lines_out.open(o.output, std::ios::trunc);
      lines_out << header.dump() << "\n" << std::flush;
    }
    if (writer && !lines_out) throw OutputError(o.output + ": cannot write");
  } else if (lines && writer) {
    std::cout << header.dump() << "\n" << std::flush;
  }
  if (!o.vtp.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.vtp, ec);
    if (!std::filesystem::is_directory(o.vtp)) throw OutputError(o.vtp + ": cannot create the --vtp directory");
  }

  std::vector<app::CellJob> todo;
  for (const std::int64_t c : mine)
    if (!finished[c]) todo.push_back({c, cells[c]});

  // ---- the cells
  const region::PvsContext context(scene);
  if (method == region::PvsMethod::conservative && writer && !o.quiet) {
    const region::ExtrudedScene& ex = context.extruded();
    std::cerr << "pvs --method conservative: "
              << (ex.is_25d ? "the scene is 2.5D" : "the scene is not 2.5D (" + ex.reason + "): fallback") << ", "
              << ex.walls.size() << " wall rectangles and " << context.solids().size()
              << " closed convex solids as occluders\n";
  }
  {
    CellsProgress bar("pvs", mine.size(), "triangles", writer && app::progress_wanted(o.quiet));
    for (std::size_t i = 0; i < mine.size() - todo.size(); ++i) bar.finish_item();
    app::PvsRunHooks hooks;
    std::optional<region::CellPvs> previous;  // --coherence: the last cell this process computed
    hooks.compute = [&](const app::CellJob& job) {
      bar.start_item(scene.triangles.size());
      region::PvsOptions cell_options = po;
      cell_options.on_progress = [&bar](std::int64_t d) { bar.item_steps(static_cast<std::uint64_t>(d)); };
      // Coherence only from a neighbour (closed boxes meeting: a shared face, edge or corner).
      const bool neighbour = o.coherence && previous && [&] {
        for (int k = 0; k < 3; ++k)
          if (previous->cell.hi[k] < job.box.lo[k] || job.box.hi[k] < previous->cell.lo[k]) return false;
        return true;
      }();
      region::CellPvs pvs = o.coherence ? region::exact_cell_pvs(context, job.box, cell_options,
                                                                 neighbour ? &*previous : nullptr)
                                        : region::compute_cell_pvs(method, context, job.box, cell_options);
      if (o.coherence && !o.quiet && neighbour)
        std::cerr << "cell " << job.index << ": " << pvs.stats.neighbour_hits << " of " << pvs.stats.neighbour_tries
                  << " triangles accepted through the previous cell's witnesses, " << pvs.stats.exact_queries << " exact queries\n";
      if (method == region::PvsMethod::sampled && !o.quiet)
        std::cerr << "cell " << job.index << ": " << pvs.stats.rays_cast << " rays in " << pvs.stats.seconds << " s ("
                  << (pvs.stats.seconds > 0 ? static_cast<double>(pvs.stats.rays_cast) / pvs.stats.seconds : 0.0)
                  << " rays/s), " << pvs.stats.visible << " triangles confirmed\n";
      if (method == region::PvsMethod::conservative && !o.quiet)
        std::cerr << "cell " << job.index << ": " << pvs.stats.culled << " of " << pvs.stats.triangles
                  << " triangles proved hidden in " << pvs.stats.seconds << " s, " << pvs.stats.visible << " listed\n";
      if (!o.vtp.empty()) write_cell_vtp(o.vtp, scene, job.index, pvs);
      OrderedJson cell_json = pvs_cell_json(scene, job.index, pvs, with_witnesses);
      if (o.coherence) previous = std::move(pvs);
      return cell_json;
    };
    hooks.finished = [&](const OrderedJson& cell) {
      bar.finish_item();
      if (lines) {
        std::ostream& out = o.output.empty() ? std::cout : static_cast<std::ostream&>(lines_out);
        out << cell.dump() << "\n" << std::flush;
        if (!out) throw OutputError((o.output.empty() ? std::string("stdout") : o.output) + ": cannot write");
      }
      done_cells.push_back(cell);
    };
    scheduler.run(todo, hooks);
  }
  if (!writer) return 0;  // an MPI worker rank: rank 0 writes the outputs
  std::sort(done_cells.begin(), done_cells.end(), [](const OrderedJson& a, const OrderedJson& b) {
    return a["cell"].get<std::int64_t>() < b["cell"].get<std::int64_t>();
  });

  // ---- the picture
  if (writer && !o.png.empty()) {
    const auto it = std::find_if(done_cells.begin(), done_cells.end(), [&](const OrderedJson& c) {
      return c["cell"].get<std::int64_t>() == o.png_cell;
    });
    if (it == done_cells.end()) throw OutputError(o.png + ": cell " + std::to_string(o.png_cell) + " was not computed");
    const ScenePicture picture = cell_picture(scene, *it, o.witnesses);
    doc_output->write(o.png, [&](const std::string& temp) { return render_scene_png(temp, picture, png_size[0], png_size[1]); });
  }

  // ---- the text summary (the full result is the JSON)
  std::ostringstream summary;  // printed once the files are in place
  if (!o.json && !(lines && o.output.empty())) {
    std::vector<std::vector<std::string>> rows;
    std::int64_t visible_sum = 0;
    for (const auto& c : done_cells) {
      visible_sum += static_cast<std::int64_t>(c["visible"].size());
      if (rows.size() == kSummaryRows) continue;
      rows.push_back({format_count(c["cell"].get<std::int64_t>()),
                      format_count(static_cast<std::int64_t>(c["visible"].size())),
                      format_count(static_cast<std::int64_t>(c["objects"].size()))});
    }
    const auto n_tri = static_cast<std::int64_t>(scene.triangles.size());
    summary << format_count(static_cast<std::int64_t>(done_cells.size())) << " cells, " << format_count(n_tri)
              << " triangles, " << format_count(static_cast<std::int64_t>(scene.objects.size())) << " objects\n";
    print_table(summary, {"cell", "visible triangles", "visible objects"}, rows,
                static_cast<std::int64_t>(done_cells.size()));
    if (!done_cells.empty())
      summary << "mean PVS: " << format_measure(static_cast<double>(visible_sum) / static_cast<double>(done_cells.size()))
                << " of " << format_count(n_tri) << " triangles\n";
    for (const std::string& f : {o.output, o.png})
      if (!f.empty()) summary << "wrote " << f << "\n";
    if (!o.vtp.empty()) summary << "wrote " << o.vtp << "/cell_<i>.vtp\n";
  }

  // ---- the document
  if (!lines) {
    const OrderedJson doc = pvs_document(scene_label, static_cast<std::int64_t>(scene.triangles.size()),
                                         std::move(done_cells), shard_json);
    if (!o.output.empty()) {
      exactvis::app::write_json_output(*doc_output, o.output, doc);
    } else if (o.json) {
      std::cout << app::json_text(doc);
    }
  }
  if (doc_output) doc_output->commit();
  std::cout << summary.str();
  return 0;
}

const exactvis::app::CommandRegistration registration("pvs", 110, [](CLI::App& parent) {
  auto o = std::make_shared<PvsCliOptions>();
  CLI::App* sub = parent.add_subcommand(
      "pvs",
      "Exact potentially visible sets: for every view cell, the visible triangles and objects, each visible "
      "triangle with an exactly checked witness segment (docs/theory.md section 5; runs under mpirun too)");
  sub->add_option("scene", o->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene")->required();
  sub->add_option("--grid", o->grid, "View cells: an NX,NY,NZ grid over the scene's bounding box (or --box)");
  sub->add_option("--box", o->box, "The box the --grid divides: X0,Y0,Z0,X1,Y1,Z1 (numbers or num/den)");
  sub->add_option("--cells", o->cells, "View cells file {\"cells\": [[x0,y0,z0,x1,y1,z1], ...]}");
  exactvis::app::add_json_flag(*sub, o->json, "The result as one JSON document (on stdout, or in the -o file)");
  sub->add_option("-o,--output", o->output,
                  "Write the result to this file: a JSON document, or JSON lines (one cell per line, written as "
                  "each cell finishes) when the name ends in .jsonl or --jsonl is given");
  sub->add_flag("--jsonl", o->jsonl, "The compact form: JSON lines, a header line then one line per cell");
  sub->add_flag("--resume", o->resume, "With JSON-lines output: keep the cells the file already has, compute the rest");
  sub->add_flag("--no-witnesses", o->no_witnesses, "Leave the witness segments out of the output");
  sub->add_option("--vtp", o->vtp, "Write DIR/cell_<i>.vtp: the scene coloured visible/hidden for each cell");
  sub->add_option("--png", o->png,
                  "Render a picture of one cell (--png-cell; VTK offscreen, starts Xvfb when DISPLAY is unset): the "
                  "scene coloured visible/hidden, the cell as a blue wire box, a legend");
  sub->add_option("--png-cell", o->png_cell, "The cell --png draws (its number in the grid or --cells file)")
      ->capture_default_str();
  sub->add_option("--png-size", o->png_size, "Size of the --png picture in pixels, WxH")->capture_default_str();
  sub->add_flag("--witnesses", o->witnesses, "Draw the cell's witness segments in the --png picture as thin lines");
  sub->add_option("--method", o->method,
                  "PVS method: exact (every triangle decided exactly), sampled (random rays per cell, each hit "
                  "confirmed exactly: never lists a hidden triangle, may miss visible ones) or conservative (leaves "
                  "out only triangles, or hierarchy boxes of them, proved exactly to be hidden by one wall rectangle "
                  "(a merged run of wall pieces), two walls at a corner, a chain of walls or one closed convex solid, "
                  "or as back faces of their own closed convex solid: "
                  "never misses a visible one, lists extra; no witnesses; --rays and --samples unused)")
      ->capture_default_str();
  sub->add_option("--shard", o->shard, "Compute only cells K, K+N, K+2N, ... (job arrays; join with pvs-merge)");
  exactvis::app::add_threads_option(*sub, o->threads);
  exactvis::app::add_samples_option(*sub, o->samples, "Random segments per source/target pair in the exact query");
  sub->add_option("--rays", o->rays,
                  "exact: Embree rays per triangle proposing witnesses (default 8); sampled: random rays per cell "
                  "(default 100000); every hit re-checked exactly");
  sub->add_flag("--coherence", o->coherence,
                "exact: try each visible triangle's witness from the previous neighbouring cell first (re-checked "
                "exactly; same visible sets, witnesses then depend on the order the cells are computed in)");
  sub->add_flag("--no-hierarchy", o->no_hierarchy,
                "exact: decide every triangle on its own (no hidden-box culling; same answers, for comparison)");
  exactvis::app::add_seed_option(*sub, o->seed);
  exactvis::app::add_quiet_flag(*sub, o->quiet);
  return [o]() { return run_pvs(*o); };
});

}  // namespace
