#include "region/convex_occluder.hpp"

#include "aspect/convex_model.hpp"
#include "kernel/filtered_predicate.hpp"
#include "kernel/predicates.hpp"
#include "util/union_find.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <optional>

namespace exactvis::region {

namespace {

using Key3 = std::array<double, 3>;
Key3 key(const Point3& p) { return {p.x, p.y, p.z}; }

// The components' triangles (indices into scene.triangles) of one object, edge-connected by exact corners.
std::vector<std::vector<std::int64_t>> edge_components(const Scene& scene, const std::vector<std::int64_t>& tris) {
  UnionFind uf(tris.size());
  std::map<std::pair<Key3, Key3>, int> first_with_edge;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const SceneTriangle& t = scene.triangles[tris[i]];
    for (int k = 0; k < 3; ++k) {
      Key3 a = key(scene.corner(t, k)), b = key(scene.corner(t, (k + 1) % 3));
      if (b < a) std::swap(a, b);
      const auto [it, fresh] = first_with_edge.emplace(std::make_pair(a, b), static_cast<int>(i));
      if (!fresh) uf.unite(static_cast<int>(i), it->second);
    }
  }
  std::map<int, std::vector<std::int64_t>> by_root;
  for (std::size_t i = 0; i < tris.size(); ++i) by_root[uf.find(static_cast<int>(i))].push_back(tris[i]);
  std::vector<std::vector<std::int64_t>> out;
  for (auto& [root, members] : by_root) out.push_back(std::move(members));
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.front() < y.front(); });
  return out;
}

// The component as a scene of its own (compact vertex list), for the convex-model test.
Scene component_scene(const Scene& scene, const std::vector<std::int64_t>& tris) {
  Scene sub;
  sub.objects.push_back({"component"});
  std::map<int, int> vertex_of;
  for (const std::int64_t ti : tris) {
    SceneTriangle t = scene.triangles[ti];
    for (int& v : t.v) {
      const auto [it, fresh] = vertex_of.emplace(v, static_cast<int>(sub.vertices.size()));
      if (fresh) sub.vertices.push_back(scene.vertices[v]);
      v = it->second;
    }
    t.object = 0;
    sub.triangles.push_back(t);
  }
  sub.faces_read = static_cast<std::int64_t>(sub.triangles.size());
  return sub;
}

// Sign of va_i * vb_j - va_j * vb_i for the facet values at a and b (the order of two clipping parameters).
Sign parameter_order(const Plane3& pi, const Plane3& pj, const RationalPoint3& a, const RationalPoint3& b) {
  static PredicateCounter counter("segment_solid_clip_order");
  return filtered_sign_with(
      counter, [] { return std::optional<Sign>{}; },  // inputs are rationals: no semi-static layer
      [&](auto nt) {
        using NT = typename decltype(nt)::type;
        auto value = [](const Plane3& p, const RationalPoint3& x) {
          return as<NT>(p.normal.x) * as<NT>(x.x) + as<NT>(p.normal.y) * as<NT>(x.y) +
                 as<NT>(p.normal.z) * as<NT>(x.z) - as<NT>(p.offset);
        };
        return value(pi, a) * value(pj, b) - value(pj, a) * value(pi, b);
      });
}

}  // namespace

