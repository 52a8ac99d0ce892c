// `exactvis info SCENE... [--json]`: statistics of a scene (after loading, as every other subcommand sees it).
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "io/load_scene.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

namespace {

struct InfoOptions {
  std::vector<std::string> scenes;
  bool json = false, quiet = false;  // quiet: accepted by every subcommand; info draws no progress
};

int run_info(const InfoOptions& o) {
  const exactvis::Scene scene = exactvis::load_scenes(o.scenes);
  const exactvis::Box3 box = exactvis::bounding_box(scene);
  if (o.json) {
    nlohmann::json j;
    j["files"] = o.scenes;
    j["triangles"] = scene.triangles.size();
    j["objects"] = scene.objects.size();
    j["vertices"] = scene.vertices.size();
    j["faces_read"] = scene.faces_read;  // triangles after fan triangulation, before dropping
    j["degenerate_dropped"] = scene.degenerate_dropped;
    if (!scene.triangles.empty())  // bounds are input doubles, hence exact in JSON
      j["bounding_box"] = {{"min", {box.lo.x, box.lo.y, box.lo.z}}, {"max", {box.hi.x, box.hi.y, box.hi.z}}};
    else
      j["bounding_box"] = nullptr;
    std::cout << exactvis::app::json_text(j);
  } else {
    std::cout << "triangles:          " << scene.triangles.size() << "\n"
              << "objects:            " << scene.objects.size() << "\n"
              << "vertices:           " << scene.vertices.size() << "\n"
              << "faces read:         " << scene.faces_read << " triangles\n"
              << "degenerate dropped: " << scene.degenerate_dropped << "\n";
    if (!scene.triangles.empty())
      std::cout.precision(17),
          std::cout << "bounding box:       [" << box.lo.x << ", " << box.hi.x << "] x [" << box.lo.y << ", "
                    << box.hi.y << "] x [" << box.lo.z << ", " << box.hi.z << "]\n";
  }
  return 0;
}

const exactvis::app::CommandRegistration registration("info", 10, [](CLI::App& parent) {
  auto opts = std::make_shared<InfoOptions>();
  CLI::App* sub = parent.add_subcommand("info", "Print scene statistics (triangles, objects, bounding box, ...)");
  sub->add_option("scene", opts->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene")->required();
  exactvis::app::add_json_flag(*sub, opts->json);
  exactvis::app::add_quiet_flag(*sub, opts->quiet, exactvis::app::kQuietNoBarHelp);
  return [opts]() { return run_info(*opts); };
});

}  // namespace
