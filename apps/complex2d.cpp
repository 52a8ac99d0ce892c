// `exactvis complex2d SCENE2D [--slice z=V] [--json] [--svg out.svg] [--vtp out.vtp]`: the 2D visibility
// complex (free bitangents, edges, faces) of a planar scene (docs/cli.md).
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "apps/common_options.hpp"
#include "api/complex2d.hpp"
#include "io/atomic_file.hpp"
#include "io/scene2d_json.hpp"
#include "io/svg_2d.hpp"
#include "io/vtp_2d.hpp"
#include "skeleton/visibility_complex_2d.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

namespace {

using namespace exactvis;

struct Complex2DOptions {
  std::string scene, slice, svg, vtp;
  bool json = false, quiet = false;
};

int run(const Complex2DOptions& o) {
  OutputFiles outputs({o.svg, o.vtp});  // fails now, not after the work, when an output cannot be created
  const Scene2D scene = load_scene2d(o.scene, o.slice);
  const app::FractionProgress progress("complex2d: sweeps", scene.num_vertices() > 2000 && app::progress_wanted(o.quiet));
  const VisibilityComplex2D cx = visibility_complex(scene, progress.callback());
  const auto& B = cx.graph.bitangents;
  if (o.json) {
    std::cout << app::json_text(api::complex2d_json(scene, cx));
  } else {
    std::cout << "objects " << scene.num_objects << ", vertices " << scene.num_vertices() << "\n"
              << "bitangents " << B.size() << ", edges " << cx.edges.size() << ", faces " << cx.faces.size()
              << ", chains " << cx.chains << "\n"
              << "visibility graph: " << cx.graph.strict_pairs.size() << " free vertex pairs + "
              << cx.graph.ring_edges.size() << " ring edges\n";
    int kinds[2][2] = {{0, 0}, {0, 0}};
    for (const auto& b : B) ++kinds[b.side_a == 'R'][b.side_b == 'R'];
    std::cout << "kinds: LL " << kinds[0][0] << ", LR " << kinds[0][1] << ", RL " << kinds[1][0] << ", RR "
              << kinds[1][1] << "\n";
    if (!cx.gluing_consistent) std::cout << "note: degenerate configuration (collinear bitangents), see docs/theory.md\n";
  }
  auto end_or_far = [&](const SegmentEnd2D& e, const Point2& from, const Point2& through, double far) {
    if (e.kind != SegmentEnd2D::Infinity) return std::array<double, 2>{e.point.ax, e.point.ay};
    const double dx = through.ax - from.ax, dy = through.ay - from.ay;
    const double len = std::max(std::hypot(dx, dy), 1e-300);
    return std::array<double, 2>{through.ax + far * dx / len, through.ay + far * dy / len};
  };
  if (!o.svg.empty()) {
    SvgDocument2D doc = svg_document(scene);
    const double far = 0.05 * std::max(doc.hi_x - doc.lo_x, doc.hi_y - doc.lo_y);
    svg_scene(doc, scene);
    for (const auto& b : B) {
      const Point2 &pa = scene.points[b.a], &pb = scene.points[b.b];
      const std::string colour = b.side_a == b.side_b ? "#1f77b4" : "#d62728";  // outer vs separating
      svg_segment(doc, end_or_far(b.end_a, pb, pa, far), {pa.ax, pa.ay}, colour, 0.6, true);
      svg_segment(doc, {pb.ax, pb.ay}, end_or_far(b.end_b, pa, pb, far), colour, 0.6, true);
      svg_segment(doc, {pa.ax, pa.ay}, {pb.ax, pb.ay}, colour, 1.5);
    }
    using Swatch = SvgLegendEntry::Swatch;
    svg_legend(doc, Swatch::Area, "#9a9a9a", "obstacle");
    svg_legend(doc, Swatch::Line, "#1f77b4", "outer bitangent (free segment)");
    svg_legend(doc, Swatch::Line, "#d62728", "separating bitangent (free segment)");
    svg_legend(doc, Swatch::Dashed, "#1f77b4", "maximal free extension (outer)");
    svg_legend(doc, Swatch::Dashed, "#d62728", "maximal free extension (separating)");
    outputs.write(o.svg, [&](const std::string& temp) { return svg_write(doc, temp), true; });
  }
  if (!o.vtp.empty()) {
    VtpCells2D cells;
    for (int obj = 0; obj < scene.num_objects; ++obj) {
      cells.polygons.emplace_back();
      for (const Ring2D& r : scene.rings) {
        if (r.object != obj) continue;
        cells.polygons.back().emplace_back();
        for (int i = 0; i < r.size; ++i)
          cells.polygons.back().back().push_back({scene.points[r.first + i].ax, scene.points[r.first + i].ay});
      }
      cells.polygon_values.push_back(obj);
    }
    for (const auto& b : B) {  // value: 0 LL, 1 LR, 2 RL, 3 RR
      cells.lines.push_back({{{scene.points[b.a].ax, scene.points[b.a].ay}, {scene.points[b.b].ax, scene.points[b.b].ay}}});
      cells.line_values.push_back(2 * (b.side_a == 'R') + (b.side_b == 'R'));
    }
    outputs.write(o.vtp, [&](const std::string& temp) { return write_vtp_2d(temp, cells), true; });
  }
  outputs.commit();  // all output files appear together, or none
  return 0;
}

const exactvis::app::CommandRegistration registration(
    "complex2d", 200, [](CLI::App& parent) -> std::function<int()> {
      auto opts = std::make_shared<Complex2DOptions>();
      CLI::App* sub = parent.add_subcommand("complex2d", "2D visibility complex: free bitangents, edges, faces");
      sub->add_option("scene", opts->scene, "2D scene JSON ({\"polygons\": ...}), or a 3D mesh with --slice")
          ->required();
      sub->add_option("--slice", opts->slice, "section of a 3D scene by a plane: x=V, y=V or z=V");
      exactvis::app::add_json_flag(*sub, opts->json, "print the complex as JSON on stdout");
      sub->add_option("--svg", opts->svg, "write a picture (objects, bitangents, maximal free segments)");
      sub->add_option("--vtp", opts->vtp, "write objects and bitangents as VTK PolyData");
      exactvis::app::add_quiet_flag(*sub, opts->quiet);
      return [opts] { return run(*opts); };
    });

}  // namespace
