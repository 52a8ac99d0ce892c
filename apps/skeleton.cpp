// `exactvis skeleton SCENE... [--pair A,B] [--json] [-o F] [--vtp F]`: the 3D visibility skeleton (nodes,
// arcs, Durand's table by object pair), exact (docs/cli.md "skeleton", docs/theory.md section 9).
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/write_skeleton_json.hpp"
#include "io/write_skeleton_vtp.hpp"
#include "skeleton/skeleton_pair.hpp"
#include "skeleton/visibility_skeleton_3d.hpp"

#include <chrono>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace {

using namespace exactvis;

struct SkeletonCliOptions {
  std::vector<std::string> scenes;
  std::string pair, output, vtp;
  bool json = false, quiet = false;
};

// One side of --pair: an object's exact name, else a stable triangle id (a whole number that is one).
SkeletonPairSide parse_pair_side(const Scene& scene, const std::string& text, const std::string& spec) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].name == text) return {static_cast<int>(i), -1};
  bool digits = !text.empty() && text.size() <= 18;
  for (char c : text) digits = digits && c >= '0' && c <= '9';
  if (digits) {
    const std::int64_t id = std::stoll(text);
    if (scene.index_of_id(id) >= 0) return {-1, id};
  }
  throw std::invalid_argument("--pair '" + spec + "': '" + text + "' is neither an object name nor a triangle id of the scene");
}

int run(const SkeletonCliOptions& o) {
  OutputFiles outputs({o.output, o.vtp});  // fails now, not after the work, when an output cannot be created
  const Scene scene = load_scenes(o.scenes);
  std::optional<std::pair<SkeletonPairSide, SkeletonPairSide>> pair;
  if (!o.pair.empty()) {
    const auto items = app::split(o.pair, ',');
    if (items.size() != 2 || items[0].empty() || items[1].empty())
      throw std::invalid_argument("--pair '" + o.pair + "': expected two objects A,B (object names or triangle ids)");
    pair.emplace(parse_pair_side(scene, items[0], o.pair), parse_pair_side(scene, items[1], o.pair));
  }
  const auto start = std::chrono::steady_clock::now();
  SkeletonOptions opt;
  opt.progress = app::progress_wanted(o.quiet);
  // --pair: the lazy build of that pair's slice only (skeleton/skeleton_pair.hpp).
  const Skeleton3D sk = pair ? build_pair_skeleton(scene, pair->first, pair->second, opt) : build_skeleton_3d(scene, opt);
  const SkeletonSelection sel = full_selection(sk);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string text = o.json ? skeleton_to_json(scene, sk, sel).dump(2) + "\n" : skeleton_to_text(sk, sel, seconds);
  if (!o.vtp.empty()) outputs.write(o.vtp, [&](const std::string& temp) {
    write_skeleton_vtp(temp, scene, sk, sel);
    return true;
  });
  if (!o.output.empty()) {
    outputs.write(o.output, [&](const std::string& temp) {
      std::ofstream f(temp, std::ios::binary);
      f << text;
      return static_cast<bool>(f.flush());
    });
    outputs.commit();
  } else {
    outputs.commit();
    std::cout << text;
  }
  return 0;
}

const app::CommandRegistration registration("skeleton", 115, [](CLI::App& parent) {
  auto opts = std::make_shared<SkeletonCliOptions>();
  CLI::App* sub = parent.add_subcommand(
      "skeleton", "The 3D visibility skeleton: extremal stabbing lines (nodes) and EV/EEE arcs between them, exact");
  sub->add_option("scene", opts->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene")->required();
  sub->add_option("--pair", opts->pair,
                  "Only the nodes and arcs whose maximal free segments end on A and B (object names, or "
                  "triangle ids), with the end nodes of those arcs");
  sub->add_flag("--json", opts->json, "Machine-readable JSON (docs/cli.md) instead of the text summary");
  sub->add_option("-o,--output", opts->output, "Write the text or JSON to this file instead of stdout");
  sub->add_option("--vtp", opts->vtp, "Write nodes (segments) and arcs (ruled strips) to this .vtp file");
  sub->add_flag("-q,--quiet", opts->quiet, "No progress bar on stderr");
  return [opts]() { return run(*opts); };
});

}  // namespace
