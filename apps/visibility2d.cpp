// `exactvis visibility2d SCENE2D --from X,Y [--method complex|sweep] [--slice z=V] [--svg out.svg] [--margin R]`:
// the exact visibility polygon of a point, as JSON (by default answered by a walk in the scene's visibility
// complex; `sweep`: one angular sweep around the point; both give the same polygon); or with --from-segment/--to-segment, segment-to-segment visibility
// with an exact witness (docs/cli.md).
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/scene2d_json.hpp"
#include "io/svg_2d.hpp"
#include "skeleton/complex_segment_visibility_2d.hpp"
#include "skeleton/complex_walk_2d.hpp"
#include "skeleton/segment_visibility_2d.hpp"
#include "skeleton/visibility_polygon_2d.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <stdexcept>

namespace {

using namespace exactvis;

struct Visibility2DOptions {
  std::string scene, slice, from, svg, from_segment, to_segment, method = "complex";
  double margin = 0.5;
  bool json = false, quiet = false;  // JSON is the only output form; no progress is drawn
};

using ojson = nlohmann::ordered_json;  // keeps the documented key order ("counts" first)

using app::exact_json;  // exact values: a JSON number when exactly a double, else "num/den"
using app::point_json;

Point2 parse_point(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) throw std::invalid_argument("--from expects X,Y (got '" + text + "')");
  try {
    return Point2(parse_rational(text.substr(0, comma)), parse_rational(text.substr(comma + 1)));
  } catch (const std::exception&) {
    throw std::invalid_argument("--from expects two numbers X,Y (got '" + text + "')");
  }
}

// "X0,Y0,X1,Y1" -> two points
std::array<Point2, 2> parse_segment(const std::string& text, const std::string& option) {
  const std::vector<std::string> parts = app::split(text, ',');
  if (parts.size() != 4) throw std::invalid_argument(option + " expects X0,Y0,X1,Y1 (got '" + text + "')");
  try {
    return {Point2(parse_rational(parts[0]), parse_rational(parts[1])),
            Point2(parse_rational(parts[2]), parse_rational(parts[3]))};
  } catch (const std::exception&) {
    throw std::invalid_argument(option + " expects four numbers X0,Y0,X1,Y1 (got '" + text + "')");
  }
}

int run_segments(const Visibility2DOptions& o) {
  const auto S = parse_segment(o.from_segment, "--from-segment");
  const auto T = parse_segment(o.to_segment, "--to-segment");
  OutputFiles outputs({o.svg});  // fails now, not after the work, when the output cannot be created
  const Scene2D scene = load_scene2d(o.scene, o.slice);
  SegmentVisibility2D r;
  try {
    if (o.method == "complex") {
      const VisibilityComplex2D cx = visibility_complex(scene);
      const ComplexWalkIndex2D index = complex_walk_index(scene, cx);
      r = segment_visibility_in_complex(index, S[0], S[1], T[0], T[1]);
    } else {
      r = segment_visibility(scene, S[0], S[1], T[0], T[1]);
    }
  } catch (const Scene2DError& e) {  // the viewpoint frame (docs/theory.md §7, "Coordinate range")
    throw InputError(o.scene + ": " + e.what());
  }
  ojson j;
  j["from_segment"] = {point_json(S[0]), point_json(S[1])};
  j["to_segment"] = {point_json(T[0]), point_json(T[1])};
  j["visible"] = r.visible;
  j["witness"] = r.visible ? ojson::array({point_json(r.witness_s), point_json(r.witness_t)}) : ojson();
  j["candidates_tested"] = r.candidates;
  std::cout << app::json_text(j);
  if (!o.svg.empty()) {
    SvgDocument2D doc = svg_document(scene);
    svg_scene(doc, scene);
    svg_segment(doc, {S[0].ax, S[0].ay}, {S[1].ax, S[1].ay}, "#1f77b4", 3);
    svg_segment(doc, {T[0].ax, T[0].ay}, {T[1].ax, T[1].ay}, "#2ca02c", 3);
    if (r.visible)
      svg_segment(doc, {r.witness_s.ax, r.witness_s.ay}, {r.witness_t.ax, r.witness_t.ay}, "#d62728", 1.5);
    svg_legend(doc, SvgLegendEntry::Swatch::Area, "#9a9a9a", "obstacle");
    svg_legend(doc, SvgLegendEntry::Swatch::Line, "#1f77b4", "source segment");
    svg_legend(doc, SvgLegendEntry::Swatch::Line, "#2ca02c", "target segment");
    svg_legend(doc, SvgLegendEntry::Swatch::Line, "#d62728", "witness segment (exactly free)");
    outputs.write(o.svg, [&](const std::string& temp) { return svg_write(doc, temp), true; });
  }
  outputs.commit();
  return 0;
}

