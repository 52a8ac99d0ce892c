// `exactvis generate KIND --triangles N --seed S -o FILE [--json] [-q]`: a deterministic test scene.
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "io/write_mesh.hpp"
#include "kernel/scene_generators.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

namespace {

struct GenerateOptions {
  std::string kind;
  std::int64_t triangles = 1000;
  std::string seed = "1";
  std::string output;
  bool json = false, quiet = false;
};

int run_generate(const GenerateOptions& o) {
  const exactvis::Scene scene = exactvis::generate_scene(o.kind, o.triangles, exactvis::app::parse_uint64(o.seed, "--seed"));
  exactvis::write_scene_mesh(o.output, scene);
  if (o.json) {
    nlohmann::ordered_json j;
    j["file"] = o.output;
    j["kind"] = o.kind;
    j["triangles"] = scene.triangles.size();
    j["objects"] = scene.objects.size();
    std::cout << exactvis::app::json_text(j);
  } else if (!o.quiet) {
    std::cerr << o.output << ": " << scene.triangles.size() << " triangles, " << scene.objects.size() << " objects\n";
  }
  return 0;
}

const exactvis::app::CommandRegistration registration("generate", 20, [](CLI::App& parent) {
  auto opts = std::make_shared<GenerateOptions>();
  CLI::App* sub = parent.add_subcommand("generate", "Write a deterministic scene (random, town, forest, room)");
  sub->add_option("kind", opts->kind, "Scene kind")
      ->required()
      ->check(CLI::IsMember(exactvis::scene_generator_kinds()));
  sub->add_option("--triangles,-n", opts->triangles, "Number of triangles (10 .. 10^7)")
      ->capture_default_str()
      ->check(CLI::Range(std::int64_t{10}, std::int64_t{10'000'000}));
  sub->add_option("--seed,-s", opts->seed, "Random seed (0 .. 2^64-1)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  exactvis::app::add_output_option(*sub, opts->output, "Output file (.obj with a group per object, .off, .ply, .stl)")
      ->required();
  exactvis::app::add_json_flag(*sub, opts->json, "Print {\"file\", \"kind\", \"triangles\", \"objects\"} as JSON on stdout");
  exactvis::app::add_quiet_flag(*sub, opts->quiet, "Nothing on stderr but errors");
  return [opts]() { return run_generate(*opts); };
});

}  // namespace
