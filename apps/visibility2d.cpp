// `exactvis visibility2d SCENE2D --from X,Y [--slice z=V] [--svg out.svg] [--margin R]`: the exact
// visibility polygon of a point, as JSON (docs/cli.md).
#include "apps/command_registry.hpp"
#include "io/scene2d_json.hpp"
#include "io/svg_2d.hpp"
#include "skeleton/visibility_polygon_2d.hpp"

#include <nlohmann/json.hpp>

#include <iostream>
#include <stdexcept>

namespace {

using namespace exactvis;

struct Visibility2DOptions {
  std::string scene, slice, from, svg;
  double margin = 0.5;
};

using ojson = nlohmann::ordered_json;  // keeps the documented key order ("counts" first)

// An exact value: a JSON number when it is exactly a double, else the string "num/den".
ojson exact_json(const Exact& x) {
  double d = 0;
  if (exact_double(x, &d)) return d;
  return to_rational_string(x);
}
ojson point_json(const Point2& p) { return ojson::array({exact_json(p.x), exact_json(p.y)}); }

Point2 parse_point(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) throw std::invalid_argument("--from expects X,Y (got '" + text + "')");
  try {
    return Point2(parse_rational(text.substr(0, comma)), parse_rational(text.substr(comma + 1)));
  } catch (const std::exception&) {
    throw std::invalid_argument("--from expects two numbers X,Y (got '" + text + "')");
  }
}

int run(const Visibility2DOptions& o) {
  if (!(o.margin >= 0)) throw std::invalid_argument("--margin must be >= 0");
  const Point2 q = parse_point(o.from);
  const Scene2D base = load_scene2d(o.scene, o.slice);
  // the frame must contain q strictly: widen it until it does
  double margin = o.margin;
  Scene2D scene = with_frame(base, margin);
  for (int k = 0; k < 64; ++k) {
    const Ring2D& fr = scene.rings[scene.frame_ring];
    const Point2 &lo = scene.points[fr.first], &hi = scene.points[fr.first + 2];
    if (lo.x < q.x && q.x < hi.x && lo.y < q.y && q.y < hi.y) break;
    margin = 2 * margin + 1;
    scene = with_frame(base, margin);
  }
  const VisibilityPolygon2D vp = visibility_polygon(scene, q);  // throws for q inside an object / on a boundary
  ojson j;
  j["from"] = point_json(q);
  j["polygon"] = ojson::array();
  for (const Point2& p : vp.vertices) j["polygon"].push_back(point_json(p));
  const Ring2D& fr = scene.rings[scene.frame_ring];
  j["frame"] = {point_json(scene.points[fr.first]), point_json(scene.points[fr.first + 2])};
  j["visible_edges"] = ojson::array();
  for (int e : visible_edges(scene, q))
    if (scene.ring_of[e] != scene.frame_ring)
      j["visible_edges"].push_back({{"edge", e}, {"object", scene.object_of(e)},
                                    {"a", point_json(scene.points[e])}, {"b", point_json(scene.points[scene.next[e]])}});
  std::cout << j.dump(1) << "\n";
  if (!o.svg.empty()) {
    SvgDocument2D doc = svg_document(scene);
    std::vector<std::array<double, 2>> ring;
    for (const Point2& p : vp.vertices) ring.push_back({p.ax, p.ay});
    svg_rings(doc, {ring}, "#ffd54f", "#e6a100", 0.7);
    svg_scene(doc, scene);
    svg_point(doc, {q.ax, q.ay}, "#d62728");
    svg_write(doc, o.svg);
  }
  return 0;
}

const exactvis::app::CommandRegistration registration(
    "visibility2d", 210, [](CLI::App& parent) -> std::function<int()> {
      auto opts = std::make_shared<Visibility2DOptions>();
      CLI::App* sub = parent.add_subcommand("visibility2d", "exact visibility polygon of a point in a 2D scene");
      sub->add_option("scene", opts->scene, "2D scene JSON, or a 3D mesh with --slice")->required();
      sub->add_option("--from", opts->from, "viewpoint X,Y (decimals or num/den, read exactly)")->required();
      sub->add_option("--slice", opts->slice, "section of a 3D scene by a plane: x=V, y=V or z=V");
      sub->add_option("--margin", opts->margin, "frame margin around the scene, relative to its size (default 0.5)");
      sub->add_option("--svg", opts->svg, "write a picture of the visibility polygon");
      return [opts] { return run(*opts); };
    });

}  // namespace
