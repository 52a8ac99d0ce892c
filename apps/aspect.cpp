// `exactvis aspect SCENE --orthographic | --perspective | --plane z=H [--json] [-o F] [--vtp F] [--png F]`:
// the aspect graph of a 3D model (docs/cli.md, docs/theory.md "Aspect graphs of polyhedra").
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "aspect/convex_aspect_graph.hpp"
#include "aspect/convex_model.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>

namespace {

using namespace exactvis;
using ojson = nlohmann::ordered_json;  // the documented key order

struct AspectOptions {
  std::vector<std::string> scenes;
  bool orthographic = false, perspective = false;
  std::string plane, output, vtp, png;
  bool json = false, quiet = false;
};

std::string scene_label(const std::vector<std::string>& files) {
  std::string s;
  for (const auto& f : files) s += (s.empty() ? "" : ",") + f;
  return s;
}

ojson event_json(const AspectAdjacency3& a) {
  ojson generators = ojson::array();
  std::string type;
  for (const AspectEvent3& e : a.events) {
    if (type.empty()) type = e.type;
    else if (type != e.type) type = "EV+EEE";
    generators.push_back({{"type", e.type}, {"vertex", e.vertex}, {"edge", {e.edge[0], e.edge[1]}},
                          {"triangles", e.triangles}});
  }
  return {{"type", type}, {"generators", generators}};
}

ojson graph_json(const AspectGraph3& g) {
  ojson j;
  j["regions"] = ojson::array();
  for (std::size_t i = 0; i < g.regions.size(); ++i) {
    const AspectRegion3& r = g.regions[i];
    j["regions"].push_back({{"id", i},
                            {"dimension", r.dimension},
                            {"aspect", r.aspect},
                            {"sample", {app::exact_json(r.sample.x), app::exact_json(r.sample.y),
                                        app::exact_json(r.sample.z)}}});
  }
  j["adjacency"] = ojson::array();
  for (const AspectAdjacency3& a : g.adjacency) j["adjacency"].push_back({a.a, a.b, event_json(a)});
  j["counts"] = {{"regions", g.regions.size()}, {"edges", g.adjacency.size()}};
  return j;
}

std::string summary(const AspectGraph3& g, std::size_t planes) {
  const bool ortho = g.view == ViewModel::Orthographic;
  std::array<std::size_t, 4> per_dim{0, 0, 0, 0};
  for (const auto& r : g.regions) ++per_dim[r.dimension];
  std::string s = std::string(ortho ? "orthographic" : "perspective") + " aspect graph of a convex model with " +
                  std::to_string(planes) + " face planes: " + std::to_string(g.regions.size()) + " regions (";
  for (int d = ortho ? 2 : 3; d >= 0; --d)
    s += std::to_string(per_dim[d]) + " of dimension " + std::to_string(d) + (d ? ", " : "");
  s += "), " + std::to_string(g.adjacency.size()) + " adjacencies; ";
  s += ortho ? "sphere cells " + std::to_string(g.cells[0]) + " vertices, " + std::to_string(g.cells[1]) + " arcs, " +
                   std::to_string(g.cells[2]) + " faces"
             : "cells outside the model " + std::to_string(g.cells[0]) + " vertices, " + std::to_string(g.cells[1]) +
                   " edges, " + std::to_string(g.cells[2]) + " faces, " + std::to_string(g.cells[3]) + " volumes";
  return s;
}

int run(const AspectOptions& o) {
  const int views = int(o.orthographic) + int(o.perspective) + int(!o.plane.empty());
  if (views != 1) throw std::invalid_argument("--orthographic, --perspective or --plane z=H: give exactly one");
  if (!o.plane.empty()) {
    const std::string p = app::trim(o.plane);
    if (p.size() < 3 || p.compare(0, 2, "z=") != 0) throw std::invalid_argument("--plane: '" + o.plane + "' is not z=H");
    app::parse_exact(p.substr(2), "--plane");
    throw std::invalid_argument("--plane: the partition of a plane of viewpoints is not implemented yet");
  }
  if (!o.vtp.empty()) throw std::invalid_argument("--vtp: not implemented yet for aspect");
  if (!o.png.empty()) throw std::invalid_argument("--png: not implemented yet for aspect");
  OutputFiles outputs({o.output});
  const Scene scene = load_scenes(o.scenes);
  const std::string label = scene_label(o.scenes);
  const ConvexModel model = convex_model(scene);
  if (!model.convex) {
    if (o.perspective)
      throw InputError(label + ": not a closed convex model (" + model.problem +
                       "); --perspective takes convex models only: use --plane z=H for perspective viewpoints on a "
                       "plane");
    throw InputError(label + ": not a closed convex model (" + model.problem +
                     "); the orthographic aspect graph of non-convex models is not implemented yet");
  }
  const AspectGraph3 g =
      convex_aspect_graph(scene, model, o.orthographic ? ViewModel::Orthographic : ViewModel::Perspective);
  const ojson j = graph_json(g);
  if (!o.output.empty())
    outputs.write(o.output, [&](const std::string& temp) {
      std::ofstream out(temp);
      out << j.dump(1) << "\n";
      return static_cast<bool>(out);
    });
  outputs.commit();
  if (o.json) std::cout << j.dump(1) << "\n";
  else std::cout << summary(g, model.planes.size()) << "\n";
  return 0;
}

const exactvis::app::CommandRegistration registration(
    "aspect", 230, [](CLI::App& parent) -> std::function<int()> {
      auto opts = std::make_shared<AspectOptions>();
      CLI::App* sub = parent.add_subcommand(
          "aspect", "exact aspect graph of a 3D model: regions of viewpoints with one set of visible triangles");
      sub->add_option("scene", opts->scenes, "Scene files (.obj .ply .off .stl), loaded as one scene")->required();
      auto* ort = sub->add_flag("--orthographic", opts->orthographic, "viewpoints are directions (the viewing sphere)");
      auto* per = sub->add_flag("--perspective", opts->perspective,
                                "viewpoints are points outside the model (convex models only)");
      auto* pla = sub->add_option("--plane", opts->plane, "viewpoints on the plane z=H (not implemented yet)");
      ort->excludes(per)->excludes(pla);
      per->excludes(pla);
      sub->add_flag("--json", opts->json, "print regions, aspects, adjacency and counts as JSON on stdout");
      sub->add_option("-o,--output", opts->output, "write the JSON to this file");
      sub->add_option("--vtp", opts->vtp, "write the partition as VTK PolyData (not implemented yet)");
      sub->add_option("--png", opts->png, "render the partition and views (not implemented yet)");
      sub->add_flag("-q,--quiet", opts->quiet, "no progress bar on stderr");
      return [opts] { return run(*opts); };
    });

}  // namespace