int run(const Visibility2DOptions& o) {
  if (!(o.margin >= 0) || !std::isfinite(o.margin)) throw std::invalid_argument("--margin must be a finite number >= 0");
  if (o.method != "complex" && o.method != "sweep")
    throw std::invalid_argument("--method must be complex or sweep (got '" + o.method + "')");
  const bool segments = !o.from_segment.empty() || !o.to_segment.empty();
  if (segments && !o.from.empty()) throw std::invalid_argument("use either --from or --from-segment/--to-segment");
  if (segments && (o.from_segment.empty() || o.to_segment.empty()))
    throw std::invalid_argument("--from-segment and --to-segment go together");
  if (segments) return run_segments(o);
  if (o.from.empty()) throw std::invalid_argument("give --from X,Y (or --from-segment and --to-segment)");
  const Point2 q = parse_point(o.from);
  OutputFiles outputs({o.svg});  // fails now, not after the work, when the output cannot be created
  const Scene2D base = load_scene2d(o.scene, o.slice);
  // the frame must contain q strictly: widen it until it does (frame corners are doubles, docs/theory.md §7)
  Scene2D scene;
  try {
    scene = with_frame_around(base, {q}, o.margin);
  } catch (const Scene2DError& e) {
    throw InputError(o.scene + ": " + e.what());
  }
  if (!frame_contains(scene, q))
    throw std::invalid_argument("--from " + o.from + ": the point lies beyond every viewpoint frame that doubles "
                                "can represent (corners up to about 1.8e308)");
  // both throw std::invalid_argument for q inside an object / on a boundary
  VisibilityPolygon2D vp;
  std::vector<int> seen;
  if (o.method == "complex") {
    const VisibilityComplex2D cx = visibility_complex(base);
    const ComplexWalkIndex2D index = complex_walk_index(base, cx);
    vp = visibility_polygon_in_complex(index, scene, q, nullptr, &seen);
  } else {
    vp = visibility_polygon(scene, q);
    seen = visible_edges(scene, q);
  }
  ojson j;
  j["from"] = point_json(q);
  j["polygon"] = ojson::array();
  for (const Point2& p : vp.vertices) j["polygon"].push_back(point_json(p));
  const Ring2D& fr = scene.rings[scene.frame_ring];
  j["frame"] = {point_json(scene.points[fr.first]), point_json(scene.points[fr.first + 2])};
  j["visible_edges"] = ojson::array();
  for (int e : seen)
    if (scene.ring_of[e] != scene.frame_ring)
      j["visible_edges"].push_back({{"edge", e}, {"object", scene.object_of(e)},
                                    {"a", point_json(scene.points[e])}, {"b", point_json(scene.points[scene.next[e]])}});
  std::cout << app::json_text(j);
  if (!o.svg.empty()) {
    SvgDocument2D doc = svg_document(scene);
    std::vector<std::array<double, 2>> ring;
    for (const Point2& p : vp.vertices) ring.push_back({p.ax, p.ay});
    svg_rings(doc, {ring}, "#ffd54f", "#e6a100", 0.7);
    svg_scene(doc, scene);
    svg_point(doc, {q.ax, q.ay}, "#d62728");
    svg_legend(doc, SvgLegendEntry::Swatch::Area, "#ffd54f", "visibility polygon");
    svg_legend(doc, SvgLegendEntry::Swatch::Area, "#9a9a9a", "obstacle");
    svg_legend(doc, SvgLegendEntry::Swatch::Point, "#d62728", "viewpoint");
    outputs.write(o.svg, [&](const std::string& temp) { return svg_write(doc, temp), true; });
  }
  outputs.commit();
  return 0;
}

const exactvis::app::CommandRegistration registration(
    "visibility2d", 210, [](CLI::App& parent) -> std::function<int()> {
      auto opts = std::make_shared<Visibility2DOptions>();
      CLI::App* sub = parent.add_subcommand("visibility2d", "exact visibility polygon of a point in a 2D scene");
      sub->add_option("scene", opts->scene, "2D scene JSON, or a 3D mesh with --slice")->required();
      sub->add_option("--from", opts->from, "viewpoint X,Y (decimals or num/den, read exactly)");
      sub->add_option("--from-segment", opts->from_segment, "segment S as X0,Y0,X1,Y1: does S see --to-segment?");
      sub->add_option("--to-segment", opts->to_segment, "segment T as X0,Y0,X1,Y1");
      sub->add_option("--slice", opts->slice, "section of a 3D scene by a plane: x=V, y=V or z=V");
      sub->add_option("--method", opts->method,
                      "complex (default): answer from the scene's visibility complex; sweep: one angular sweep "
                      "around the point, or the O(n^4) cell sampling for segments (same answers)");
      sub->add_option("--margin", opts->margin, "frame margin around the scene, relative to its size (default 0.5)");
      sub->add_option("--svg", opts->svg, "write a picture of the visibility polygon");
      exactvis::app::add_quiet_flag(*sub, opts->quiet, exactvis::app::kQuietNoBarHelp);
      exactvis::app::add_json_flag(*sub, opts->json, "The answer as JSON on stdout (the only output form: accepted for uniformity)");
      return [opts] { return run(*opts); };
    });

}  // namespace
