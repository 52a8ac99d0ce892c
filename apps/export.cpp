// `exactvis export SCENE... -o scene.vtp`: the loaded scene as VTK PolyData with "id" and "object" cell arrays.
#include "apps/command_registry.hpp"
#include "io/load_scene.hpp"
#include "io/write_vtp.hpp"

#include <iostream>

namespace {

struct ExportOptions {
  std::vector<std::string> scenes;
  std::string output;
};

int run_export(const ExportOptions& o) {
  const auto dot = o.output.find_last_of('.');
  if (dot == std::string::npos || o.output.substr(dot) != ".vtp")
    throw std::runtime_error(o.output + ": output must be a .vtp file");
  const exactvis::Scene scene = exactvis::load_scenes(o.scenes);
  exactvis::write_scene_vtp(o.output, scene);
  std::cerr << o.output << ": " << scene.triangles.size() << " triangles\n";
  return 0;
}

const exactvis::app::CommandRegistration registration("export", 30, [](CLI::App& parent) {
  auto opts = std::make_shared<ExportOptions>();
  CLI::App* sub = parent.add_subcommand("export", "Write a scene as VTK PolyData (.vtp) for ParaView");
  sub->add_option("scene", opts->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene")->required();
  sub->add_option("-o,--output", opts->output, "Output .vtp file")->required();
  return [opts]() { return run_export(*opts); };
});

}  // namespace
