#include "region/coplanar_panels.hpp"

#include "kernel/predicates.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <tuple>

namespace exactvis::region {
namespace {

using Key = std::tuple<double, double, double>;
Key key(const Point3& p) { return {p.x, p.y, p.z}; }
Point3 point(const Key& k) { return {std::get<0>(k), std::get<1>(k), std::get<2>(k)}; }

// The coordinate (along `axis` of the projection) used to order collinear points: the first of the two
// projected coordinates in which they differ.
bool strictly_between(const Point3& u, const Point3& v, const Point3& w, int axis) {
  for (int k : {(axis + 1) % 3, (axis + 2) % 3}) {
    if (u[k] == w[k]) continue;
    return (u[k] < v[k] && v[k] < w[k]) || (u[k] > v[k] && v[k] > w[k]);
  }
  return false;  // u and w project to one point
}

}  // namespace

std::vector<Point3> convex_union_loop(const Scene& scene, const std::vector<std::int64_t>& triangles) {
  if (triangles.empty()) return {};
  // A projection the plane does not degenerate in, and the common orientation there.
  const SceneTriangle& t0 = scene.triangles[static_cast<std::size_t>(triangles.front())];
  int axis = -1;
  Sign orientation = Sign::Zero;
  for (int a = 0; a < 3 && axis < 0; ++a) {
    orientation = orient2d_projected(scene.corner(t0, 0), scene.corner(t0, 1), scene.corner(t0, 2), a);
    if (orientation != Sign::Zero) axis = a;
  }
  if (axis < 0) return {};
  // Net multiplicity of each undirected edge (+1 per traversal from the smaller key to the larger).
  std::map<std::pair<Key, Key>, int> net;
  for (const std::int64_t t : triangles) {
    const SceneTriangle& st = scene.triangles[static_cast<std::size_t>(t)];
    const std::array<Point3, 3> c{scene.corner(st, 0), scene.corner(st, 1), scene.corner(st, 2)};
    if (orient2d_projected(c[0], c[1], c[2], axis) != orientation) return {};
    if (orient3d(scene.corner(t0, 0), scene.corner(t0, 1), scene.corner(t0, 2), c[0]) != Sign::Zero ||
        orient3d(scene.corner(t0, 0), scene.corner(t0, 1), scene.corner(t0, 2), c[1]) != Sign::Zero ||
        orient3d(scene.corner(t0, 0), scene.corner(t0, 1), scene.corner(t0, 2), c[2]) != Sign::Zero)
      return {};  // not coplanar
    for (std::size_t k = 0; k < 3; ++k) {
      const Key a = key(c[k]), b = key(c[(k + 1) % 3]);
      if (a < b) ++net[{a, b}];
      else --net[{b, a}];
    }
  }
  // The boundary: directed edges of net multiplicity one; each vertex must start exactly one.
  std::map<Key, Key> next;
  for (const auto& [e, m] : net) {
    if (m == 0) continue;
    if (m != 1 && m != -1) return {};
    const Key& from = m > 0 ? e.first : e.second;
    const Key& to = m > 0 ? e.second : e.first;
    if (!next.emplace(from, to).second) return {};
  }
  if (next.size() < 3) return {};
  // One closed loop through every boundary edge.
  std::vector<Point3> loop;
  Key at = next.begin()->first;
  for (std::size_t steps = 0; steps < next.size(); ++steps) {
    loop.push_back(point(at));
    const auto it = next.find(at);
    if (it == next.end()) return {};
    at = it->second;
    if (at == next.begin()->first && steps + 1 < next.size()) return {};  // a shorter loop
  }
  if (at != next.begin()->first) return {};
  // Drop collinear points (each must lie strictly between its neighbours); the rest must turn strictly
  // the triangles' way.
  const std::size_t m = loop.size();
  std::vector<Point3> corners;
  for (std::size_t i = 0; i < m; ++i) {
    const Point3 &u = loop[(i + m - 1) % m], &v = loop[i], &w = loop[(i + 1) % m];
    const Sign s = orient2d_projected(u, v, w, axis);
    if (s == Sign::Zero) {
      if (!strictly_between(u, v, w, axis)) return {};
      continue;
    }
    if (s != orientation) return {};
    corners.push_back(v);
  }
  if (corners.size() < 3) return {};
  // Every corner on the closed inner side of every edge: a convex polygon traversed once.
  const std::size_t k = corners.size();
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j) {
      if (j == i || j == (i + 1) % k) continue;
      const Sign s = orient2d_projected(corners[i], corners[(i + 1) % k], corners[j], axis);
      if (s != Sign::Zero && s != orientation) return {};
    }
  return corners;
}

