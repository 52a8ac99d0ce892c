#include "region/occluder_shaft.hpp"

#include "kernel/filtered_predicate.hpp"

#include <CGAL/Mpzf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <type_traits>
#include <utility>

namespace exactvis::region {

std::vector<Plane3> shaft_planes(const StabbingPair& pair) {
  std::vector<RationalPoint3> pts = pair.source;
  pts.insert(pts.end(), pair.target.begin(), pair.target.end());
  std::vector<Plane3> planes{pair.source_plane, pair.target_plane};
  // The side of point p with respect to plane_through(a, b, c) is the sign of ((b - a) x (c - a)) . (p - a):
  // evaluated first in interval arithmetic from enclosures of the points (computed once), the exact plane
  // built only when an interval contains 0 or the plane is kept. The same signs, hence the same planes.
  using I = Interval;
  std::vector<std::array<I, 3>> enc(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (int k = 0; k < 3; ++k) enc[i][static_cast<std::size_t>(k)] = I(enclosing_interval(pts[i][k]));
  auto sub = [](const std::array<I, 3>& x, const std::array<I, 3>& y) {
    return std::array<I, 3>{x[0] - y[0], x[1] - y[1], x[2] - y[2]};
  };
  std::vector<signed char> sign(pts.size());  // +1, -1, 0: on the plane or undecided by the intervals
  // edges_at: offset of edges_of in pts, vertices_at: that of vertices_of.
  auto consider = [&](const Polygon3& edges_of, std::size_t edges_at, const Polygon3& vertices_of,
                      std::size_t vertices_at) {
    for (std::size_t i = 0; i < edges_of.size(); ++i) {
      const std::size_t i1 = (i + 1) % edges_of.size();
      const auto& a = edges_of[i];
      const auto& b = edges_of[i1];
      for (std::size_t ci = 0; ci < vertices_of.size(); ++ci) {
        const auto& c = vertices_of[ci];
        if (collinear(a, b, c)) continue;
        // a, b, c lie on the plane by construction (side 0, which sets neither flag): not evaluated.
        auto skip = [&](std::size_t pi) { return pi == edges_at + i || pi == edges_at + i1 || pi == vertices_at + ci; };
        bool pos = false, neg = false;
        {
          CGAL::Protect_FPU_rounding<true> guard;  // interval arithmetic only in this scope
          const std::array<I, 3>& ea = enc[edges_at + i];
          const std::array<I, 3> ab = sub(enc[edges_at + i1], ea), ac = sub(enc[vertices_at + ci], ea);
          const std::array<I, 3> n{ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                                   ab[0] * ac[1] - ab[1] * ac[0]};
          for (std::size_t pi = 0; pi < pts.size(); ++pi) {
            sign[pi] = 0;
            if (skip(pi)) continue;
            const std::array<I, 3> ap = sub(enc[pi], ea);
            const I v = n[0] * ap[0] + n[1] * ap[1] + n[2] * ap[2];
            sign[pi] = v.inf() > 0 ? 1 : v.sup() < 0 ? -1 : 0;
            pos |= sign[pi] > 0;
            neg |= sign[pi] < 0;
          }
        }
        if (pos && neg) continue;  // not a supporting plane
        std::optional<Plane3> pl;  // plane_through(a, b, c), built on demand
        for (std::size_t pi = 0; pi < pts.size() && !(pos && neg); ++pi) {
          if (skip(pi) || sign[pi] != 0) continue;
          if (!pl) pl = plane_through(a, b, c);
          const Sign sd = plane_side(*pl, pts[pi]);
          pos |= sd == Sign::Positive;
          neg |= sd == Sign::Negative;
        }
        if (pos && neg) continue;
        if (!pl) pl = plane_through(a, b, c);
        planes.push_back(neg ? pl->flipped() : *pl);
      }
    }
  };
  consider(pair.source, 0, pair.target, pair.source.size());
  consider(pair.target, pair.source.size(), pair.source, 0);
  return planes;
}

namespace {

// A shaft plane tested against many scene corners: its coefficients are converted once. The side test is the
// named, counted predicate `shaft_plane_side` (the three layers of kernel/filtered_predicate.hpp; the same
// value as plane_side, whose generic form converts the coefficients on every call).
// Layer 1 is a hand-written semi-static filter (docs/theory.md §5.4): the value in plain doubles from the
// coefficients rounded once, certified when its magnitude exceeds 2^-48 times the sum of the terms'
// magnitudes (the coefficient rounding, < 2 ulps each, and the 4 roundings of the evaluation are < 8 u of
// that sum; 2^-48 = 32 u leaves a wide margin), plus 2^-1000 for underflow. When every coefficient is a
// double exactly (the common case on scenes with coordinates on a binary grid), layers 2 and 3 evaluate the
// same double expression in interval arithmetic (a corner on the plane then gives an exact [0, 0]) and in
// CGAL::Mpzf, without GMP rationals.
struct ShaftPlane {
  Plane3 exact;
  std::array<std::pair<double, double>, 4> enclosures;  // normal x, y, z and offset
  std::array<double, 4> approx;                          // the same, rounded to doubles
  bool filter_usable = false;  // every approx finite (else layer 1 is skipped)
  bool doubles_exact = false;  // every approx equals its coefficient exactly
  explicit ShaftPlane(const Plane3& p)
      : exact(p),
        enclosures{enclosing_interval(p.normal.x), enclosing_interval(p.normal.y), enclosing_interval(p.normal.z),
                   enclosing_interval(p.offset)},
        approx{CGAL::to_double(p.normal.x), CGAL::to_double(p.normal.y), CGAL::to_double(p.normal.z),
               CGAL::to_double(p.offset)} {
    filter_usable = true;
    for (const double a : approx) filter_usable = filter_usable && std::isfinite(a) && std::fabs(a) < 0x1p500;
    doubles_exact = filter_usable && Exact(approx[0]) == p.normal.x && Exact(approx[1]) == p.normal.y &&
                    Exact(approx[2]) == p.normal.z && Exact(approx[3]) == p.offset;
    // The box test picks the corner of largest value by the signs of the rounded normal: they must be the
    // exact signs (rounding keeps a sign, but a tiny component could round to zero).
    box_usable = filter_usable && (approx[0] == 0) == (CGAL::sign(p.normal.x) == 0) &&
                 (approx[1] == 0) == (CGAL::sign(p.normal.y) == 0) && (approx[2] == 0) == (CGAL::sign(p.normal.z) == 0);
  }
  bool box_usable = false;  // box_outside may certify
  // True only when the closed box lies strictly on the outer side (value < 0 at every point, certified by
  // layer 1 at the corner of largest value); false when unsure. Every triangle inside such a box has its
  // three corners on the outer side, so the per-triangle culling below would drop it: skipping the box
  // changes nothing.
  bool box_outside(const Box3& b) const {
    if (!box_usable) return false;
    const Point3 x{approx[0] > 0 ? b.hi.x : b.lo.x, approx[1] > 0 ? b.hi.y : b.lo.y, approx[2] > 0 ? b.hi.z : b.lo.z};
    const auto s = semi_static(x);
    return s && *s == Sign::Negative;
  }
  // Layer 1: the certified sign, or nullopt.
  std::optional<Sign> semi_static(const Point3& x) const {
    if (!filter_usable) return std::nullopt;
    const double t0 = approx[0] * x.x, t1 = approx[1] * x.y, t2 = approx[2] * x.z;
    const double v = (t0 + t1) + (t2 - approx[3]);
    const double bound = 0x1p-48 * ((std::fabs(t0) + std::fabs(t1)) + (std::fabs(t2) + std::fabs(approx[3]))) +
                         0x1p-1000;
    if (!(std::fabs(bound) < 0x1p900)) return std::nullopt;  // also catches NaN and infinity
    if (v > bound) return Sign::Positive;
    if (v < -bound) return Sign::Negative;
    return std::nullopt;
  }
  // sign(exact.value(x))
  Sign side(const Point3& x) const {
    static PredicateCounter counter("shaft_plane_side");
    auto semi = [&] { return semi_static(x); };
    if (doubles_exact)
      return filtered_sign_with<CGAL::Mpzf>(counter, semi, [&](auto nt) {
        using NT = typename decltype(nt)::type;
        return NT(approx[0]) * NT(x.x) + NT(approx[1]) * NT(x.y) + NT(approx[2]) * NT(x.z) - NT(approx[3]);
      });
    return filtered_sign_with(counter, semi, [&](auto nt) {
      using NT = typename decltype(nt)::type;
      if constexpr (std::is_same_v<NT, Exact>) {
        return exact.value(to_rational(x));
      } else {
        return NT(enclosures[0]) * NT(x.x) + NT(enclosures[1]) * NT(x.y) + NT(enclosures[2]) * NT(x.z) -
               NT(enclosures[3]);
      }
    });
  }
};

// A polygon being clipped, with the line each edge lies on: edge_line[i] = k (0..2) when the edge
// points[i] -> points[i + 1] lies on the triangle's edge k (corner k -> corner k + 1), in that direction; -1
// when it lies on a clipping plane (or tracking was given up). The points are exactly clip_polygon's.
struct TrackedPolygon {
  Polygon3 points;
  std::vector<int> edge_line;
};

// clip_polygon (region/convex_polygon_3) with the edges' lines tracked: the same loop, the same crossing
// points and the same removal of repeated vertices. An output edge from a kept vertex i or the crossing on
// input edge i to the kept vertex i + 1 or the crossing on input edge i lies on input edge i, in its
// direction; any other output edge joins two points of the plane. When repeated vertices were removed the
// tracking is given up (every edge -1: the caller then takes the rational line, as before).
TrackedPolygon clip_tracked(const TrackedPolygon& in, const Plane3& plane) {
  TrackedPolygon out;
  const Polygon3& poly = in.points;
  const std::size_t n = poly.size();
  if (n == 0) return out;
  struct Tag {
    bool kept;      // kept input vertex `i`, else the crossing point on input edge `i`
    std::size_t i;
  };
  std::vector<Exact> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = plane.value(poly[i]);
  Polygon3 pts;
  std::vector<Tag> tags;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const int si = CGAL::sign(v[i]), sj = CGAL::sign(v[j]);
    if (si >= 0) {
      pts.push_back(poly[i]);
      tags.push_back({true, i});
    }
    if ((si > 0 && sj < 0) || (si < 0 && sj > 0)) {
      const Exact t = v[i] / (v[i] - v[j]);
      pts.push_back(poly[i] + t * (poly[j] - poly[i]));
      tags.push_back({false, i});
    }
  }
  bool merged = false;
  std::vector<Tag> clean_tags;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    if (out.points.empty() || !(out.points.back() == pts[k])) {
      out.points.push_back(pts[k]);
      clean_tags.push_back(tags[k]);
    } else {
      merged = true;
    }
  }
  while (out.points.size() > 1 && out.points.front() == out.points.back()) {
    out.points.pop_back();
    clean_tags.pop_back();
    merged = true;
  }
  const std::size_t m = out.points.size();
  out.edge_line.assign(m, -1);
  if (merged) return out;
  for (std::size_t e = 0; e < m; ++e) {
    const Tag& a = clean_tags[e];
    const Tag& b = clean_tags[(e + 1) % m];
    const bool along = a.kept ? (b.kept ? b.i == (a.i + 1) % n : b.i == a.i) : (b.kept && b.i == (a.i + 1) % n);
    if (along) out.edge_line[e] = in.edge_line[a.i];
  }
  return out;
}

// The triangle clipped to the wedge between the pair's planes, with its edge functionals; std::nullopt when
// the clipped part has no area off both planes (docs/theory.md §5.2). An edge of the clipped polygon that
// lies on one of the triangle's edges, in its direction, has that edge's functional (the primitive integer
// vector of a directed line does not depend on the two points chosen on it): from the double corners in the
// fixed layer when `corners` is given and it fits, else from the rational corners. Only the edges on the
// polygon planes need the rational clipped points.
// inside_source / inside_target: the caller proved the three corners strictly inside that polygon plane, so
// the triangle (convex) is, and clipping by that plane keeps it as it is (clip_polygon keeps vertices of value
// > 0 in order and inserts none) and it cannot lie in that plane: the clip and the test are skipped.
std::optional<ShaftOccluder> clipped_occluder(const std::array<RationalPoint3, 3>& tri, const StabbingPair& pair,
                                              const std::array<Point3, 3>* corners, bool inside_source = false,
                                              bool inside_target = false) {
  TrackedPolygon clipped{{tri[0], tri[1], tri[2]}, {0, 1, 2}};
  if (!inside_source) clipped = clip_tracked(clipped, pair.source_plane);
  if (!inside_target) clipped = clip_tracked(clipped, pair.target_plane);
  const Polygon3& poly = clipped.points;
  if (is_degenerate(poly)) return std::nullopt;
  if ((!inside_source && lies_in_plane(poly, pair.source_plane)) ||
      (!inside_target && lies_in_plane(poly, pair.target_plane)))
    return std::nullopt;
  std::array<std::optional<ConeVector6>, 3> triangle_edge;
  auto edge_functional = [&](int k) -> const ConeVector6& {
    auto& f = triangle_edge[static_cast<std::size_t>(k)];
    if (!f) {
      ConeVector6 e;
      const std::size_t a = static_cast<std::size_t>(k), b = static_cast<std::size_t>((k + 1) % 3);
      if (corners && side_functional_of_doubles((*corners)[a], (*corners)[b], e)) f = std::move(e);
      else f = ConeVector6(side_functional(line_through(tri[a], tri[b])));
    }
    return *f;
  };
  ShaftOccluder occ;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const int k = clipped.edge_line[i];
    if (k >= 0) occ.edges.push_back(edge_functional(k));
    else occ.edges.emplace_back(side_functional(line_through(poly[i], poly[(i + 1) % poly.size()])));
  }
  return occ;
}

