// `exactvis skeleton SCENE... [--pair A,B] [--json] [-o F] [--vtp F]`: the 3D visibility skeleton (nodes,
// arcs, Durand's table by object pair), exact (docs/cli.md "skeleton", docs/theory.md section 9).
#include "api/skeleton.hpp"
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/write_skeleton_json.hpp"
#include "io/write_skeleton_vtp.hpp"

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

int run(const SkeletonCliOptions& o) {
  OutputFiles outputs({o.output, o.vtp});  // fails now, not after the work, when an output cannot be created
  const Scene scene = load_scenes(o.scenes);
  api::SkeletonRequest request;
  if (!o.pair.empty()) request.pair = api::parse_skeleton_pair(scene, o.pair);
  request.progress_bar = app::progress_wanted(o.quiet);
  const auto start = std::chrono::steady_clock::now();
  // --pair: the lazy build of that pair's slice only (skeleton/skeleton_pair.hpp).
  const Skeleton3D sk = api::skeleton(scene, request);
  const SkeletonSelection sel = full_selection(sk);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string text =
      o.json ? exactvis::app::json_text(api::skeleton_json(scene, sk)) : skeleton_to_text(sk, sel, seconds);
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
  exactvis::app::add_json_flag(*sub, opts->json, "Machine-readable JSON (docs/cli.md) instead of the text summary");
  exactvis::app::add_output_option(*sub, opts->output, "Write the text or JSON to this file instead of stdout");
  sub->add_option("--vtp", opts->vtp, "Write nodes (segments) and arcs (ruled strips) to this .vtp file");
  exactvis::app::add_quiet_flag(*sub, opts->quiet);
  return [opts]() { return run(*opts); };
});

}  // namespace
