#include "aspect/eee_face_split.hpp"

#include "kernel/predicates.hpp"
#include "kernel/rational_between.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

namespace exactvis {
namespace {

using V3 = Vec3<Exact>;
using Mat = std::array<std::array<Exact, 3>, 3>;

Exact quad_form(const Mat& q, const V3& a, const V3& b) {
  Exact v(0);
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) v += a[r] * q[r][s] * b[s];
  return v;
}

// p (on the cone of arc `own`, strictly inside face f) moved by eps w, eps an exact power of two small enough
// that the segment [p, p + eps w] stays in f (same circle signs at both ends: they are linear along it) and meets
// no cone of the face's sub-arcs but at p (own cone: q(p + l w) = l (2 p^T Q w + l w^T Q w), no other root in
// (0, eps] iff the bracket keeps its sign at eps; the others: no sign change at eps nor at an extremum inside).
std::optional<V3> off_side(const EeeArcInsertion& ins, const std::vector<V3>& normals, int f, int own, const V3& p,
                           const V3& w) {
  std::set<int> arcs;
  for (int si : ins.subarcs_of_face[f]) arcs.insert(ins.subarcs[si].arc);
  Exact eps(1);
  for (int it = 0; it < 400; ++it, eps /= 2) {
    const V3 d = p + eps * w;
    bool ok = true;
    for (const V3& n : normals)
      if (CGAL::sign(dot(n, d)) != CGAL::sign(dot(n, p))) ok = false;
    for (int g : arcs) {
      if (!ok) break;
      const Mat& q = ins.cone[g];
      const Exact h0 = quad_form(q, p, p), h1 = Exact(2) * quad_form(q, p, w), h2 = quad_form(q, w, w);
      if (g == own) {
        if (CGAL::sign(h1) == 0) return std::nullopt;
        ok = CGAL::sign(h1 + eps * h2) == CGAL::sign(h1);
        continue;
      }
      const int s0 = CGAL::sign(h0);
      if (s0 == 0) return std::nullopt;
      ok = CGAL::sign(h0 + eps * (h1 + eps * h2)) == s0;
      if (ok && CGAL::sign(h2) != 0) {
        const Exact tv = -h1 / (Exact(2) * h2);
        if (CGAL::sign(tv) > 0 && tv < eps) ok = CGAL::sign(h0 + tv * (h1 + tv * h2)) == s0;
      }
    }
    if (ok) return scaled_to_unit_max(d);
  }
  return std::nullopt;
}

}  // namespace

