#include "api/shadows.hpp"

#include "events/eee_events.hpp"
#include "io/json_number.hpp"
#include "util/text_split.hpp"

#include <set>
#include <stdexcept>

namespace exactvis::api {

namespace {

using nlohmann::ordered_json;

ordered_json exact_json(const Exact& x) { return ordered_json(exact_to_json(x)); }

ordered_json point3_json(const Vec3<Exact>& p) {
  return ordered_json::array({exact_json(p.x), exact_json(p.y), exact_json(p.z)});
}
ordered_json double3_json(const Point3& p) { return ordered_json::array({p.x, p.y, p.z}); }

ordered_json curve_json(const Scene& scene, const shadows::DiscontinuityCurve& c) {
  using Kind = shadows::DiscontinuityCurve::Kind;
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
    g["light"] = c.blocker_blocker ? "none" : "edge";
  }
  j["generators"] = g;
  if (c.ends_exact)
    j["ends"] = {point3_json(c.points.front()), point3_json(c.points.back())};
  else
    j["ends"] = {double3_json(c.ends[0]), double3_json(c.ends[1])};
  j["ends_exact"] = c.ends_exact;
  if (c.order != 0) j["t"] = {root_number_to_string(c.t0), root_number_to_string(c.t1)};
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

ordered_json visible_json(const Scene& scene, const std::vector<shadows::VisibleLightPart>& parts) {
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

}  // namespace

std::vector<std::int64_t> parse_receivers(const Scene& scene, const std::string& text, const std::vector<int>& light_list) {
  const std::set<int> light(light_list.begin(), light_list.end());
  std::vector<std::int64_t> out;
  if (trim(text) == "all") return out;
  const auto items = split(text, ',');
  if (items.empty()) throw std::invalid_argument("--receivers: expected 'all' or comma-separated triangle ids");
  std::set<std::int64_t> seen;
  for (const auto& item : items) {
    const std::string t = trim(item);
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

shadows::ShadowResult shadows(const Scene& scene, const shadows::ShadowOptions& options) {
  return shadows::compute_shadows(scene, options);
}

ShadowCounts shadow_counts(const shadows::ShadowResult& res) {
  ShadowCounts n;
  n.receivers = res.receivers.size();
  for (const auto& r : res.receivers) {
    for (const auto& c : r.curves) {
      if (c.order == 0) ++n.d0;
      else if (c.kind == shadows::DiscontinuityCurve::Kind::EV) ++n.ev;
      else ++n.eee;
    }
    for (const auto& f : r.faces) {
      ++n.faces;
      if (f.light_class == shadows::LightClass::Umbra) ++n.umbra;
      else if (f.light_class == shadows::LightClass::Penumbra) ++n.penumbra;
      else ++n.lit;
    }
  }
  n.curves = n.ev + n.eee + n.d0;
  return n;
}

ordered_json shadows_json(const Scene& scene, const shadows::ShadowResult& res, const std::vector<int>& light) {
  ordered_json recv = ordered_json::array();
  for (const auto& r : res.receivers) {
    ordered_json rj;
    rj["triangle"] = scene.triangles[r.triangle].id;
    rj["curves"] = ordered_json::array();
    for (const auto& c : r.curves) rj["curves"].push_back(curve_json(scene, c));
    rj["faces"] = ordered_json::array();
    for (const auto& f : r.faces) {
      ordered_json fj;
      fj["class"] = shadows::light_class_name(f.light_class);
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
    recv.push_back(rj);
  }
  const ShadowCounts n = shadow_counts(res);
  ordered_json j;
  j["receivers"] = recv;
  j["counts"] = {{"receivers", n.receivers}, {"curves", n.curves}, {"EV", n.ev},       {"EEE", n.eee},
                 {"D0", n.d0},               {"faces", n.faces},   {"umbra", n.umbra}, {"penumbra", n.penumbra},
                 {"lit", n.lit}};
  ordered_json lt = ordered_json::array();
  for (int t : light) lt.push_back(scene.triangles[t].id);
  j["light"] = {{"triangles", lt}};
  j["stats"] = {{"ev_events", res.stats.ev_events},
                {"eee_events", res.stats.eee_events},
                {"blocker_ev_events", res.stats.blocker_ev_events},
                {"blocker_eee_events", res.stats.blocker_eee_events},
                {"backprojections", res.stats.backprojections},
                {"conic_arcs", res.stats.conic_arcs},
                {"chord_curves", res.stats.chord_curves},
                {"arrangement_failures", res.stats.arrangement_failures},
                {"trimmed_arcs", res.stats.trimmed_arcs},
                {"polyline_arrangements", res.stats.polyline_arrangements},
                {"polyline_pieces", res.stats.polyline_pieces},
                {"uncertified_samples", res.stats.uncertified_samples},
                {"shaft_box_candidates", res.stats.shaft_box_candidates},
                {"shaft_candidates", res.stats.shaft_candidates},
                {"shaft_outside_points", res.stats.shaft_outside_points},
                {"seconds_ev", res.stats.seconds_ev},
                {"seconds_eee", res.stats.seconds_eee},
                {"seconds_blocker_ev", res.stats.seconds_blocker_ev},
                {"seconds_blocker_eee", res.stats.seconds_blocker_eee},
                {"seconds_events", res.stats.seconds_events},
                {"seconds_receivers", res.stats.seconds_receivers}};
  return j;
}

}  // namespace exactvis::api
