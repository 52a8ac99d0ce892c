#include "skeleton/angular_sweep_2d.hpp"

#include <algorithm>
#include <numeric>
#include <set>

namespace exactvis {
namespace {

struct SweepEdge {
  int id;     // edge id
  int a, b;   // endpoints ordered so that center, a, b turn counterclockwise
  // orientation2(a, b, center) is Positive by construction (center, a, b counterclockwise)
};

// e1 strictly closer to the center than e2 along every ray of a sector both cross (they are disjoint
// except possibly for a shared endpoint, which no open sector both cross contains).
struct CloserEdge {
  const Scene2D* s;
  const Point2* c;
  bool operator()(const SweepEdge& e1, const SweepEdge& e2) const {
    if (e1.id == e2.id) return false;
    const auto& P = s->points;
    const Point2 &a1 = P[e1.a], &b1 = P[e1.b], &a2 = P[e2.a], &b2 = P[e2.b];
    const Sign sc = Sign::Positive;  // orientation2(a1, b1, center): center, a1, b1 turn counterclockwise
    const Sign o1 = orientation2(a1, b1, a2), o2 = orientation2(a1, b1, b2);
    const bool same1 = o1 == sc || o1 == Sign::Zero, same2 = o2 == sc || o2 == Sign::Zero;
    const bool opp1 = o1 == -sc || o1 == Sign::Zero, opp2 = o2 == -sc || o2 == Sign::Zero;
    if (same1 && same2) return false;  // e2 on the center's side of e1: e2 closer
    if (opp1 && opp2) return true;
    // e2 straddles line(e1); then e1 lies on one side of line(e2)
    const Sign tc = Sign::Positive;
    const Sign p1 = orientation2(a2, b2, a1), p2 = orientation2(a2, b2, b1);
    return (p1 == tc || p1 == Sign::Zero) && (p2 == tc || p2 == Sign::Zero);
  }
};

}  // namespace

bool edge_closer(const Scene2D& scene, const Point2& center, int e1, int e2) {
  auto oriented = [&](int e) {
    int a = e, b = scene.next[e];
    if (orientation2(center, scene.points[a], scene.points[b]) == Sign::Negative) std::swap(a, b);
    return SweepEdge{e, a, b};
  };
  return CloserEdge{&scene, &center}(oriented(e1), oriented(e2));
}

bool vertex_before_crossing(const Scene2D& scene, const Point2& center, int w, int crossing) {
  if (crossing < 0) return true;
  const Point2& a = scene.points[crossing];
  const Point2& b = scene.points[scene.next[crossing]];
  return orientation2(a, b, scene.points[w]) == orientation2(a, b, center);
}

std::vector<SweepEvent2D> angular_sweep(const Scene2D& scene, const Point2& c, int center_vertex) {
  const auto& P = scene.points;
  const int n = scene.num_vertices();
  // 1. vertices sorted by direction, then distance
  // half-plane of each direction computed once: the sort then needs one orientation per comparison
  std::vector<char> half(n, 0);
  std::vector<int> order;
  order.reserve(n);
  for (int v = 0; v < n; ++v) {
    if (v == center_vertex) continue;
    order.push_back(v);
    const Sign sy = dy_sign(c, P[v]);
    half[v] = sy == Sign::Positive ? 0 : (sy == Sign::Negative ? 1 : (dx_sign(c, P[v]) == Sign::Positive ? 0 : 1));
  }
  auto angle_cmp = [&](int u, int v) {  // -1, 0, +1 as compare_angle
    if (half[u] != half[v]) return half[u] < half[v] ? -1 : 1;
    const Sign o = orientation2(c, P[u], P[v]);
    return o == Sign::Positive ? -1 : (o == Sign::Negative ? 1 : 0);
  };
  std::sort(order.begin(), order.end(), [&](int u, int v) {
    const int k = angle_cmp(u, v);
    if (k != 0) return k < 0;
    return dot_sign(P[u], P[v], c, P[u]) == Sign::Positive;  // u nearer: (v-u).(u-c) > 0
  });
  std::vector<int> group(n, -1);
  std::vector<SweepEvent2D> events;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || angle_cmp(order[i - 1], order[i]) != 0) events.emplace_back();
    events.back().vertices.push_back(order[i]);
    group[order[i]] = static_cast<int>(events.size()) - 1;
  }
  const int G = static_cast<int>(events.size());
  // 2. edges not collinear with the center, oriented counterclockwise as seen from it
  std::vector<std::vector<SweepEdge>> starts(G), ends(G);
  std::set<SweepEdge, CloserEdge> status(CloserEdge{&scene, &c});
  std::vector<std::set<SweepEdge, CloserEdge>::iterator> where(n, status.end());
  std::vector<SweepEdge> initial;
  for (int e = 0; e < n; ++e) {
    int a = e, b = scene.next[e];
    if (a == center_vertex || b == center_vertex) continue;
    const Sign o = orientation2(c, P[a], P[b]);
    if (o == Sign::Zero) continue;
    if (o == Sign::Negative) std::swap(a, b);
    const SweepEdge se{e, a, b};
    starts[group[a]].push_back(se);
    ends[group[b]].push_back(se);
    if (group[a] > group[b]) initial.push_back(se);  // wraps past direction (1,0): present at the start
  }
  for (const SweepEdge& se : initial) where[se.id] = status.insert(se).first;
  // 3. sweep
  for (int g = 0; g < G; ++g) {
    SweepEvent2D& ev = events[g];
    ev.before = status.empty() ? -1 : status.begin()->id;
    for (const SweepEdge& se : ends[g]) {
      if (where[se.id] != status.end()) {
        status.erase(where[se.id]);
        where[se.id] = status.end();
      }
    }
    ev.crossing = status.empty() ? -1 : status.begin()->id;
    for (const SweepEdge& se : starts[g]) where[se.id] = status.insert(se).first;
    ev.after = status.empty() ? -1 : status.begin()->id;
  }
  return events;
}

}  // namespace exactvis