CoplanarPanels coplanar_panels(const Scene& scene, int max_greedy) {
  const std::size_t n = scene.triangles.size();
  CoplanarPanels out;
  out.panel_of.assign(n, -1);
  // Undirected edges -> the triangles that have them.
  std::map<std::pair<Key, Key>, std::vector<std::int64_t>> edges;
  std::vector<char> usable(n, 0);
  for (std::size_t t = 0; t < n; ++t) {
    const SceneTriangle& st = scene.triangles[t];
    if (collinear(scene.corner(st, 0), scene.corner(st, 1), scene.corner(st, 2))) continue;
    usable[t] = 1;
    for (int k = 0; k < 3; ++k) {
      Key u = key(scene.corner(st, k)), v = key(scene.corner(st, (k + 1) % 3));
      if (v < u) std::swap(u, v);
      edges[{u, v}].push_back(static_cast<std::int64_t>(t));
    }
  }
  // Coplanar edge-adjacency.
  std::vector<std::vector<std::int64_t>> adjacent(n);
  for (const auto& [e, ts] : edges)
    for (std::size_t i = 0; i < ts.size(); ++i)
      for (std::size_t j = i + 1; j < ts.size(); ++j) {
        const SceneTriangle& a = scene.triangles[static_cast<std::size_t>(ts[i])];
        const SceneTriangle& b = scene.triangles[static_cast<std::size_t>(ts[j])];
        bool coplanar = true;
        for (int k = 0; k < 3 && coplanar; ++k)
          coplanar = orient3d(scene.corner(a, 0), scene.corner(a, 1), scene.corner(a, 2), scene.corner(b, k)) == Sign::Zero;
        if (!coplanar) continue;
        adjacent[static_cast<std::size_t>(ts[i])].push_back(ts[j]);
        adjacent[static_cast<std::size_t>(ts[j])].push_back(ts[i]);
      }
  std::vector<char> seen(n, 0);
  auto add_panel = [&](std::vector<std::int64_t> members, std::vector<Point3> loop) {
    const auto p = static_cast<std::int32_t>(out.panels.size());
    for (const std::int64_t t : members) out.panel_of[static_cast<std::size_t>(t)] = p;
    out.panels.push_back({std::move(members), std::move(loop)});
  };
  for (std::size_t start = 0; start < n; ++start) {
    if (!usable[start] || seen[start] || adjacent[start].empty()) continue;
    // The connected component, in increasing order.
    std::vector<std::int64_t> component{static_cast<std::int64_t>(start)};
    seen[start] = 1;
    for (std::size_t i = 0; i < component.size(); ++i)
      for (const std::int64_t o : adjacent[static_cast<std::size_t>(component[i])])
        if (!seen[static_cast<std::size_t>(o)]) {
          seen[static_cast<std::size_t>(o)] = 1;
          component.push_back(o);
        }
    std::sort(component.begin(), component.end());
    if (auto loop = convex_union_loop(scene, component); !loop.empty()) {
      add_panel(std::move(component), std::move(loop));
      continue;
    }
    // Greedy growth inside the component.
    std::set<std::int64_t> open(component.begin(), component.end());
    while (!open.empty()) {
      std::vector<std::int64_t> members{*open.begin()};
      open.erase(open.begin());
      std::vector<Point3> loop;
      for (bool grew = true; grew && static_cast<int>(members.size()) < max_greedy;) {
        grew = false;
        std::set<std::int64_t> frontier;
        for (const std::int64_t t : members)
          for (const std::int64_t o : adjacent[static_cast<std::size_t>(t)])
            if (open.count(o)) frontier.insert(o);
        for (const std::int64_t o : frontier) {
          std::vector<std::int64_t> trial = members;
          trial.insert(std::upper_bound(trial.begin(), trial.end(), o), o);
          if (auto l = convex_union_loop(scene, trial); !l.empty()) {
            members = std::move(trial);
            loop = std::move(l);
            open.erase(o);
            grew = true;
            break;
          }
        }
      }
      if (members.size() >= 2) add_panel(std::move(members), std::move(loop));
    }
  }
  // Pairs, greedy in index order along t's edges.
  out.pair_of.assign(n, -1);
  for (std::size_t t = 0; t < n; ++t) {
    if (!usable[t] || adjacent[t].empty() || out.pair_of[t] >= 0) continue;
    const SceneTriangle& st = scene.triangles[t];
    for (int k = 0; k < 3 && out.pair_of[t] < 0; ++k) {
      Key u = key(scene.corner(st, k)), v = key(scene.corner(st, (k + 1) % 3));
      if (v < u) std::swap(u, v);
      for (const std::int64_t o : edges[{u, v}]) {
        if (o == static_cast<std::int64_t>(t) || out.pair_of[static_cast<std::size_t>(o)] >= 0) continue;
        const auto& adj = adjacent[t];
        if (std::find(adj.begin(), adj.end(), o) == adj.end()) continue;  // not coplanar
        std::vector<std::int64_t> two{std::min<std::int64_t>(static_cast<std::int64_t>(t), o),
                                      std::max<std::int64_t>(static_cast<std::int64_t>(t), o)};
        std::vector<Point3> loop = convex_union_loop(scene, two);
        if (loop.empty()) continue;
        const auto p = static_cast<std::int32_t>(out.pairs.size());
        out.pair_of[t] = out.pair_of[static_cast<std::size_t>(o)] = p;
        out.pairs.push_back({std::move(two), std::move(loop)});
        break;
      }
    }
  }
  return out;
}

}  // namespace exactvis::region
