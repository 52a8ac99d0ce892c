#include "events/extremal_line_key.hpp"

#include "kernel/lines_through_four_lines.hpp"
#include "kernel/predicates.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

namespace exactvis {
namespace {

struct KindInfo {
  const char* name;
  int vertices, edges, faces;
};

KindInfo info(ExtremalLineKind k) {
  switch (k) {
    case ExtremalLineKind::VV: return {"VV", 2, 0, 0};
    case ExtremalLineKind::VEE: return {"VEE", 1, 2, 0};
    case ExtremalLineKind::EEEE: return {"EEEE", 0, 4, 0};
    case ExtremalLineKind::FVE: return {"FVE", 1, 1, 1};
    case ExtremalLineKind::FEE: return {"FEE", 0, 2, 1};
    case ExtremalLineKind::VEF: return {"VEF", 1, 1, 1};
    case ExtremalLineKind::EEEF: return {"EEEF", 0, 3, 1};
    case ExtremalLineKind::EEP: return {"EEP", 0, 3, 0};
    case ExtremalLineKind::VEFF: return {"VEFF", 1, 1, 2};
  }
  return {"?", 0, 0, 0};
}

ExtremalLineKey make(ExtremalLineKind kind) {
  ExtremalLineKey k;
  k.kind = kind;
  return k;
}

std::array<RootNumber, 6> normalised(const PluckerLine<RootNumber>& l) {
  std::array<RootNumber, 6> c{l.d.x, l.d.y, l.d.z, l.m.x, l.m.y, l.m.z};
  for (int i = 0; i < 6; ++i) {
    if (CGAL::is_zero(c[i])) continue;
    const RootNumber f = c[i];
    for (int j = i; j < 6; ++j) c[j] = c[j] / f;
    break;
  }
  return c;
}

// Lexicographic comparison of normalised coordinates (exact, also across different roots).
bool lex_less(const std::array<RootNumber, 6>& a, const std::array<RootNumber, 6>& b) {
  for (int i = 0; i < 6; ++i) {
    if (a[i] < b[i]) return true;
    if (b[i] < a[i]) return false;
  }
  return false;
}

}  // namespace

const char* kind_name(ExtremalLineKind kind) { return info(kind).name; }

int ExtremalLineKey::vertex_count() const { return info(kind).vertices; }
int ExtremalLineKey::edge_count() const { return info(kind).edges; }
int ExtremalLineKey::face_count() const { return info(kind).faces; }

std::string to_string(const ExtremalLineKey& key) {
  std::ostringstream s;
  s << kind_name(key.kind) << "(";
  const char* sep = "";
  if (key.vertex_count() > 0) {
    s << "v";
    for (int i = 0; i < key.vertex_count(); ++i) s << " " << key.vertices[i];
    sep = "; ";
  }
  if (key.edge_count() > 0) {
    s << sep << "e";
    for (int i = 0; i < key.edge_count(); ++i) s << " [" << key.edges[i][0] << "," << key.edges[i][1] << "]";
    sep = "; ";
  }
  if (key.face_count() > 0) {
    s << sep << "f";
    for (int i = 0; i < key.face_count(); ++i) s << " " << key.faces[i];
  }
  if (key.kind == ExtremalLineKind::EEEE) s << "; branch " << key.branch;
  s << ")";
  return s.str();
}

ExtremalLineKey vv_key(int a, int b) {
  ExtremalLineKey k = make(ExtremalLineKind::VV);
  k.vertices = {std::min(a, b), std::max(a, b)};
  return k;
}

ExtremalLineKey vee_key(int v, EdgeIds e1, EdgeIds e2) {
  ExtremalLineKey k = make(ExtremalLineKind::VEE);
  k.vertices[0] = v;
  e1 = edge_ids(e1[0], e1[1]);
  e2 = edge_ids(e2[0], e2[1]);
  k.edges[0] = std::min(e1, e2);
  k.edges[1] = std::max(e1, e2);
  return k;
}

ExtremalLineKey fve_key(std::int64_t face, int v, EdgeIds e) {
  ExtremalLineKey k = make(ExtremalLineKind::FVE);
  k.vertices[0] = v;
  k.edges[0] = edge_ids(e[0], e[1]);
  k.faces[0] = face;
  return k;
}

ExtremalLineKey fee_key(std::int64_t face, EdgeIds e1, EdgeIds e2) {
  ExtremalLineKey k = make(ExtremalLineKind::FEE);
  e1 = edge_ids(e1[0], e1[1]);
  e2 = edge_ids(e2[0], e2[1]);
  k.edges[0] = std::min(e1, e2);
  k.edges[1] = std::max(e1, e2);
  k.faces[0] = face;
  return k;
}

ExtremalLineKey vef_key(int v, EdgeIds e, std::int64_t face) {
  ExtremalLineKey k = make(ExtremalLineKind::VEF);
  k.vertices[0] = v;
  k.edges[0] = edge_ids(e[0], e[1]);
  k.faces[0] = face;
  return k;
}

ExtremalLineKey eeef_key(EdgeIds e1, EdgeIds e2, EdgeIds contact_edge, std::int64_t face) {
  ExtremalLineKey k = fee_key(face, e1, e2);
  k.kind = ExtremalLineKind::EEEF;
  k.edges[2] = edge_ids(contact_edge[0], contact_edge[1]);
  return k;
}

ExtremalLineKey eep_key(EdgeIds e1, EdgeIds e2, EdgeIds parallel_edge) {
  ExtremalLineKey k = fee_key(-1, e1, e2);
  k.kind = ExtremalLineKind::EEP;
  k.edges[2] = edge_ids(parallel_edge[0], parallel_edge[1]);
  return k;
}

ExtremalLineKey veff_key(int v, EdgeIds e, std::int64_t f1, std::int64_t f2) {
  ExtremalLineKey k = make(ExtremalLineKind::VEFF);
  k.vertices[0] = v;
  k.edges[0] = edge_ids(e[0], e[1]);
  k.faces = {std::min(f1, f2), std::max(f1, f2)};
  return k;
}

ExtremalLineKey eeee_key(const Scene& scene, const std::array<EdgeIds, 4>& edges, const PluckerLine<RootNumber>& line) {
  ExtremalLineKey k = make(ExtremalLineKind::EEEE);
  for (int i = 0; i < 4; ++i) k.edges[i] = edge_ids(edges[i][0], edges[i][1]);
  std::sort(k.edges.begin(), k.edges.end());
  std::array<PluckerLine<Exact>, 4> lines;
  for (int i = 0; i < 4; ++i)
    lines[i] = line_through(to_rational(scene.vertices[k.edges[i][0]]), to_rational(scene.vertices[k.edges[i][1]]));
  const LinesThroughFourLines t = lines_through_four_lines(lines);
  const auto self = normalised(line);
  int rank = 0;
  for (const auto& other : t.lines)
    if (lex_less(normalised(other), self)) ++rank;
  k.branch = rank;
  return k;
}

}  // namespace exactvis

std::size_t std::hash<exactvis::ExtremalLineKey>::operator()(const exactvis::ExtremalLineKey& k) const noexcept {
  std::size_t h = static_cast<std::size_t>(k.kind);
  auto mix = [&h](std::int64_t x) { h ^= std::hash<std::int64_t>{}(x) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2); };
  for (int v : k.vertices) mix(v);
  for (const auto& e : k.edges) mix(e[0]), mix(e[1]);
  for (std::int64_t f : k.faces) mix(f);
  mix(k.branch);
  return h;
}