std::vector<ConvexSolid> convex_solids(const Scene& scene) {
  std::vector<std::vector<std::int64_t>> by_object(scene.objects.size());
  for (std::size_t i = 0; i < scene.triangles.size(); ++i)
    by_object[scene.triangles[i].object].push_back(static_cast<std::int64_t>(i));
  std::vector<ConvexSolid> out;
  for (std::size_t o = 0; o < by_object.size(); ++o) {
    if (by_object[o].size() < 4) continue;
    for (std::vector<std::int64_t>& tris : edge_components(scene, by_object[o])) {
      if (tris.size() < 4) continue;
      // Zero-area triangles have no plane (the loader drops them; built scenes may not).
      if (std::any_of(tris.begin(), tris.end(), [&](std::int64_t ti) {
            const SceneTriangle& t = scene.triangles[ti];
            return collinear(scene.corner(t, 0), scene.corner(t, 1), scene.corner(t, 2));
          }))
        continue;
      const Scene sub = component_scene(scene, tris);
      const ConvexModel model = convex_model(sub);
      if (!model.convex) continue;
      ConvexSolid s;
      s.object = static_cast<int>(o);
      s.triangles = std::move(tris);
      for (const ModelPlane& p : model.planes) s.facets.push_back({p.normal, p.offset});
      std::map<Key3, Point3> corners;
      for (const Point3& v : sub.vertices) corners.emplace(key(v), v);
      for (const auto& [k, p] : corners) s.corners.push_back(p);
      s.box = bounding_box(sub);
      out.push_back(std::move(s));
    }
  }
  return out;
}

bool segment_meets_solid(const ConvexSolid& solid, const RationalPoint3& a, const RationalPoint3& b) {
  // On [a, b], x(t) = a + t (b - a) and each facet value is affine: v(t) = va + t (vb - va); P is where
  // every v(t) <= 0. A facet with va > 0 >= vb gives t >= va / (va - vb) (a lower bound), one with
  // va <= 0 < vb gives t <= va / (va - vb) (an upper bound); both denominators are non-zero, and
  // lower_i <= upper_j iff va_i vb_j - va_j vb_i <= 0 (cross-multiplied by (va_i - vb_i) > 0 and
  // (vb_j - va_j) > 0).
  std::vector<int> lower, upper;
  for (std::size_t f = 0; f < solid.facets.size(); ++f) {
    const Sign sa = plane_side(solid.facets[f], a), sb = plane_side(solid.facets[f], b);
    if (sa == Sign::Positive && sb == Sign::Positive) return false;
    if (sa == Sign::Positive) lower.push_back(static_cast<int>(f));
    else if (sb == Sign::Positive) upper.push_back(static_cast<int>(f));
  }
  for (const int i : lower)
    for (const int j : upper)
      if (parameter_order(solid.facets[i], solid.facets[j], a, b) == Sign::Positive) return false;
  return true;
}

namespace {
std::array<RationalPoint3, 8> box_corners(const RationalBox3& b) {
  std::array<RationalPoint3, 8> c;
  for (int k = 0; k < 8; ++k)
    c[k] = {(k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z};
  return c;
}
}  // namespace

bool box_disjoint_from_solid(const ConvexSolid& solid, const RationalBox3& box) {
  const std::array<RationalPoint3, 8> corners = box_corners(box);
  for (const Plane3& f : solid.facets)
    if (std::all_of(corners.begin(), corners.end(),
                    [&](const RationalPoint3& c) { return plane_side(f, c) == Sign::Positive; }))
      return true;
  // The solid's corners are doubles, the box's rationals: exact comparisons.
  for (int axis = 0; axis < 3; ++axis) {
    const bool below = std::all_of(solid.corners.begin(), solid.corners.end(),
                                   [&](const Point3& p) { return Exact(p[axis]) < box.lo[axis]; });
    const bool above = std::all_of(solid.corners.begin(), solid.corners.end(),
                                   [&](const Point3& p) { return Exact(p[axis]) > box.hi[axis]; });
    if (below || above) return true;
  }
  return false;
}

bool solid_blocks_box_pair(const ConvexSolid& solid, const RationalBox3& cell, const RationalBox3& box) {
  // Both boxes apart from P: a closed segment from C to B that meets P then meets it (entering from outside,
  // at its surface) at a point of its open interior (a decal flush on a facet is not hidden by that solid).
  if (!box_disjoint_from_solid(solid, cell) || !box_disjoint_from_solid(solid, box)) return false;
  const std::array<RationalPoint3, 8> from = box_corners(cell), to = box_corners(box);
  for (const RationalPoint3& a : from)
    for (const RationalPoint3& b : to)
      if (!segment_meets_solid(solid, a, b)) return false;
  return true;
}

}  // namespace exactvis::region
