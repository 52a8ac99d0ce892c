// `exactvis shadows SCENE --light SPEC [--receivers all|IDS] [-o mesh.vtp] [--ply F] [--json] [--png F]`:
// the exact discontinuity mesh of area lights on receiver triangles (docs/cli.md "shadows", definitions in
// docs/theory.md section 11).
#include "apps/cli_util.hpp"
#include "apps/command_registry.hpp"
#include "events/eee_events.hpp"
#include "io/atomic_file.hpp"
#include "io/load_scene.hpp"
#include "io/render_png.hpp"
#include "io/write_shadow_mesh.hpp"
#include "shadows/shadow_mesh.hpp"

#include <nlohmann/json.hpp>

#include <iostream>
#include <set>
#include <stdexcept>

namespace {

using nlohmann::ordered_json;
using exactvis::app::exact_json;

struct ShadowsCliOptions {
  std::string scene;
  std::vector<std::string> lights;
  std::string receivers = "all";
  std::string vtp, ply, png;
  bool json = false;
  bool no_progress = false;
};

ordered_json point3_json(const exactvis::Vec3<exactvis::Exact>& p) {
  return ordered_json::array({exact_json(p.x), exact_json(p.y), exact_json(p.z)});
}
ordered_json double3_json(const exactvis::Point3& p) { return ordered_json::array({p.x, p.y, p.z}); }

ordered_json curve_json(const exactvis::Scene& scene, const exactvis::shadows::DiscontinuityCurve& c) {
  using Kind = exactvis::shadows::DiscontinuityCurve::Kind;
  ordered_json j;
  j["kind"] = c.kind == Kind::EV ? "EV" : "EEE";
  j["order"] = c.order;
  ordered_json g;
  if (c.order == 0) {
    g["blocker_triangle"] = c.blocker;
  } else if (c.kind == Kind::EV) {
    g["vertex"] = c.vertex;
    g["edge"] = {c.edge[0], c.edge[1]};
    g["light"] = c.blocker_blocker ? "none" : c.light_vertex ? "vertex" : "edge";
  } else {
    g["edges"] = ordered_json::array();
    for (const auto& e : c.edges) g["edges"].push_back({e[0], e[1]});
    g["light_edge"] = c.light_edge;
  }
  j["generators"] = g;
  if (c.ends_exact)
    j["ends"] = {point3_json(c.points.front()), point3_json(c.points.back())};
  else
    j["ends"] = {double3_json(c.ends[0]), double3_json(c.ends[1])};
  j["ends_exact"] = c.ends_exact;
  if (c.order != 0) j["t"] = {exactvis::root_number_to_string(c.t0), exactvis::root_number_to_string(c.t1)};
  if (c.kind == Kind::EEE) {
    ordered_json pts = ordered_json::array();
    for (const auto& p : c.points) pts.push_back(point3_json(p));
    j["points"] = pts;
    ordered_json co = ordered_json::array();
    for (const auto& x : c.conic) co.push_back(exact_json(x));
    j["conic"] = {{"frame", "receiver (u, v): X = corner0 + u (corner1 - corner0) + v (corner2 - corner0)"},
                  {"coefficients", co}};
  }
  return j;
}

ordered_json visible_json(const exactvis::Scene& scene, const std::vector<exactvis::shadows::VisibleLightPart>& parts) {
  ordered_json out = ordered_json::array();
  for (const auto& part : parts)
    for (const auto& piece : part.pieces) {
      ordered_json p;
      p["light_triangle"] = scene.triangles[part.light_triangle].id;
      p["outer"] = ordered_json::array();
      for (const auto& v : piece.outer) p["outer"].push_back(point3_json(v));
      p["holes"] = ordered_json::array();
      for (const auto& h : piece.holes) {
        ordered_json hj = ordered_json::array();
        for (const auto& v : h) hj.push_back(point3_json(v));
        p["holes"].push_back(hj);
      }
      out.push_back(p);
    }
  return out;
}

std::vector<std::int64_t> parse_receivers(const exactvis::Scene& scene, const std::string& text,
                                          const std::set<int>& light) {
  std::vector<std::int64_t> out;
  if (exactvis::app::trim(text) == "all") return out;
  const auto items = exactvis::app::split(text, ',');
  if (items.empty()) throw std::invalid_argument("--receivers: expected 'all' or comma-separated triangle ids");
  std::set<std::int64_t> seen;
  for (const auto& item : items) {
    const std::string t = exactvis::app::trim(item);
    std::int64_t id = -1;
    std::size_t used = 0;
    try {
      id = std::stoll(t, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (t.empty() || used != t.size() || id < 0)
      throw std::invalid_argument("--receivers: '" + item + "' is not a triangle id");
    const std::int64_t index = scene.index_of_id(id);
    if (index < 0) throw std::invalid_argument("--receivers: the scene has no triangle " + t);
    if (light.count(static_cast<int>(index)))
      throw std::invalid_argument("--receivers: triangle " + t + " is part of the light");
    if (seen.insert(index).second) out.push_back(index);
  }
  return out;
}

int run_shadows(const ShadowsCliOptions& o) {
  exactvis::OutputFiles outputs({o.vtp, o.ply, o.png});
  exactvis::Scene scene = exactvis::load_scenes({o.scene});
  exactvis::shadows::ShadowOptions opt;
  std::set<int> light;
  for (const auto& spec : o.lights) {
    const exactvis::LightSource ls = exactvis::app::parse_light(scene, spec);
    for (int t : ls.triangles)
      if (light.insert(t).second) opt.light.push_back(t);
  }
  opt.receivers = parse_receivers(scene, o.receivers, light);
  if (opt.receivers.empty() && light.size() == scene.triangles.size())
    throw std::invalid_argument(o.scene + ": no receiver triangles (every triangle is part of the light)");
  opt.progress = exactvis::app::progress_wanted(o.no_progress);
  opt.vertex_irradiance = !o.vtp.empty() || !o.ply.empty() || !o.png.empty();
  const exactvis::shadows::ShadowResult res = exactvis::shadows::compute_shadows(scene, opt);
  if (!o.vtp.empty())
    outputs.write(o.vtp, [&](const std::string& tmp) { return exactvis::write_shadow_mesh_vtp(tmp, scene, res); });
  if (!o.ply.empty())
    outputs.write(o.ply, [&](const std::string& tmp) { return exactvis::write_shadow_mesh_ply(tmp, scene, res); });
  if (!o.png.empty())
    outputs.write(o.png, [&](const std::string& tmp) {
      return exactvis::render_shadows_png(tmp, scene, res, opt.light);
    });
  outputs.commit();

  std::uint64_t n_ev = 0, n_eee = 0, n_d0 = 0, n_faces = 0, n_umbra = 0, n_pen = 0, n_lit = 0;
  ordered_json recv = ordered_json::array();
  for (const auto& r : res.receivers) {
    ordered_json rj;
    rj["triangle"] = scene.triangles[r.triangle].id;
    rj["curves"] = ordered_json::array();
    for (const auto& c : r.curves) {
      if (c.order == 0) ++n_d0;
      else if (c.kind == exactvis::shadows::DiscontinuityCurve::Kind::EV) ++n_ev;
      else ++n_eee;
      if (o.json) rj["curves"].push_back(curve_json(scene, c));
    }
    rj["faces"] = ordered_json::array();
    for (const auto& f : r.faces) {
      ++n_faces;
      if (f.light_class == exactvis::shadows::LightClass::Umbra) ++n_umbra;
      else if (f.light_class == exactvis::shadows::LightClass::Penumbra) ++n_pen;
      else ++n_lit;
      if (!o.json) continue;
      ordered_json fj;
      fj["class"] = exactvis::shadows::light_class_name(f.light_class);
      fj["area"] = f.area;
      fj["sample"] = point3_json(f.sample);
      fj["light_fraction"] = f.fraction_value;
      fj["irradiance"] = f.irradiance;
      fj["light_fraction_exact"] = f.fraction_exact ? exact_json(f.fraction) : ordered_json(nullptr);
      fj["area_uv"] = f.area_exact ? exact_json(f.area_uv) : ordered_json(f.area_uv_value);
      fj["area_exact"] = f.area_exact;
      fj["conic_bounded"] = f.conic_bounded;
      fj["blockers"] = f.blockers;
      fj["backprojection"] = visible_json(scene, f.visible);
      rj["faces"].push_back(fj);
    }
    if (o.json) recv.push_back(rj);
  }
  if (o.json) {
    ordered_json j;
    j["receivers"] = recv;
    j["counts"] = {{"receivers", res.receivers.size()}, {"curves", n_ev + n_eee + n_d0}, {"EV", n_ev},
                   {"EEE", n_eee},  {"D0", n_d0}, {"faces", n_faces}, {"umbra", n_umbra},
                   {"penumbra", n_pen}, {"lit", n_lit}};
    ordered_json lt = ordered_json::array();
    for (int t : opt.light) lt.push_back(scene.triangles[t].id);
    j["light"] = {{"triangles", lt}};
    j["stats"] = {{"ev_events", res.stats.ev_events},
                  {"eee_events", res.stats.eee_events},
                  {"blocker_ev_events", res.stats.blocker_ev_events},
                  {"backprojections", res.stats.backprojections},
                  {"conic_arcs", res.stats.conic_arcs},
                  {"chord_curves", res.stats.chord_curves},
                  {"arrangement_failures", res.stats.arrangement_failures},
                  {"trimmed_arcs", res.stats.trimmed_arcs},
                  {"uncertified_samples", res.stats.uncertified_samples},
                  {"seconds_ev", res.stats.seconds_ev},
                  {"seconds_eee", res.stats.seconds_eee},
                  {"seconds_blocker_ev", res.stats.seconds_blocker_ev},
                  {"seconds_events", res.stats.seconds_events},
                  {"seconds_receivers", res.stats.seconds_receivers}};
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << "receivers: " << res.receivers.size() << "\n"
            << "curves: " << n_ev + n_eee + n_d0 << " (EV " << n_ev << ", EEE " << n_eee << ", D0 " << n_d0 << ")\n"
            << "faces: " << n_faces << " (umbra " << n_umbra << ", penumbra " << n_pen << ", lit " << n_lit << ")\n"
            << "events: EV " << res.stats.ev_events << ", EEE " << res.stats.eee_events
            << "; backprojections: " << res.stats.backprojections << "\n";
  return 0;
}

const exactvis::app::CommandRegistration registration("shadows", 120, [](CLI::App& parent) {
  auto opts = std::make_shared<ShadowsCliOptions>();
  CLI::App* sub = parent.add_subcommand(
      "shadows", "Exact discontinuity mesh of area lights: shadow curves, umbra/penumbra/lit faces, irradiance");
  sub->add_option("scene", opts->scene, "Scene file (.obj .ply .off .stl .bsp)")->required();
  sub->add_option("--light", opts->lights,
                  "Area light: a scene object name, or a polygon 'x,y,z;x,y,z;x,y,z' appended to the scene "
                  "(repeat for several lights)")
      ->required();
  sub->add_option("--receivers", opts->receivers,
                  "'all' (every triangle not part of a light) or comma-separated scene triangle ids")
      ->capture_default_str();
  sub->add_option("-o,--vtp", opts->vtp, "Write the conforming mesh (.vtp: irradiance per vertex, class per cell)");
  sub->add_option("--ply", opts->ply, "Write the conforming mesh as ASCII .ply");
  sub->add_option("--png", opts->png, "Render the lit scene to a PNG (VTK offscreen; starts Xvfb when DISPLAY is unset)");
  sub->add_flag("--json", opts->json, "Machine-readable JSON on stdout");
  sub->add_flag("-q,--quiet,--no-progress", opts->no_progress, "No progress bar on stderr");
  return [opts]() { return run_shadows(*opts); };
});

}  // namespace
