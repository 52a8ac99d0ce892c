#include "events/interval_end_key.hpp"

#include "events/ev_events.hpp"
#include "kernel/predicates.hpp"

#include <algorithm>

namespace exactvis {
namespace {

bool is_zero(const Vec3<Exact>& v) { return CGAL::is_zero(v.x) && CGAL::is_zero(v.y) && CGAL::is_zero(v.z); }

// The other two edges of an EEE family than generator k, in family order (sorted).
std::array<EdgeIds, 2> others(const EeeEvent& event, int k) {
  std::array<EdgeIds, 2> out;
  int n = 0;
  for (int i = 0; i < 3; ++i)
    if (i != k) out[n++] = event.edges[i];
  return out;
}

}  // namespace

ExtremalLineKey ev_end_key(const Scene& scene, const SceneAdjacency& adj, int vertex, const EdgeIds& edge,
                           const Exact& t, const CriticalEnd& end) {
  using Cause = CriticalEnd::Cause;
  using Kind = OccluderFeature::Kind;
  const int endpoint = CGAL::is_zero(t) ? edge[0] : edge[1];
  switch (end.cause) {
    case Cause::EdgeEndpoint:
      return vv_key(vertex, end.vertex >= 0 ? end.vertex : endpoint);
    case Cause::Occluder:
    case Cause::EndObjectChange:
      switch (end.feature.kind) {
        case Kind::WedgeSide: return vv_key(vertex, endpoint);
        case Kind::Vertex: return vv_key(vertex, end.feature.ids.at(0));
        case Kind::Edge: return vee_key(vertex, edge, edge_ids(end.feature.ids.at(0), end.feature.ids.at(1)));
        case Kind::Face:
          if (end.cause == Cause::EndObjectChange) return veff_key(vertex, edge, end.triangle, end.other_triangle);
          return vef_key(vertex, edge, end.triangle);
      }
      break;
    case Cause::Tangency: {
      const Vec3<Exact> V = to_rational(scene.vertices[vertex]);
      const Vec3<Exact> d = ev_edge_point(scene, edge, t) - V;
      int through = -1;
      std::int64_t face = end.triangle;
      bool found_face = false;
      for (int ti : adj.vertex_triangles[vertex]) {
        const SceneTriangle& tr = scene.triangles[ti];
        std::array<Vec3<Exact>, 2> w;
        int n = 0;
        for (int k = 0; k < 3; ++k) {
          if (tr.v[k] == vertex) continue;
          w[n] = to_rational(scene.vertices[tr.v[k]]) - V;
          if (is_zero(cross(w[n], d)) && (through < 0 || tr.v[k] < through)) through = tr.v[k];
          ++n;
        }
        if (CGAL::is_zero(dot(cross(w[0], w[1]), d)) && (!found_face || tr.id < face)) {
          face = tr.id;
          found_face = true;
        }
      }
      if (through >= 0) return vv_key(vertex, through);
      return fve_key(face, vertex, edge);
    }
    case Cause::Singular:
      break;
  }
  return fve_key(end.triangle, vertex, edge);  // not reached for EV causes
}

ExtremalLineKey eee_end_key(const Scene& scene, const SceneAdjacency& adj, const EeeEvent& event, const RootNumber& t,
                            const CriticalEnd& end) {
  using Cause = CriticalEnd::Cause;
  using Kind = OccluderFeature::Kind;
  const int g = end.generator;
  switch (end.cause) {
    case Cause::EdgeEndpoint: {
      const auto o = others(event, g);
      return vee_key(end.vertex, o[0], o[1]);
    }
    case Cause::Singular: {
      const auto o = others(event, g);
      return eep_key(o[0], o[1], event.edges[g]);
    }
    case Cause::EndObjectChange:
      break;
    case Cause::Occluder:
    case Cause::Tangency: {
      if (end.cause == Cause::Occluder && end.feature.kind == Kind::Vertex)
        return vee_key(end.feature.ids.at(0), event.edges[0], event.edges[1]);
      const EeeLinePoints line = eee_line_points(scene, event, t);
      if (end.cause == Cause::Occluder && end.feature.kind == Kind::Edge) {
        const PluckerLine<RootNumber> l{line.direction, cross(line.on_e1, line.direction)};
        return eeee_key(scene, {event.edges[0], event.edges[1], event.edges[2],
                                edge_ids(end.feature.ids.at(0), end.feature.ids.at(1))}, l);
      }
      // Does the plane of scene triangle `ti` contain the point p (in the field of t)?
      auto in_plane = [&](int ti, const Vec3<RootNumber>& p) {
        const SceneTriangle& tr = scene.triangles[ti];
        const Vec3<Exact> a = to_rational(scene.corner(tr, 0));
        const Vec3<Exact> n = cross(to_rational(scene.corner(tr, 1)) - a, to_rational(scene.corner(tr, 2)) - a);
        const RootNumber h = RootNumber(n.x) * p.x + RootNumber(n.y) * p.y + RootNumber(n.z) * p.z - RootNumber(dot(n, a));
        return CGAL::is_zero(h);
      };
      if (end.cause == Cause::Occluder) {  // Face: the first generator point in the occluder's plane
        const int ti = static_cast<int>(scene.index_of_id(end.triangle));
        const std::optional<Vec3<RootNumber>> pts[3] = {line.on_e1, line.on_e2, line.on_e3};
        int k = 0;
        for (int i = 0; i < 3; ++i)
          if (pts[i] && ti >= 0 && in_plane(ti, *pts[i])) {
            k = i;
            break;
          }
        const auto o = others(event, k);
        return eeef_key(o[0], o[1], event.edges[k], end.triangle);
      }
      // Tangency at generator g: the lowest id among E_g's faces whose plane contains the line.
      const Vec3<RootNumber> second(line.on_e1.x + line.direction.x, line.on_e1.y + line.direction.y,
                                    line.on_e1.z + line.direction.z);
      std::int64_t face = end.triangle;
      bool found = false;
      const int ei = adj.edge_index(event.edges[g][0], event.edges[g][1]);
      if (ei >= 0)
        for (int ti : adj.edges[ei].triangles)
          if (in_plane(ti, line.on_e1) && in_plane(ti, second) && (!found || scene.triangles[ti].id < face)) {
            face = scene.triangles[ti].id;
            found = true;
          }
      const auto o = others(event, g);
      return fee_key(face, o[0], o[1]);
    }
  }
  const auto o = others(event, 0);
  return vee_key(-1, o[0], o[1]);  // not reached for EEE causes
}

}  // namespace exactvis
