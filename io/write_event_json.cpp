#include "io/write_event_json.hpp"

#include "io/json_number.hpp"

namespace exactvis {
namespace {

bool is_rational(const RootNumber& x) { return !x.is_extended() || CGAL::is_zero(x.a1()); }

nlohmann::json eee_end_to_json(const Scene& scene, const EeeEvent& ev, const RootNumber& t, const CriticalEnd& end) {
  nlohmann::json j;
  j["t"] = root_number_to_json(t);
  j["t_approx"] = CGAL::to_double(t);
  j["cause"] = cause_name(end.cause);
  if (end.generator >= 0) j["generator"] = end.generator;
  if (end.vertex >= 0) j["vertex"] = end.vertex;
  if (end.triangle >= 0) j["triangle"] = end.triangle;
  if (end.cause == CriticalEnd::Cause::Occluder)
    j["feature"] = {{"kind", feature_name(end.feature.kind)}, {"vertices", end.feature.ids}};
  // The end line exactly (coordinates in the field of t): its point on E1 and that point plus its direction,
  // and its points on the other two generators' lines (null where it is parallel to that line).
  const EeeLinePoints line = eee_line_points(scene, ev, t);
  auto point = [](const Vec3<RootNumber>& p) {
    return nlohmann::json{root_number_to_json(p.x), root_number_to_json(p.y), root_number_to_json(p.z)};
  };
  const Vec3<RootNumber> second(line.on_e1.x + line.direction.x, line.on_e1.y + line.direction.y,
                                line.on_e1.z + line.direction.z);
  j["line"] = {{"through", {point(line.on_e1), point(second)}},
               {"on_generators", {point(line.on_e1), line.on_e2 ? point(*line.on_e2) : nlohmann::json(nullptr),
                                  line.on_e3 ? point(*line.on_e3) : nlohmann::json(nullptr)}}};
  j["key"] = extremal_line_key_to_json(end.line);
  return j;
}

}  // namespace

nlohmann::json extremal_line_key_to_json(const ExtremalLineKey& key) {
  nlohmann::json vertices = nlohmann::json::array(), edges = nlohmann::json::array(), faces = nlohmann::json::array();
  for (int i = 0; i < key.vertex_count(); ++i) vertices.push_back(key.vertices[i]);
  for (int i = 0; i < key.edge_count(); ++i) edges.push_back({key.edges[i][0], key.edges[i][1]});
  for (int i = 0; i < key.face_count(); ++i) faces.push_back(key.faces[i]);
  nlohmann::json j = {{"kind", kind_name(key.kind)}, {"vertices", vertices}, {"edges", edges}, {"faces", faces}};
  if (key.kind == ExtremalLineKind::EEEE) j["branch"] = key.branch;
  return j;
}

nlohmann::json root_number_to_json(const RootNumber& x) {
  if (is_rational(x)) return exact_to_json(x.a0());
  return root_number_to_string(x);
}

nlohmann::json eee_events_to_json(const Scene& scene, const EeeResult& result) {
  nlohmann::json events = nlohmann::json::array();
  auto object_of = [&](std::int64_t id) -> nlohmann::json {
    if (id < 0) return nullptr;
    const auto& t = scene.triangles[scene.index_of_id(id)];
    return {{"triangle", id}, {"object", scene.objects[t.object].name}};
  };
  for (const auto& ev : result.events) {
    nlohmann::json e;
    e["kind"] = "EEE";
    e["edges"] = {{ev.edges[0][0], ev.edges[0][1]}, {ev.edges[1][0], ev.edges[1][1]}, {ev.edges[2][0], ev.edges[2][1]}};
    nlohmann::json iv = nlohmann::json::array(), approx = nlohmann::json::array(), ends = nlohmann::json::array();
    nlohmann::json objects = nlohmann::json::array();
    for (const auto& i : ev.intervals) {
      iv.push_back({root_number_to_json(i.t0), root_number_to_json(i.t1)});
      approx.push_back({CGAL::to_double(i.t0), CGAL::to_double(i.t1)});
      ends.push_back({eee_end_to_json(scene, ev, i.t0, i.end0), eee_end_to_json(scene, ev, i.t1, i.end1)});
      objects.push_back({{"interval", objects.size()},
                         {"t0", root_number_to_json(i.t0)},
                         {"t1", root_number_to_json(i.t1)},
                         {"sample_t", exact_to_json(i.sample_t)},
                         {"front", object_of(i.front_object)},
                         {"back", object_of(i.back_object)}});
    }
    e["intervals"] = iv;
    e["intervals_approx"] = approx;
    e["ends"] = ends;
    e["segment_ends"] = objects;
    events.push_back(std::move(e));
  }
  return events;
}

nlohmann::json event_end_to_json(const Scene& scene, const EvEvent& ev, const RootNumber& t_root, const CriticalEnd& end) {
  const Exact t = rational_parameter(t_root);
  nlohmann::json j;
  j["t"] = exact_to_json(t);
  j["t_approx"] = CGAL::to_double(t);
  j["cause"] = cause_name(end.cause);
  if (end.triangle >= 0) j["triangle"] = end.triangle;
  if (end.cause == CriticalEnd::Cause::Occluder)
    j["feature"] = {{"kind", feature_name(end.feature.kind)}, {"vertices", end.feature.ids}};
  const Point3& v = scene.vertices[ev.vertex];
  const Vec3<Exact> p = ev_edge_point(scene, ev.edge, t);
  j["line"] = {{"through",
                {{v.x, v.y, v.z}, {exact_to_json(p.x), exact_to_json(p.y), exact_to_json(p.z)}}}};
  j["key"] = extremal_line_key_to_json(end.line);
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
    // "intervals" are the free intervals proper (maximal components of the valid set): pieces split where
    // the end objects change are re-joined here, and listed one by one in "segment_ends".
    std::size_t first = 0;
    for (std::size_t k = 0; k < ev.intervals.size(); ++k) {
      const CriticalInterval& i = ev.intervals[k];
      objects.push_back({{"interval", iv.size()},
                         {"t0", root_number_to_json(i.t0)},
                         {"t1", root_number_to_json(i.t1)},
                         {"sample_t", exact_to_json(i.sample_t)},
                         {"beyond_edge", object_of(i.front_object)},
                         {"behind_vertex", object_of(i.back_object)}});
      const bool continues = k + 1 < ev.intervals.size() &&
                             i.end1.cause == CriticalEnd::Cause::EndObjectChange && i.t1 == ev.intervals[k + 1].t0;
      if (continues) continue;
      const CriticalInterval& f = ev.intervals[first];
      iv.push_back({root_number_to_json(f.t0), root_number_to_json(i.t1)});
      approx.push_back({CGAL::to_double(f.t0), CGAL::to_double(i.t1)});
      ends.push_back({event_end_to_json(scene, ev, f.t0, f.end0), event_end_to_json(scene, ev, i.t1, i.end1)});
      first = k + 1;
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
