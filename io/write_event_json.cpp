#include "io/write_event_json.hpp"

#include "io/json_number.hpp"

namespace exactvis {
namespace {

const char* cause_name(EventEnd::Cause c) {
  switch (c) {
    case EventEnd::Cause::EdgeEndpoint: return "edge_endpoint";
    case EventEnd::Cause::Occluder: return "occluder";
    case EventEnd::Cause::Tangency: return "tangency";
  }
  return "?";
}

const char* feature_name(OccluderFeature::Kind k) {
  switch (k) {
    case OccluderFeature::Kind::Vertex: return "vertex";
    case OccluderFeature::Kind::Edge: return "edge";
    case OccluderFeature::Kind::Face: return "face";
    case OccluderFeature::Kind::WedgeSide: return "wedge_side";
  }
  return "?";
}

}  // namespace

nlohmann::json event_end_to_json(const Scene& scene, const EvEvent& ev, const Exact& t, const EventEnd& end) {
  nlohmann::json j;
  j["t"] = exact_to_json(t);
  j["t_approx"] = CGAL::to_double(t);
  j["cause"] = cause_name(end.cause);
  if (end.triangle >= 0) j["triangle"] = end.triangle;
  if (end.cause == EventEnd::Cause::Occluder)
    j["feature"] = {{"kind", feature_name(end.feature.kind)}, {"vertices", end.feature.ids}};
  const Point3& v = scene.vertices[ev.vertex];
  const Vec3<Exact> p = ev_edge_point(scene, ev.edge, t);
  j["line"] = {{"through",
                {{v.x, v.y, v.z}, {exact_to_json(p.x), exact_to_json(p.y), exact_to_json(p.z)}}}};
  return j;
}

nlohmann::json ev_events_to_json(const Scene& scene, const EvResult& result) {
  nlohmann::json events = nlohmann::json::array();
  for (const auto& ev : result.events) {
    nlohmann::json e;
    e["kind"] = "EV";
    e["vertex"] = ev.vertex;
    e["edge"] = {ev.edge[0], ev.edge[1]};
    nlohmann::json iv = nlohmann::json::array(), approx = nlohmann::json::array(), ends = nlohmann::json::array();
    nlohmann::json objects = nlohmann::json::array();
    auto object_of = [&](std::int64_t id) -> nlohmann::json {
      if (id < 0) return nullptr;
      const auto& t = scene.triangles[scene.index_of_id(id)];
      return {{"triangle", id}, {"object", scene.objects[t.object].name}};
    };
    for (const auto& i : ev.intervals) {
      objects.push_back({{"sample_t", exact_to_json(i.sample_t)},
                         {"beyond_edge", object_of(i.beyond_edge)},
                         {"behind_vertex", object_of(i.behind_vertex)}});
      iv.push_back({exact_to_json(i.t0), exact_to_json(i.t1)});
      approx.push_back({CGAL::to_double(i.t0), CGAL::to_double(i.t1)});
      ends.push_back({event_end_to_json(scene, ev, i.t0, i.end0), event_end_to_json(scene, ev, i.t1, i.end1)});
    }
    e["intervals"] = iv;
    e["intervals_approx"] = approx;
    e["ends"] = ends;
    e["segment_ends"] = objects;
    events.push_back(std::move(e));
  }
  nlohmann::json j;
  j["counts"] = {{"EV", result.events.size()}};
  j["events"] = std::move(events);
  j["stats"] = {{"ev_pairs", result.stats.pairs},
                {"ev_tangent_pairs", result.stats.tangent_pairs},
                {"occluder_tests", result.stats.occluder_tests}};
  return j;
}

}  // namespace exactvis
