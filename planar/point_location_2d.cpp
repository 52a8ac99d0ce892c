#include "planar/point_location_2d.hpp"

#include <algorithm>
#include <stdexcept>

namespace exactvis {
namespace {

// Edges e and f both span an open slab (their y-ranges contain it) and do not cross inside it: is e left of
// f there? Scene edges meet only at shared endpoints, so an endpoint of one lying on the other is a shared
// vertex; then the other ends decide.
bool left_of(const PointLocation2D& L, int e, int f) {
  if (e == f) return false;
  const auto& P = L.scene->points;
  const int a = L.lower[e], b = L.upper[e], c = L.lower[f], d = L.upper[f];
  if (L.level_of[a] >= L.level_of[c]) {  // a lies within f's height range
    const Sign s = orientation2(P[c], P[d], P[a]);
    if (s != Sign::Zero) return s == Sign::Positive;
  } else {  // c lies within e's height range (and is not an endpoint of e)
    return orientation2(P[a], P[b], P[c]) == Sign::Negative;
  }
  // a == c: compare by the upper ends, the lower of which lies within the other edge's range
  if (L.level_of[b] <= L.level_of[d]) return orientation2(P[c], P[d], P[b]) == Sign::Positive;
  return orientation2(P[a], P[b], P[d]) == Sign::Negative;
}

// The endpoint of horizontal edge e with the smaller x, and the other one.
int left_end(const Scene2D& s, int e) { return dx_sign(s.points[s.next[e]], s.points[e]) == Sign::Negative ? e : s.next[e]; }
int right_end(const Scene2D& s, int e) { return left_end(s, e) == e ? s.next[e] : e; }

void insert(PointLocation2D& L, int node, int lo, int hi, int s, int t, int e) {
  if (t <= lo || hi <= s) return;
  if (s <= lo && hi <= t) {
    L.node_edges[node].push_back(e);
    return;
  }
  const int mid = (lo + hi) / 2;
  insert(L, 2 * node, lo, mid, s, t, e);
  insert(L, 2 * node + 1, mid, hi, s, t, e);
}

// Sign of q.y - (height of level i).
Sign compare_height(const PointLocation2D& L, const Point2& q, int level) {
  return dy_sign(L.scene->points[L.by_height[L.level_start[level]]], q);
}

struct SlabHits {
  int east = -1, west = -1;  // first edge right / left of q inside the slab
  bool on_edge = false;      // q lies on an edge spanning the slab
};

// The edges of slab j nearest to q on each side; q's height lies in the closed slab.
SlabHits search_slab(const PointLocation2D& L, int j, const Point2& q) {
  const auto& P = L.scene->points;
  SlabHits out;
  int node = 1, lo = 0, hi = L.slabs;
  for (;;) {
    const std::vector<int>& list = L.node_edges[node];
    // first edge with q on or left of it (orientation >= 0): the sorted order makes the sign monotone
    std::size_t a = 0, b = list.size();
    Sign at = Sign::Negative;
    while (a < b) {
      const std::size_t m = (a + b) / 2;
      const Sign s = orientation2(P[L.lower[list[m]]], P[L.upper[list[m]]], q);
      if (s == Sign::Negative) {
        a = m + 1;
      } else {
        b = m;
        at = s;
      }
    }
    if (a < list.size()) {
      if (at == Sign::Zero) out.on_edge = true;
      else if (out.east < 0 || left_of(L, list[a], out.east)) out.east = list[a];
    }
    if (a > 0 && (out.west < 0 || left_of(L, out.west, list[a - 1]))) out.west = list[a - 1];
    if (hi - lo == 1) break;
    const int mid = (lo + hi) / 2;
    if (j < mid) node = 2 * node, hi = mid;
    else node = 2 * node + 1, lo = mid;
  }
  return out;
}

}  // namespace

PointLocation2D point_location_2d(const Scene2D& scene) {
  PointLocation2D L;
  L.scene = &scene;
  const auto& P = scene.points;
  const int n = scene.num_vertices();
  L.by_height.resize(n);
  for (int v = 0; v < n; ++v) L.by_height[v] = v;
  std::sort(L.by_height.begin(), L.by_height.end(), [&](int u, int v) {
    const Sign sy = dy_sign(P[u], P[v]);
    return sy != Sign::Zero ? sy == Sign::Positive : dx_sign(P[u], P[v]) == Sign::Positive;
  });
  L.level_of.assign(n, -1);
  for (int i = 0; i < n; ++i) {
    const int v = L.by_height[i];
    if (i == 0 || dy_sign(P[L.by_height[i - 1]], P[v]) != Sign::Zero) L.level_start.push_back(i);
    L.level_of[v] = static_cast<int>(L.level_start.size()) - 1;
  }
  const int levels = static_cast<int>(L.level_start.size());
  L.level_start.push_back(n);
  L.slabs = std::max(levels - 1, 0);
  L.horizontal.resize(levels);
  L.lower.assign(n, -1);
  L.upper.assign(n, -1);
  L.node_edges.resize(L.slabs > 0 ? 4 * L.slabs : 0);
  for (int e = 0; e < n; ++e) {
    const int a = e, b = scene.next[e];
    if (L.level_of[a] == L.level_of[b]) {
      L.horizontal[L.level_of[a]].push_back(e);
      continue;
    }
    const bool up = L.level_of[a] < L.level_of[b];
    L.lower[e] = up ? a : b;
    L.upper[e] = up ? b : a;
    insert(L, 1, 0, L.slabs, L.level_of[L.lower[e]], L.level_of[L.upper[e]], e);
  }
  for (auto& list : L.node_edges) std::sort(list.begin(), list.end(), [&](int e, int f) { return left_of(L, e, f); });
  for (auto& list : L.horizontal)
    std::sort(list.begin(), list.end(), [&](int e, int f) {
      return dx_sign(P[left_end(scene, e)], P[left_end(scene, f)]) == Sign::Positive;
    });
  return L;
}

LocatedPoint2D locate_point(const PointLocation2D& L, const Point2& q) {
  const auto& P = L.scene->points;
  const Scene2D& s = *L.scene;
  LocatedPoint2D out;
  const int levels = static_cast<int>(L.level_start.size()) - 1;
  if (levels == 0) return out;
  // the first level not below q
  int lo = 0, hi = levels;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (compare_height(L, q, mid) == Sign::Positive) lo = mid + 1; else hi = mid;
  }
  const bool at_level = lo < levels && compare_height(L, q, lo) == Sign::Zero;
  if (at_level) {
    // q on a horizontal edge of its height (a vertex of q's height with a non-horizontal edge is found by
    // the slab searches below: that edge spans a slab next to the height and passes through q)
    // horizontal edges of this height are disjoint but for shared (vertex) ends: sorted by their left ends,
    // the last one starting at or left of q is the only one that can hold q
    const auto& hz = L.horizontal[lo];
    const auto e = std::upper_bound(hz.begin(), hz.end(), 0, [&](int, int f) {
      return dx_sign(q, P[left_end(s, f)]) == Sign::Positive;  // q.x < left end of f
    });
    if (e != hz.begin() && dx_sign(q, P[right_end(s, *(e - 1))]) != Sign::Negative) {
      out.on_boundary = true;
      return out;
    }
  }
  // the slab of each ray: (1, -eps) runs just below q's height, (-1, +eps) just above (at a level they differ)
  const int east_slab = lo - 1;
  const int west_slab = at_level ? lo : lo - 1;
  if (east_slab >= 0 && east_slab < L.slabs) {
    const SlabHits h = search_slab(L, east_slab, q);
    if (h.on_edge) {
      out.on_boundary = true;
      return out;
    }
    out.east = h.east;
    if (west_slab == east_slab) out.west = h.west;
  }
  if (west_slab != east_slab && west_slab >= 0 && west_slab < L.slabs) {
    const SlabHits h = search_slab(L, west_slab, q);
    if (h.on_edge) {
      out.on_boundary = true;
      return out;
    }
    out.west = h.west;
  }
  out.inside_object = out.east >= 0 && orientation2(P[out.east], P[s.next[out.east]], q) == Sign::Positive;
  return out;
}

}  // namespace exactvis
