// `exactvis export SCENE... (-o scene.vtp | --png scene.png) [--png-size WxH] [--json] [-q]`: the loaded scene
// as VTK PolyData with "id" and "object" cell arrays, and/or a picture of it coloured by object.
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/result_pictures.hpp"
#include "io/write_vtp.hpp"
#include "util/format_number.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

namespace {

struct ExportOptions {
  std::vector<std::string> scenes;
  std::string output, png, png_size = "1280x960";
  bool json = false, quiet = false;
};

int run_export(const ExportOptions& o) {
  if (o.output.empty() && o.png.empty()) throw std::invalid_argument("give -o FILE.vtp, --png FILE.png or both");
  if (!o.output.empty()) {
    const auto dot = o.output.find_last_of('.');
    if (dot == std::string::npos || o.output.substr(dot) != ".vtp")
      throw std::runtime_error(o.output + ": output must be a .vtp file");
  }
  const std::array<int, 2> png_size = exactvis::app::parse_png_size(o.png_size);
  exactvis::OutputFiles outputs({o.output, o.png});
  const exactvis::Scene scene = exactvis::load_scenes(o.scenes);
  if (!o.output.empty())
    outputs.write(o.output, [&](const std::string& temp) { return exactvis::write_scene_vtp(temp, scene), true; });
  if (!o.png.empty()) {
    const exactvis::ScenePicture picture = exactvis::scene_picture(
        scene, "exactvis export: " + exactvis::format_count(static_cast<std::int64_t>(scene.triangles.size())) +
                   " triangles, " + exactvis::format_count(static_cast<std::int64_t>(scene.objects.size())) +
                   " objects");
    outputs.write(o.png, [&](const std::string& temp) {
      return exactvis::render_scene_png(temp, picture, png_size[0], png_size[1]);
    });
  }
  outputs.commit();
  if (o.json) {
    nlohmann::ordered_json j;
    j["triangles"] = scene.triangles.size();
    j["objects"] = scene.objects.size();
    j["files"] = nlohmann::ordered_json::object();
    if (!o.output.empty()) j["files"]["vtp"] = o.output;
    if (!o.png.empty()) j["files"]["png"] = o.png;
    std::cout << exactvis::app::json_text(j);
  } else {
    // The summary went to stderr before pictures existed; it stays there (scripts read stdout as empty).
    for (const std::string& f : {o.output, o.png})
      if (!f.empty() && !o.quiet)
        std::cerr << f << ": " << exactvis::format_count(static_cast<std::int64_t>(scene.triangles.size()))
                  << " triangles\n";
  }
  return 0;
}

const exactvis::app::CommandRegistration registration("export", 30, [](CLI::App& parent) {
  auto opts = std::make_shared<ExportOptions>();
  CLI::App* sub = parent.add_subcommand("export", "Write a scene as VTK PolyData (.vtp) for ParaView, or as a picture");
  sub->add_option("scene", opts->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene")->required();
  exactvis::app::add_output_option(*sub, opts->output, "Output .vtp file");
  sub->add_option("--png", opts->png,
                  "Render a picture of the scene, coloured by object (VTK offscreen; starts Xvfb when DISPLAY is "
                  "unset)");
  sub->add_option("--png-size", opts->png_size, "Size of the --png picture in pixels, WxH")->capture_default_str();
  exactvis::app::add_json_flag(*sub, opts->json, "Print {\"triangles\", \"objects\", \"files\"} as JSON on stdout");
  exactvis::app::add_quiet_flag(*sub, opts->quiet, "Nothing on stderr but errors");
  return [opts]() { return run_export(*opts); };
});

}  // namespace