// The same for a triangle with double corners strictly inside both polygon planes (the caller proved the six
// signs): clipping keeps the triangle as it is (clip_polygon keeps vertices of value > 0 in order and adds
// none), it is not degenerate unless collinear, and it lies in neither plane. The edge functionals come from
// the fixed layer where it can, else from the rational line (the same vectors either way).
std::optional<ShaftOccluder> unclipped_occluder(const std::array<Point3, 3>& c) {
  if (collinear(c[0], c[1], c[2])) return std::nullopt;
  ShaftOccluder occ;
  for (std::size_t i = 0; i < 3; ++i) {
    const Point3 &a = c[i], &b = c[(i + 1) % 3];
    ConeVector6 e;
    if (!side_functional_of_doubles(a, b, e)) e = ConeVector6(side_functional(line_through(to_rational(a), to_rational(b))));
    occ.edges.push_back(std::move(e));
  }
  return occ;
}

}  // namespace

namespace {

std::vector<ShaftOccluder> occluders_among(const Scene& scene, const std::vector<std::int64_t>& candidates,
                                           std::int64_t target, const std::vector<ShaftPlane>& planes,
                                           const StabbingPair& pair) {
  std::vector<ShaftOccluder> out;
  for (const std::int64_t idx : candidates) {
    if (idx == target) continue;
    const auto& st = scene.triangles[idx];
    const std::array<Point3, 3> c{scene.corner(st, 0), scene.corner(st, 1), scene.corner(st, 2)};
    bool culled = false;
    for (std::size_t k = 0; k < planes.size() && !culled; ++k) {
      const auto& pl = planes[k];
      // Entirely on the closed outer side of a supporting plane: meets the shaft at most in that plane,
      // which only a measure-zero set of stabbing segments touches (docs/theory.md §5.2).
      culled = pl.side(c[0]) != Sign::Positive && pl.side(c[1]) != Sign::Positive && pl.side(c[2]) != Sign::Positive;
    }
    if (culled) continue;
    // Strictly inside both polygon planes (planes[0], planes[1]): the clipping shortcut applies. Only the
    // few survivors of the culling pay these signs.
    std::array<bool, 2> inside{true, true};  // the three corners strictly inside planes[k]
    for (std::size_t k = 0; k < 2; ++k)
      for (std::size_t i = 0; i < 3 && inside[k]; ++i) inside[k] = planes[k].side(c[i]) == Sign::Positive;
    const bool inside_wedge = inside[0] && inside[1];
    auto occ = inside_wedge ? unclipped_occluder(c)
                            : clipped_occluder(triangle_points(scene, idx), pair, &c, inside[0], inside[1]);
    if (occ) {
      occ->triangle = idx;
      occ->corners_d = c;
      occ->whole = inside_wedge;
      out.push_back(std::move(*occ));
    }
  }
  return out;
}

std::vector<ShaftPlane> filtered_shaft_planes(const StabbingPair& pair) {
  std::vector<ShaftPlane> planes;
  for (const auto& p : shaft_planes(pair)) planes.emplace_back(p);
  return planes;
}

}  // namespace

