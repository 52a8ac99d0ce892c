#include "skeleton/node_validity.hpp"

#include "events/tangency.hpp"
#include "kernel/rational_between.hpp"
#include "skeleton/line_first_hit.hpp"

#include <algorithm>

namespace exactvis {
namespace {

using R = RootNumber;

Vec3<R> lift(const Point3& p) { return {R(Exact(p.x)), R(Exact(p.y)), R(Exact(p.z))}; }

bool has_corner(const SceneTriangle& t, int v) { return t.v[0] == v || t.v[1] == v || t.v[2] == v; }

// Edge rule for the plane spanned by a line with direction d that meets the edge e's line at a finite
// point x: the plane through x, x + d and e has normal (b - a) x (x + d - a) = (b - a) x d, as x - a is a
// multiple of b - a, so the rule needs only d (no meeting point, no division).
bool edge_rule(const Scene& scene, const SceneAdjacency& adj, const EdgeIds& e, const Vec3<R>& d) {
  const int ei = adj.edge_index(e[0], e[1]);
  if (ei < 0) return false;
  const Vec3<R> a = lift(scene.vertices[e[0]]), b = lift(scene.vertices[e[1]]);
  const Vec3<R> n = cross(b - a, d);
  int side = 0;
  for (int ti : adj.edges[ei].triangles) {
    const SceneTriangle& t = scene.triangles[ti];
    int w = t.v[0];
    for (int c : t.v)
      if (c != e[0] && c != e[1]) w = c;
    const int s = CGAL::sign(dot(n, lift(scene.vertices[w]) - a));
    if (s == 0 || (side != 0 && s != side)) return false;
    side = s;
  }
  return true;
}

bool in_plane_of(const Scene& scene, std::int64_t face, const Vec3<R>& x, const Vec3<R>& d) {
  const std::int64_t i = scene.index_of_id(face);
  if (i < 0) return false;
  const SceneTriangle& t = scene.triangles[i];
  const Vec3<R> a = lift(scene.corner(t, 0));
  const Vec3<R> n = cross(lift(scene.corner(t, 1)) - a, lift(scene.corner(t, 2)) - a);
  return CGAL::is_zero(dot(n, d)) && CGAL::is_zero(dot(n, x - a));
}

}  // namespace

bool is_zero_root(const RootNumber& x) {
  // a0 = a1 = 0 is zero whatever the root (no interval needed); otherwise CGAL's filtered exact sign.
  if (CGAL::is_zero(x.a0()) && (!x.is_extended() || CGAL::is_zero(x.a1()))) return true;
  return CGAL::is_zero(x);
}

bool is_zero_vector(const Vec3<RootNumber>& v) { return is_zero_root(v.x) && is_zero_root(v.y) && is_zero_root(v.z); }

std::optional<RootNumber> edge_meeting_parameter(const Vec3<RootNumber>& o, const Vec3<RootNumber>& d,
                                                 const Vec3<RootNumber>& a, const Vec3<RootNumber>& b) {
  // (a - o + u w) x d = g + u c with w = b - a, g = (a - o) x d, c = w x d: where the lines meet, g = -u c,
  // so u = -g_k / c_k on any axis with c_k != 0 (one component: 4 products instead of the 18 of a
  // least-squares formula; the lines are parallel iff c = 0).
  const Vec3<R> w = b - a;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const R c = w[i] * d[j] - w[j] * d[i];
    if (is_zero_root(c)) continue;
    const R ai = a[i] - o[i], aj = a[j] - o[j];
    return (aj * d[i] - ai * d[j]) / c;  // -g_k / c_k
  }
  return std::nullopt;
}

