// `exactvis lightcheck SCENE --light SPEC --points points.txt [--json]`: the light-leak certifier. Each point
// is classified exactly as fully lit / partly lit (with the visible fraction of the light) / umbra, with a
// witness (a light point whose open segment to the point meets no scene triangle, re-checked exactly) or a
// proof (the backprojection is empty: the blockers that cover the light). docs/cli.md "lightcheck".
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "io/load_scene.hpp"
#include "kernel/segment_triangle_intersection.hpp"
#include "kernel/triangle_index.hpp"
#include "shadows/backprojection.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace {

using nlohmann::ordered_json;
using exactvis::app::exact_json;

struct LightcheckOptions {
  std::string scene;
  std::vector<std::string> lights;
  std::string points;
  bool json = false, quiet = false;  // quiet: accepted by every subcommand; lightcheck draws no progress
};

// One point per line: three numbers (decimal, or num/den exactly) separated by spaces, tabs or commas; blank
// lines and lines starting with '#' are skipped. Throws "FILE:LINE: problem" / "FILE: problem".
std::vector<exactvis::RationalPoint3> read_points(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open");
  std::vector<exactvis::RationalPoint3> out;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    for (char& c : line)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    std::istringstream ss(line);
    std::vector<std::string> items;
    for (std::string w; ss >> w;) items.push_back(w);
    if (items.empty() || items[0][0] == '#') continue;
    const std::string where = path + ":" + std::to_string(lineno);
    if (items.size() != 3)
      throw std::invalid_argument(where + ": expected 3 coordinates, found " + std::to_string(items.size()));
    exactvis::RationalPoint3 p;
    for (int k = 0; k < 3; ++k) p[k] = exactvis::app::parse_exact(items[k], where);
    out.push_back(p);
  }
  if (in.bad()) throw std::invalid_argument(path + ": read error");
  if (out.empty()) throw std::invalid_argument(path + ": no points");
  return out;
}

int run_lightcheck(const LightcheckOptions& o) {
  exactvis::Scene scene = exactvis::load_scenes({o.scene});
  std::vector<int> light;
  std::set<int> light_set;
  for (const auto& spec : o.lights)
    for (int t : exactvis::app::parse_light(scene, spec).triangles)
      if (light_set.insert(t).second) light.push_back(t);
  const auto points = read_points(o.points);
  const exactvis::TriangleIndex index(scene);
  ordered_json all = ordered_json::array();
  std::uint64_t n_lit = 0, n_part = 0, n_umbra = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    const auto bp = exactvis::shadows::backproject(scene, index, light, p);
    ordered_json j;
    j["point"] = ordered_json::array({exact_json(p.x), exact_json(p.y), exact_json(p.z)});
    const char* status = bp.light_class == exactvis::shadows::LightClass::Lit        ? "fully_lit"
                         : bp.light_class == exactvis::shadows::LightClass::Penumbra ? "partly_lit"
                                                                                     : "umbra";
    j["status"] = status;
    j["light_fraction"] = bp.fraction_value;
    j["light_fraction_exact"] = bp.fraction_exact ? exact_json(bp.fraction) : ordered_json(nullptr);
    if (bp.light_class == exactvis::shadows::LightClass::Umbra) {
      ++n_umbra;
      j["proof"] = {{"backprojection", "empty"}, {"blockers", bp.blockers}};
    } else {
      bp.light_class == exactvis::shadows::LightClass::Lit ? ++n_lit : ++n_part;
      // Witness: a point strictly inside the largest visible piece, re-checked against every triangle.
      const exactvis::shadows::VisibleLightPart* best = nullptr;
      for (const auto& part : bp.parts)
        if (!part.pieces.empty() && (!best || part.visible_area_2d > best->visible_area_2d)) best = &part;
      const exactvis::RationalPoint3 q = exactvis::shadows::interior_point(best->chart, best->pieces.front());
      for (const auto& t : scene.triangles) {
        const auto a = exactvis::to_rational(scene.corner(t, 0)), b = exactvis::to_rational(scene.corner(t, 1)),
                   c = exactvis::to_rational(scene.corner(t, 2));
        if (exactvis::open_segment_meets_closed_triangle(p, q, a, b, c))
          throw std::logic_error("lightcheck: witness segment blocked by triangle " + std::to_string(t.id));
      }
      j["witness"] = {{"light_point", ordered_json::array({exact_json(q.x), exact_json(q.y), exact_json(q.z)})},
                      {"light_triangle", scene.triangles[best->light_triangle].id}};
      if (bp.light_class == exactvis::shadows::LightClass::Penumbra) j["blockers"] = bp.blockers;
    }
    if (o.json) {
      all.push_back(j);
    } else {
      std::cout << i << ": " << status;
      if (bp.light_class == exactvis::shadows::LightClass::Penumbra)
        std::cout << " fraction " << (bp.fraction_exact ? exact_json(bp.fraction).dump() : std::to_string(bp.fraction_value))
                  << " (~" << bp.fraction_value << ")";
      if (j.contains("witness")) std::cout << " witness " << j["witness"]["light_point"].dump();
      else std::cout << " blockers " << j["proof"]["blockers"].dump();
      std::cout << "\n";
    }
  }
  if (o.json) {
    ordered_json out;
    out["points"] = all;
    out["counts"] = {{"points", points.size()}, {"fully_lit", n_lit}, {"partly_lit", n_part}, {"umbra", n_umbra}};
    std::cout << exactvis::app::json_text(out);
  } else {
    std::cout << "points: " << points.size() << " (fully lit " << n_lit << ", partly lit " << n_part << ", umbra "
              << n_umbra << ")\n";
  }
  return 0;
}

const exactvis::app::CommandRegistration registration("lightcheck", 121, [](CLI::App& parent) {
  auto opts = std::make_shared<LightcheckOptions>();
  CLI::App* sub = parent.add_subcommand(
      "lightcheck", "Light-leak certifier: each point fully lit / partly lit / umbra, with a witness or a proof");
  sub->add_option("scene", opts->scene, "Scene file (.obj .ply .off .stl .bsp)")->required();
  sub->add_option("--light", opts->lights,
                  "Area light: a scene object name, or a polygon 'x,y,z;x,y,z;x,y,z' (repeat for several)")
      ->required();
  sub->add_option("--points", opts->points, "Text file: one point 'x y z' per line (decimals or num/den)")
      ->required();
  exactvis::app::add_json_flag(*sub, opts->json);
  exactvis::app::add_quiet_flag(*sub, opts->quiet, exactvis::app::kQuietNoBarHelp);
  return [opts]() { return run_lightcheck(*opts); };
});

}  // namespace
