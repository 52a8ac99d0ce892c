#include "api/complex2d.hpp"

#include "io/json_number.hpp"

namespace exactvis::api {
namespace {

using ojson = nlohmann::ordered_json;  // keeps the documented key order ("counts" first)

ojson point_json(const Point2& p) { return ojson::array({ojson(exact_to_json(p.x)), ojson(exact_to_json(p.y))}); }
ojson end_json(const SegmentEnd2D& e) { return e.kind == SegmentEnd2D::Infinity ? ojson() : point_json(e.point); }

}  // namespace

nlohmann::ordered_json complex2d_json(const Scene2D& scene, const VisibilityComplex2D& cx) {
  const auto& B = cx.graph.bitangents;
  ojson j;
  j["counts"] = {{"bitangents", B.size()}, {"edges", cx.edges.size()}, {"faces", cx.faces.size()}};
  j["bitangents"] = ojson::array();
  for (std::size_t i = 0; i < B.size(); ++i) {
    const Bitangent2D& b = B[i];
    j["bitangents"].push_back({{"objects", {b.object_a, b.object_b}},
                               {"kind", b.kind()},
                               {"a", point_json(scene.points[b.a])},
                               {"b", point_json(scene.points[b.b])},
                               {"vertices", {b.a, b.b}},
                               {"segment", {end_json(b.end_a), end_json(b.end_b)}},
                               {"end_objects", {b.end_a.object, b.end_b.object}},
                               {"edges", cx.vertices[i].edges},
                               {"faces", cx.vertices[i].faces}});
  }
  j["edges"] = ojson::array();
  for (const auto& e : cx.edges)
    j["edges"].push_back({{"object", e.object}, {"chain", e.chain}, {"vertices", e.vertices},
                          {"end_objects", e.end_objects}, {"faces", e.faces}, {"degenerate", e.degenerate}});
  j["faces"] = ojson::array();
  for (const auto& f : cx.faces) j["faces"].push_back({{"objects", f.objects}});
  j["visibility_graph"] = {{"vertices", scene.num_vertices()},
                           {"strict_pairs", cx.graph.strict_pairs.size()},
                           {"ring_edges", cx.graph.ring_edges.size()}};
  j["gluing_consistent"] = cx.gluing_consistent;
  return j;
}

}  // namespace exactvis::api