std::vector<ShaftOccluder> shaft_occluders(const Scene& scene, const std::vector<std::int64_t>& candidates,
                                           std::int64_t target, const StabbingPair& pair) {
  return occluders_among(scene, candidates, target, filtered_shaft_planes(pair), pair);
}

std::vector<ShaftOccluder> shaft_occluders(const Scene& scene, const HierarchyCandidates& finder, const Box3& box,
                                           std::int64_t target, const StabbingPair& pair) {
  const std::vector<ShaftPlane> planes = filtered_shaft_planes(pair);
  std::size_t last = 0;  // the plane that pruned last: neighbouring boxes tend to lie outside the same one
  auto outside = [&](const Box3& b) {
    if (planes[last].box_outside(b)) return true;
    for (std::size_t k = 0; k < planes.size(); ++k)
      if (k != last && planes[k].box_outside(b)) {
        last = k;
        return true;
      }
    return false;
  };
  return occluders_among(scene, finder.pruned_with(box, outside), target, planes, pair);
}

namespace {

// One level of merge_coplanar_panels: `groups` with `group_of` per scene triangle (the panels, or the pairs).
void merge_level(std::vector<ShaftOccluder>& occluders, const std::vector<CoplanarPanel>& groups,
                 const std::vector<std::int32_t>& group_of, const std::array<ShaftPlane, 2>& wedge,
                 std::int64_t target, const std::function<bool(std::int64_t)>& excluded) {
  const std::size_t n = group_of.size();
  auto group = [&](const ShaftOccluder& o) -> std::int32_t {
    if (o.triangle < 0 || static_cast<std::size_t>(o.triangle) >= n || o.panel_loop) return -1;
    return group_of[static_cast<std::size_t>(o.triangle)];
  };
  // The groups present with the position of their first occluder: sorted by (group, position), the first of
  // each group kept, then back in the order of first occurrence.
  std::vector<std::pair<std::int32_t, std::size_t>> first;
  for (std::size_t i = 0; i < occluders.size(); ++i)
    if (const std::int32_t g = group(occluders[i]); g >= 0) first.emplace_back(g, i);
  if (first.empty()) return;
  std::sort(first.begin(), first.end());
  first.erase(std::unique(first.begin(), first.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
              first.end());
  std::vector<char> merged(occluders.size(), 0);  // positions that now hold a merged group
  std::vector<std::int32_t> used;                 // usable groups, sorted (`first` is sorted by group)
  for (const auto& [g, at] : first) {
    const CoplanarPanel& panel = groups[static_cast<std::size_t>(g)];
    bool ok = true;
    for (const Point3& c : panel.loop)
      for (const ShaftPlane& pl : wedge) ok = ok && pl.side(c) == Sign::Positive;
    for (std::size_t k = 0; k < panel.triangles.size() && ok; ++k)
      ok = panel.triangles[k] != target && !(excluded && excluded(panel.triangles[k]));
    if (!ok) continue;
    ShaftOccluder q;
    q.triangle = occluders[at].triangle;
    q.corners_d = occluders[at].corners_d;
    q.panel_loop = &panel.loop;
    const std::size_t m = panel.loop.size();
    for (std::size_t i = 0; i < m; ++i) {
      const Point3 &a = panel.loop[i], &b = panel.loop[(i + 1) % m];
      ConeVector6 e;
      if (!side_functional_of_doubles(a, b, e)) e = ConeVector6(side_functional(line_through(to_rational(a), to_rational(b))));
      q.edges.push_back(std::move(e));
    }
    occluders[at] = std::move(q);
    merged[at] = 1;
    used.push_back(g);
  }
  if (used.empty()) return;
  std::size_t w = 0;
  for (std::size_t i = 0; i < occluders.size(); ++i) {
    const std::int32_t g = merged[i] ? -1 : group(occluders[i]);
    if (g >= 0 && std::binary_search(used.begin(), used.end(), g)) continue;  // merged into its group
    if (w != i) occluders[w] = std::move(occluders[i]);
    ++w;
  }
  occluders.resize(w);
}

}  // namespace

void merge_coplanar_panels(std::vector<ShaftOccluder>& occluders, const CoplanarPanels& panels,
                           const StabbingPair& pair, std::int64_t target,
                           const std::function<bool(std::int64_t)>& excluded, bool whole_panels) {
  // Nothing to merge (the common case on scenes without coplanar neighbours): not even the wedge's planes.
  auto in_some = [&](const ShaftOccluder& o) {
    if (o.triangle < 0 || static_cast<std::size_t>(o.triangle) >= panels.pair_of.size()) return false;
    const auto t = static_cast<std::size_t>(o.triangle);
    return (whole_panels && panels.panel_of[t] >= 0) || panels.pair_of[t] >= 0;
  };
  if (std::none_of(occluders.begin(), occluders.end(), in_some)) return;
  const std::array<ShaftPlane, 2> wedge{ShaftPlane(pair.source_plane), ShaftPlane(pair.target_plane)};
  if (whole_panels) merge_level(occluders, panels.panels, panels.panel_of, wedge, target, excluded);
  merge_level(occluders, panels.pairs, panels.pair_of, wedge, target, excluded);
}

std::vector<ShaftOccluder> shaft_occluders(const std::vector<std::array<RationalPoint3, 3>>& triangles,
                                           const StabbingPair& pair) {
  const std::vector<Plane3> planes = shaft_planes(pair);
  std::vector<ShaftOccluder> out;
  for (std::size_t idx = 0; idx < triangles.size(); ++idx) {
    const auto& tri = triangles[idx];
    bool culled = false;
    for (const auto& pl : planes)
      if (plane_side(pl, tri[0]) != Sign::Positive && plane_side(pl, tri[1]) != Sign::Positive &&
          plane_side(pl, tri[2]) != Sign::Positive) {
        culled = true;  // as above: meets the shaft at most in a supporting plane
        break;
      }
    if (culled) continue;
    if (auto occ = clipped_occluder(tri, pair, nullptr)) {
      occ->triangle = static_cast<std::int64_t>(idx);
      for (int k = 0; k < 3; ++k)
        occ->corners_d[static_cast<std::size_t>(k)] = {CGAL::to_double(tri[static_cast<std::size_t>(k)].x),
                                                       CGAL::to_double(tri[static_cast<std::size_t>(k)].y),
                                                       CGAL::to_double(tri[static_cast<std::size_t>(k)].z)};
      out.push_back(std::move(*occ));
    }
  }
  return out;
}

}  // namespace exactvis::region
