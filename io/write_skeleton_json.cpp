#include "io/write_skeleton_json.hpp"

#include "events/eee_events.hpp"
#include "io/json_number.hpp"
#include "kernel/rational_between.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

namespace exactvis {
namespace {

using ojson = nlohmann::ordered_json;

constexpr ExtremalLineKind kAllKinds[] = {ExtremalLineKind::VV,  ExtremalLineKind::VEE,  ExtremalLineKind::EEEE,
                                          ExtremalLineKind::FVE, ExtremalLineKind::FEE,  ExtremalLineKind::VEF,
                                          ExtremalLineKind::EEEF, ExtremalLineKind::EEP, ExtremalLineKind::VEFF};

ojson number(const RootNumber& x) {
  Exact q;
  if (root_number_rational(x, &q)) return ojson(exact_to_json(q));
  return root_number_to_string(x);
}

ojson point(const Vec3<RootNumber>& p) { return ojson::array({number(p.x), number(p.y), number(p.z)}); }

ojson end_json(const Scene& scene, std::int64_t id) {
  if (id < 0) return nullptr;
  const auto& t = scene.triangles[scene.index_of_id(id)];
  return ojson{{"triangle", id}, {"object", scene.objects[t.object].name}};
}

ojson edge_json(const EdgeIds& e) { return ojson::array({e[0], e[1]}); }

}  // namespace

SkeletonSelection full_selection(const Skeleton3D& skeleton) {
  SkeletonSelection s;
  for (std::size_t i = 0; i < skeleton.nodes.size(); ++i) s.nodes.push_back(static_cast<int>(i));
  for (std::size_t i = 0; i < skeleton.arcs.size(); ++i) s.arcs.push_back(static_cast<int>(i));
  return s;
}

ojson skeleton_to_json(const Scene& scene, const Skeleton3D& sk, const SkeletonSelection& sel) {
  std::map<int, int> node_pos, arc_pos;
  for (std::size_t i = 0; i < sel.nodes.size(); ++i) node_pos[sel.nodes[i]] = static_cast<int>(i);
  for (std::size_t i = 0; i < sel.arcs.size(); ++i) arc_pos[sel.arcs[i]] = static_cast<int>(i);
  ojson node_counts = ojson::object();
  for (ExtremalLineKind k : kAllKinds) node_counts[kind_name(k)] = 0;
  ojson nodes = ojson::array();
  int degenerate = 0;
  for (int ni : sel.nodes) {
    const SkeletonNode& n = sk.nodes[ni];
    const ExtremalLineKey& key = n.key;
    if (n.valid) node_counts[kind_name(key.kind)] = node_counts[kind_name(key.kind)].get<int>() + 1;
    else ++degenerate;
    ojson vertices = ojson::array(), edges = ojson::array(), faces = ojson::array(), arcs = ojson::array();
    for (int i = 0; i < key.vertex_count(); ++i) vertices.push_back(key.vertices[i]);
    for (int i = 0; i < key.edge_count(); ++i) edges.push_back(edge_json(key.edges[i]));
    for (int i = 0; i < key.face_count(); ++i) faces.push_back(key.faces[i]);
    for (int a : n.arcs)
      if (arc_pos.count(a)) arcs.push_back(arc_pos[a]);
    ojson j;
    j["kind"] = kind_name(key.kind);
    j["vertices"] = vertices;
    j["edges"] = edges;
    j["faces"] = faces;
    if (key.kind == ExtremalLineKind::EEEE) j["branch"] = key.branch;
    j["line"] = {{"through", ojson::array({point(n.from), point(n.to)})}};
    j["ends"] = ojson::array({end_json(scene, n.ends[0]), end_json(scene, n.ends[1])});
    j["valid"] = n.valid;
    j["arcs"] = arcs;
    nodes.push_back(std::move(j));
  }
  std::size_t ev = 0, eee = 0;
  ojson arcs = ojson::array();
  for (int ai : sel.arcs) {
    const SkeletonArc& a = sk.arcs[ai];
    ojson j;
    j["kind"] = arc_kind_name(a.kind);
    if (a.kind == SkeletonArcKind::EV) {
      ++ev;
      j["vertex"] = a.vertex;
      j["edge"] = edge_json(a.edges[0]);
    } else {
      ++eee;
      j["edges"] = ojson::array({edge_json(a.edges[0]), edge_json(a.edges[1]), edge_json(a.edges[2])});
    }
    j["t"] = ojson::array({number(a.t0), number(a.t1)});
    j["nodes"] = ojson::array({node_pos.at(a.nodes[0]), node_pos.at(a.nodes[1])});
    j["ends"] = ojson::array({end_json(scene, a.ends[0]), end_json(scene, a.ends[1])});
    arcs.push_back(std::move(j));
  }
  node_counts["degenerate"] = degenerate;
  ojson out;
  out["counts"] = {{"nodes", node_counts}, {"arcs", {{"EV", ev}, {"EEE", eee}}}};
  out["nodes"] = std::move(nodes);
  out["arcs"] = std::move(arcs);
  return out;
}

std::string skeleton_to_text(const Skeleton3D& sk, const SkeletonSelection& sel, double seconds) {
  std::map<ExtremalLineKind, std::size_t> by_kind;
  std::size_t degenerate = 0;
  for (int i : sel.nodes) {
    if (sk.nodes[i].valid) ++by_kind[sk.nodes[i].key.kind];
    else ++degenerate;
  }
  std::size_t ev = 0, eee = 0;
  for (int i : sel.arcs) (sk.arcs[i].kind == SkeletonArcKind::EV ? ev : eee) += 1;
  std::ostringstream os;
  os << "nodes: " << sel.nodes.size() << " (";
  bool first = true;
  for (ExtremalLineKind k : kAllKinds) {
    os << (first ? "" : ", ") << kind_name(k) << " " << by_kind[k];
    first = false;
  }
  os << ", degenerate " << degenerate << ")\narcs: " << sel.arcs.size() << " (EV " << ev << ", EEE " << eee << ")\n";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", seconds);
  os << "time: " << buf << " s\n";
  return os.str();
}

}  // namespace exactvis