EeeFaceSplit split_eee_face(const Scene& scene, const DirectionEventArcs& events, const GreatCircleArrangement& arr,
                            const std::vector<V3>& normals, const EeeArcInsertion& ins, const EeeCrossings& xs, int f,
                            const std::vector<int>& ring, const std::vector<V3>& ring_samples,
                            const std::vector<EeeFaceSegment>& segments,
                            const std::vector<std::vector<int>>& segments_of_subarc, const std::vector<int>& point_cell,
                            const std::vector<int>& crossing_cell) {
  EeeFaceSplit out;
  const int n = static_cast<int>(ring.size());
  std::map<int, int> position;  // vertex cell -> index in ring
  for (int i = 0; i < n; i += 2) position[ring[i]] = i;
  const auto& subs = ins.subarcs_of_face[f];
  // Sub-arc ends on the boundary; several at one point x by the angle of their tangents in the face's chart,
  // swept from the boundary before x (towards the previous ring cell) through the face (the chart's origin, the
  // face's sample) to the boundary after x: bucket 0 along the boundary before x, 1 strictly inside the sweep, 2
  // along the boundary after x when x is no vertex (a straight angle: an arc touching the circle at x).
  struct End {
    int pos, sub, k;
  };
  std::vector<End> list;
  for (std::size_t i = 0; i < subs.size(); ++i) {
    const EeeSubArc& s = ins.subarcs[subs[i]];
    for (int k = 0; k < 2; ++k) {
      const auto it = position.find(point_cell[k == 0 ? s.first : s.second]);
      if (it != position.end()) list.push_back({it->second, static_cast<int>(i), k});
    }
  }
  const EeeFaceChart chart = eee_face_chart(arr, f);
  auto tangent = [&](const End& e) {
    const EeeSubArc& s = ins.subarcs[subs[e.sub]];
    Exact t;
    root_number_rational(ins.points[e.k == 0 ? s.first : s.second].t, &t);
    return eee_end_tangent(scene, events.arcs[s.arc], chart, t, e.k);
  };
  auto cr = [](const std::array<Exact, 2>& u, const std::array<Exact, 2>& v) { return CGAL::sign(u[0] * v[1] - u[1] * v[0]); };
  auto sweep_at = [&](int pos) {
    const auto x = chart_point(chart, ring_samples[pos]);
    const auto y = chart_point(chart, ring_samples[(pos + n - 1) % n]);
    return cr({y[0] - x[0], y[1] - x[1]}, {-x[0], -x[1]});
  };
  bool unordered = false;
  std::sort(list.begin(), list.end(), [&](const End& a, const End& b) {
    if (a.pos != b.pos) return a.pos < b.pos;
    if (a.sub == b.sub && a.k == b.k) return false;
    const auto x = chart_point(chart, ring_samples[a.pos]);
    const auto y = chart_point(chart, ring_samples[(a.pos + n - 1) % n]);
    const std::array<Exact, 2> r0{y[0] - x[0], y[1] - x[1]};
    const int sweep = cr(r0, {-x[0], -x[1]});
    auto bucket = [&](const std::array<Exact, 2>& v) {
      const int c = cr(r0, v) * sweep;
      if (c > 0) return 1;
      if (c < 0) return 3;
      return CGAL::sign(r0[0] * v[0] + r0[1] * v[1]) > 0 ? 0 : 2;
    };
    const auto va = tangent(a), vb = tangent(b);
    const int ba = bucket(va), bb = bucket(vb);
    if (ba != bb) return ba < bb;
    int o = cr(va, vb) * sweep;
    if (o == 0 && CGAL::sign(va[0] * vb[0] + va[1] * vb[1]) > 0) {
      // One tangent: b lies on a's left (counter-clockwise in the chart) iff, just after the common point, b is on
      // the side of a's cone where q_a has the sign of (Q_a p) . w, w the left normal of a's dart there.
      const EeeSubArc &sa = ins.subarcs[subs[a.sub]], &sb = ins.subarcs[subs[b.sub]];
      Exact ta, tb;
      root_number_rational(ins.points[a.k == 0 ? sa.first : sa.second].t, &ta);
      root_number_rational(ins.points[b.k == 0 ? sb.first : sb.second].t, &tb);
      const auto& qa = ins.cone[sa.arc];
      const V3 p = arc_direction(scene, events.arcs[sa.arc], ta);
      V3 w = eee_left_normal(scene, events.arcs[sa.arc], chart, ta);
      if (a.k == 1) w = -w;
      V3 qp;
      for (int r = 0; r < 3; ++r) qp[r] = qa[r][0] * p.x + qa[r][1] * p.y + qa[r][2] * p.z;
      const int left = CGAL::sign(dot(qp, w));
      const int side = eee_cone_sign_after(scene, events.arcs[sb.arc], qa, tb, b.k == 0 ? 1 : -1);
      if (left != 0 && side != 0) o = (side == left ? 1 : -1) * sweep;
    }
    if (o == 0 && CGAL::sign(va[0] * vb[0] + va[1] * vb[1]) > 0) unordered = true;
    return o > 0;
  });
  if (unordered) {
    out.problem = "two free EEE arcs leave a common point tangentially";
    return out;
  }
  // rho = +1 when the boundary runs counter-clockwise in the chart (the face on its left there): every
  // orientation below is taken in the sense in which the face lies on the left of the boundary.
  const int rho = -sweep_at(0);

  // Edges: the boundary pieces (dart 2e along the boundary, 2e + 1 against it), then the segments (2e along
  // increasing parameter). A dart's tail is a node (a cell id).
  struct Edge {
    int from, to, cell, segment;  // segment -1 for a boundary piece
  };
  std::vector<Edge> edges;
  std::vector<int> ring_edge(n, -1);
  for (int i = 1; i < n; i += 2) {
    ring_edge[i] = static_cast<int>(edges.size());
    edges.push_back({ring[i - 1], ring[(i + 1) % n], ring[i], -1});
  }
  std::map<int, int> edge_of_segment;
  for (int si : subs)
    for (int g : segments_of_subarc[si]) {
      edge_of_segment[g] = static_cast<int>(edges.size());
      edges.push_back({segments[g].from, segments[g].to, segments[g].cell, g});
    }
  auto tail = [&](int d) { return d % 2 == 0 ? edges[d / 2].from : edges[d / 2].to; };
  const int darts = 2 * static_cast<int>(edges.size());
  std::map<int, std::vector<int>> rot;  // node -> darts leaving it, counter-clockwise (face-on-the-left sense)
  for (int i = 0; i < n; i += 2) {
    std::vector<int>& r = rot[ring[i]];
    r.push_back(2 * ring_edge[(i + 1) % n]);
    std::vector<int> inner;
    for (const End& e : list)
      if (e.pos == i) {
        const auto& sg = segments_of_subarc[subs[e.sub]];
        inner.push_back(e.k == 0 ? 2 * edge_of_segment[sg.front()] : 2 * edge_of_segment[sg.back()] + 1);
      }
    r.insert(r.end(), inner.rbegin(), inner.rend());
    r.push_back(2 * ring_edge[(i + n - 1) % n] + 1);
  }
  std::map<int, int> crossing_of_node;
  for (std::size_t x = 0; x < xs.crossings.size(); ++x)
    if (xs.crossings[x].face == f) crossing_of_node[crossing_cell[x]] = static_cast<int>(x);
  std::map<int, std::vector<int>> loose;  // other nodes: their darts
  for (int d = 2 * (n / 2); d < darts; ++d)
    if (!position.count(tail(d))) loose[tail(d)].push_back(d);
  for (auto& [node, ds] : loose) {
    const auto it = crossing_of_node.find(node);
    if (it == crossing_of_node.end()) {
      if (ds.size() != 1) {
        out.problem = "free EEE arcs meet at a point inside a face that is no crossing";
        return out;
      }
      rot[node] = ds;
      continue;
    }
    const EeeCrossing& x = xs.crossings[it->second];
    std::array<int, 2> plus{-1, -1}, minus{-1, -1};
    for (int d : ds) {
      const int sub = segments[edges[d / 2].segment].subarc;
      const int side = sub == x.subarc[0] ? 0 : 1;
      (d % 2 == 0 ? plus : minus)[side] = d;
    }
    if (ds.size() != 4 || plus[0] < 0 || plus[1] < 0 || minus[0] < 0 || minus[1] < 0)
      throw std::logic_error("split_eee_face: a crossing without its four segments");
    rot[node] = x.turn * rho > 0 ? std::vector<int>{plus[0], plus[1], minus[0], minus[1]}
                                 : std::vector<int>{plus[0], minus[1], minus[0], plus[1]};
  }
  std::vector<int> slot(darts, -1);
  for (const auto& [node, r] : rot)
    for (std::size_t i = 0; i < r.size(); ++i) slot[r[i]] = static_cast<int>(i);
  // The face to the left of dart d continues with the dart just clockwise of d's reverse at d's head.
  auto next = [&](int d) {
    const int rev = d ^ 1;
    const auto& r = rot[tail(rev)];
    return r[(slot[rev] + r.size() - 1) % r.size()];
  };
  std::vector<int> orbit(darts, -1);
  int orbits = 0;
  for (int d = 0; d < darts; ++d) {
    if (orbit[d] >= 0) continue;
    for (int e = d; orbit[e] < 0; e = next(e)) orbit[e] = orbits;
    ++orbits;
  }
  // Nodes joined to the boundary by segments; the other clusters lie inside one component.
  std::map<int, int> parent;
  std::function<int(int)> find = [&](int x) {
    auto it = parent.find(x);
    if (it == parent.end() || it->second == x) return x;
    return it->second = find(it->second);
  };
  for (const Edge& e : edges) parent[find(e.from)] = find(e.to);
  const int root = find(ring[0]);
  std::vector<char> outside(orbits, 0), attached(orbits, 0);
  for (int i = 1; i < n; i += 2) outside[orbit[2 * ring_edge[i] + 1]] = 1;
  for (int d = 0; d < darts; ++d) attached[orbit[d]] = find(tail(d)) == root;
  std::vector<int> inner;
  for (int o = 0; o < orbits; ++o)
    if (attached[o] && !outside[o]) inner.push_back(o);
  std::map<int, int> component_of_orbit;
  for (std::size_t k = 0; k < inner.size(); ++k) component_of_orbit[inner[k]] = static_cast<int>(k);
  out.components.resize(inner.size());
  std::vector<std::set<int>> facets(inner.size());
  std::map<int, std::set<int>> cluster_orbits;
  for (int d = 0; d < darts; ++d)
    if (!attached[orbit[d]]) cluster_orbits[find(tail(d))].insert(orbit[d]);
  for (const auto& [cluster, os] : cluster_orbits)
    if (os.size() != 1 || inner.size() != 1) {
      out.problem = "free EEE arcs with no end on the boundary of a face of the great circles enclose a region or lie in a face cut into several components";
      out.components.clear();
      return out;
    }
  for (int d = 0; d < darts; ++d) {
    const int k = attached[orbit[d]] ? (outside[orbit[d]] ? -1 : component_of_orbit[orbit[d]]) : 0;
    if (k >= 0) facets[k].insert(edges[d / 2].cell);
  }
  for (std::size_t k = 0; k < inner.size(); ++k) {
    out.components[k].facets.assign(facets[k].begin(), facets[k].end());
    std::optional<V3> sample;
    // Boundary pieces first, in ring order from the first end on the boundary (session 10's choice, so models
    // without crossings keep their samples).
    const int start = list.empty() ? 0 : list.front().pos;
    for (int j = 0; j < n && !sample; ++j) {
      const int i = (start + j) % n;
      if (i % 2 == 1 && orbit[2 * ring_edge[i]] == inner[k]) sample = sample_off_eee_arcs(ins, arr, f, ring_samples[i]);
    }
    for (int d = 0; d < darts && !sample; ++d) {
      if (orbit[d] != inner[k] || edges[d / 2].segment < 0) continue;
      const EeeFaceSegment& sg = segments[edges[d / 2].segment];
      const int arc = ins.subarcs[sg.subarc].arc;
      const V3 p = arc_direction(scene, events.arcs[arc], sg.t);
      V3 w = eee_left_normal(scene, events.arcs[arc], chart, sg.t);
      if ((d % 2 == 0 ? 1 : -1) * rho < 0) w = -w;
      sample = off_side(ins, normals, f, arc, p, w);
    }
    if (!sample) {
      out.problem = "every sample of a component of a face cut by free EEE arcs lies on an EEE cone";
      out.components.clear();
      return out;
    }
    out.components[k].sample = *sample;
  }
  return out;
}

}  // namespace exactvis