bool node_line_valid(const Scene& scene, const SceneAdjacency& adj, const TriangleIndex& index,
                     const SkeletonNode& node, const Vec3<RootNumber>& dir) {
  const ExtremalLineKey& k = node.key;
  const bool face_kind = k.kind == ExtremalLineKind::FVE || k.kind == ExtremalLineKind::FEE;
  if (!face_kind && k.kind != ExtremalLineKind::VV && k.kind != ExtremalLineKind::VEE &&
      k.kind != ExtremalLineKind::EEEE)
    return true;  // contact kinds: valid by definition (header)
  if (is_zero_vector(dir)) return false;
  const Vec3<R>& o = node.from;
  // Vertex generators: on the line (true by construction; checked), vertex rule unless a face kind.
  for (int i = 0; i < k.vertex_count(); ++i) {
    const int v = k.vertices[i];
    if (!is_zero_vector(cross(lift(scene.vertices[v]) - o, dir))) return false;
    if (face_kind) continue;
    Vec3<Exact> d;
    if (!rational_vector(dir, &d)) return false;  // lines through a vertex are rational
    const VertexFan fan = build_vertex_fan(scene, adj, v);
    const Vec3<Exact> ex{1, 0, 0}, ey{0, 1, 0};
    const Vec3<Exact> cx = cross(d, ex);
    const bool parallel_x = CGAL::is_zero(cx.x) && CGAL::is_zero(cx.y) && CGAL::is_zero(cx.z);
    if (!line_tangent_at_vertex(scene, fan, d, parallel_x ? ey : ex).tangent) return false;
  }
  // Edge generators: met in the relative interior, edge rule.
  // With w = b - a, the lines meet iff w x dir != 0 (not parallel) and det[a - o, w, dir] = 0 (coplanar);
  // the meeting point is then a + u w with u = num / c_k on an axis with c_k = (w x dir)_k != 0 (as in
  // edge_meeting_parameter), so 0 < u < 1 is two signs: signs only, no division in Q(sqrt D).
  for (int i = 0; i < k.edge_count(); ++i) {
    const Vec3<R> a = lift(scene.vertices[k.edges[i][0]]), b = lift(scene.vertices[k.edges[i][1]]);
    const Vec3<R> w = b - a;
    int axis = 0;
    R c;
    for (; axis < 3; ++axis) {
      const int p = (axis + 1) % 3, q = (axis + 2) % 3;
      c = w[p] * dir[q] - w[q] * dir[p];
      if (!is_zero_root(c)) break;
    }
    if (axis == 3) return false;  // parallel
    const int p = (axis + 1) % 3, q = (axis + 2) % 3;
    const R num = (a[q] - o[q]) * dir[p] - (a[p] - o[p]) * dir[q];
    const int sc = CGAL::sign(c);
    if (CGAL::sign(num) != sc || CGAL::sign(num - c) != -sc) return false;  // u <= 0 or u >= 1
    if (!is_zero_root(dot(cross(a - o, w), dir))) return false;            // skew: not met at all
    if (!edge_rule(scene, adj, k.edges[i], dir)) return false;
  }
  if (face_kind && !in_plane_of(scene, k.faces[0], o, dir)) return false;
  // Free: the open spanned segment against the triangles whose boxes meet its (outward-rounded) box.
  Box3 box;
  for (int c = 0; c < 3; ++c) {
    const auto p = CGAL::to_interval(node.from[c]), q = CGAL::to_interval(node.to[c]);
    box.lo[c] = std::min(p.first, q.first);
    box.hi[c] = std::max(p.second, q.second);
  }
  std::vector<int> face_vertices;
  if (face_kind) {
    const SceneTriangle& f = scene.triangles[scene.index_of_id(k.faces[0])];
    face_vertices.assign(f.v.begin(), f.v.end());
  }
  const OpenSegmentTest spanned(node.from, node.to);
  for (const std::int64_t ti : index.candidates_in_box(box)) {
    const SceneTriangle& t = scene.triangles[ti];
    bool incident = false;
    for (int i = 0; i < k.vertex_count() && !incident; ++i) incident = has_corner(t, k.vertices[i]);
    for (int i = 0; i < k.edge_count() && !incident; ++i)
      incident = has_corner(t, k.edges[i][0]) && has_corner(t, k.edges[i][1]);
    for (int v : face_vertices) incident = incident || has_corner(t, v);
    if (incident) continue;
    if (spanned.meets(scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2)))
      return false;
  }
  return true;
}

}  // namespace exactvis
