#include "shadows/backprojection.hpp"

#include "kernel/predicates.hpp"
#include "shadows/convex_difference.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <stdexcept>

namespace exactvis::shadows {
namespace {

// The polygon's vertices in the chart (exact; the chart drops one coordinate).
std::vector<ChartPoint> to_chart(const PlaneChart& chart, const region::Polygon3& poly) {
  std::vector<ChartPoint> out;
  out.reserve(poly.size());
  for (const auto& v : poly) out.push_back(chart.to_2d(v));
  return out;
}

region::Polygon3 to_polygon3(const PlaneChart& chart, const std::vector<ChartPoint>& poly) {
  region::Polygon3 out;
  out.reserve(poly.size());
  for (const auto& p : poly) out.push_back(chart.to_3d(p[0], p[1]));
  return out;
}

void add_pieces(const PlaneChart& chart, const ChartRegion& region, VisibleLightPart& part) {
  for (const auto& pwh : region.pieces) {
    VisiblePolygon vp;
    vp.outer = to_polygon3(chart, pwh.outer);
    for (const auto& h : pwh.holes) vp.holes.push_back(to_polygon3(chart, h));
    part.pieces.push_back(std::move(vp));
  }
}

// The orient3d signs of a backprojection's pre-tests, where one point may be the (rational) point p: first
// BoundedDouble on p's enclosure (computed once per backprojection) and the exact doubles of the triangle
// and the light corners; the exact rational orient3d (kernel/predicates) only when the bound does not
// decide. Same signs as orient3d on the rationals.
class PointSigns {
 public:
  // A point of the predicate: its BoundedDouble enclosure and its exact rational.
  struct Arg {
    const Vec3<BoundedDouble>* bd;
    const RationalPoint3* q;
  };
  PointSigns(const Vec3<BoundedDouble>& pb, const RationalPoint3& p, const Point3 (&td)[3]) : pb_(pb), p_(p), td_(td) {
    for (int k = 0; k < 3; ++k) tb_[k] = {BoundedDouble(td[k].x), BoundedDouble(td[k].y), BoundedDouble(td[k].z)};
  }
  Arg p() const { return {&pb_, &p_}; }
  Arg t(int k) { return {&tb_[k], nullptr}; }
  Sign orient(const Arg& a, const Arg& b, const Arg& c, const Arg& d) {
    const Vec3<BoundedDouble>& A = *a.bd;
    const BoundedDouble det = dot(cross(*b.bd - A, *c.bd - A), *d.bd - A);
    if (const std::optional<Sign> s = det.certified_sign()) return *s;
    return orient3d(exact(a), exact(b), exact(c), exact(d));
  }
  // The triangle's corners as rationals (converted once, on first use).
  const std::array<RationalPoint3, 3>& rational() {
    if (!t_) t_ = std::array<RationalPoint3, 3>{to_rational(td_[0]), to_rational(td_[1]), to_rational(td_[2])};
    return *t_;
  }

 private:
  const RationalPoint3& exact(const Arg& a) {
    if (a.q) return *a.q;
    return rational()[a.bd - &tb_[0]];
  }
  const Vec3<BoundedDouble>& pb_;
  const RationalPoint3& p_;
  const Point3 (&td_)[3];
  Vec3<BoundedDouble> tb_[3];
  std::optional<std::array<RationalPoint3, 3>> t_;
};

}  // namespace

const char* light_class_name(LightClass c) {
  switch (c) {
    case LightClass::Umbra: return "umbra";
    case LightClass::Penumbra: return "penumbra";
    case LightClass::Lit: return "lit";
  }
  return "lit";
}

namespace {

// The backprojection with the candidate blockers of light triangle light[k] given by
// candidates(k, box of p and that triangle): any superset (in increasing index order) of the triangles
// meeting conv(p ∪ L) gives the same result, since the others hide a set of zero area.
template <class Candidates>
Backprojection backproject_with(const Scene& scene, const std::vector<int>& light, const RationalPoint3& p,
                                Candidates&& candidates) {
  Backprojection bp;
  std::set<std::int64_t> blockers;
  const Vec3<BoundedDouble> pb{BoundedDouble(enclosing_interval(p.x)), BoundedDouble(enclosing_interval(p.y)),
                               BoundedDouble(enclosing_interval(p.z))};
  for (std::size_t k_light = 0; k_light < light.size(); ++k_light) {
    const int li = light[k_light];
    const auto lt = region::triangle_points(scene, li);
    const auto& ltri = scene.triangles[li];
    const Point3 ld[3] = {scene.corner(ltri, 0), scene.corner(ltri, 1), scene.corner(ltri, 2)};
    VisibleLightPart part;
    part.light_triangle = li;
    part.chart = chart_of_triangle(lt[0], lt[1], lt[2]);
    const region::Polygon3 light_poly(lt.begin(), lt.end());
    const std::vector<ChartPoint> light2 = normalized_convex_polygon(to_chart(part.chart, light_poly));
    part.area_2d = ((light2[1][0] - light2[0][0]) * (light2[2][1] - light2[0][1]) -
                    (light2[1][1] - light2[0][1]) * (light2[2][0] - light2[0][0])) / 2;
    std::vector<RationalPoint3> hull(lt.begin(), lt.end());
    hull.push_back(p);
    const Box3 box = region::enclosing_box(hull);
    std::vector<std::vector<ChartPoint>> hidden;
    std::vector<std::int64_t> hidden_by;
    bool covered = false;  // one hidden polygon is the whole triangle (then it is the only one kept)
    Vec3<BoundedDouble> lb[3];
    PointSigns::Arg light_args[3];
    for (int j = 0; j < 3; ++j) {
      lb[j] = {BoundedDouble(ld[j].x), BoundedDouble(ld[j].y), BoundedDouble(ld[j].z)};
      light_args[j] = {&lb[j], &lt[j]};
    }
    for (std::int64_t ti : candidates(k_light, box)) {
      if (ti == li) continue;
      // The light corners against T's plane: scene doubles, so the double-input filtered orient3d (exact,
      // no rational conversion) decides them.
      const auto& tt = scene.triangles[ti];
      const Point3 td[3] = {scene.corner(tt, 0), scene.corner(tt, 1), scene.corner(tt, 2)};
      const Sign s0 = orient3d(td[0], td[1], td[2], ld[0]), s1 = orient3d(td[0], td[1], td[2], ld[1]),
                 s2 = orient3d(td[0], td[1], td[2], ld[2]);
      if (s0 == Sign::Zero && s1 == Sign::Zero && s2 == Sign::Zero)
        continue;  // T in the light's plane: the open segment (p, q) ends before it
      // The signs with p: BoundedDouble on p's enclosure (computed once) and the exact doubles of T and the
      // light, the exact rational orient3d only where the bound does not decide (PointSigns above).
      PointSigns ps(pb, p, td);
      const Sign sp = ps.orient(ps.t(0), ps.t(1), ps.t(2), ps.p());
      if (sp == Sign::Zero) continue;  // p in T's plane: hides at most a segment
      // Exact sign pre-tests (filtered): the light triangle entirely on p's side of T's plane, or entirely
      // outside one of the cone's side planes, is not hidden by T.
      if (s0 == sp && s1 == sp && s2 == sp) continue;
      bool outside = false;
      Sign inner[3];
      for (int k = 0; k < 3 && !outside; ++k) {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        inner[k] = ps.orient(ps.p(), ps.t(k), ps.t(k1), ps.t(k2));
        outside = ps.orient(ps.p(), ps.t(k), ps.t(k1), light_args[0]) == -inner[k] &&
                  ps.orient(ps.p(), ps.t(k), ps.t(k1), light_args[1]) == -inner[k] &&
                  ps.orient(ps.p(), ps.t(k), ps.t(k1), light_args[2]) == -inner[k];
      }
      if (outside) continue;
      const auto& t = ps.rational();
      // Beyond T's plane (closed), inside the three planes through p and T's edges (closed). The side plane
      // through p, t_k, t_k+1 has normal (t_k - p) x (t_k+1 - p) = (t_k+1 - t_k) x (p - t_k) (the same
      // vector, computed from the small difference of two corners), oriented by inner[k], the sign of its
      // value at t_k+2; T's plane is oriented by sp. The planes (hence the clipped polygon) are exactly those
      // of orienting each by its value at the inner point.
      const region::Plane3 tplane = region::plane_through(t[0], t[1], t[2]);
      region::Polygon3 poly = region::clip_polygon(light_poly, sp == Sign::Positive ? tplane.flipped() : tplane);
      for (int k = 0; k < 3 && poly.size() >= 3; ++k) {
        const RationalPoint3& a = t[k];
        const Vec3<Exact> normal = cross(t[(k + 1) % 3] - a, p - a);
        const region::Plane3 side{normal, dot(normal, a)};
        poly = region::clip_polygon(poly, inner[k] == Sign::Positive ? side : side.flipped());
      }
      if (region::is_degenerate(poly)) continue;
      std::vector<ChartPoint> h2 = normalized_convex_polygon(to_chart(part.chart, poly));
      if (h2.empty()) continue;
      // Fast path: one cone covering the whole light triangle. The hidden polygon is a convex subset of the
      // triangle, so it is the whole triangle iff it holds the three corners, iff the three corners are among
      // its vertices (each clip keeps a vertex on its closed side). It alone is the proof.
      const bool covers = std::all_of(lt.begin(), lt.end(), [&](const RationalPoint3& c) {
        return std::find(poly.begin(), poly.end(), c) != poly.end();
      });
      if (covers) {
        covered = true;
        hidden.clear();
        hidden_by.clear();
      }
      hidden.push_back(std::move(h2));
      hidden_by.push_back(scene.triangles[ti].id);
      if (covers) break;
    }
    if (covered) {
      part.visible_area_2d = 0;
      blockers.insert(hidden_by.front());
    } else if (hidden.empty()) {
      add_pieces(part.chart, cell_union_boundary({light2}), part);
      part.visible_area_2d = part.area_2d;
    } else {
      // The light triangle minus the union of the convex hidden polygons, in canonical form
      // (shadows/convex_difference.hpp; CGAL's Boolean operations are its oracle in the tests).
      // Largest first (double estimates; the result does not depend on the order): later, smaller ones then
      // mostly fall inside what is already hidden and split no cell.
      std::vector<std::pair<double, std::size_t>> order;
      for (std::size_t k = 0; k < hidden.size(); ++k) {
        double a2 = 0;
        const auto& h = hidden[k];
        for (std::size_t i = 0; i < h.size(); ++i) {
          const auto& p0 = h[i];
          const auto& p1 = h[(i + 1) % h.size()];
          a2 += CGAL::to_double(p0[0]) * CGAL::to_double(p1[1]) - CGAL::to_double(p0[1]) * CGAL::to_double(p1[0]);
        }
        order.push_back({-a2, k});
      }
      std::sort(order.begin(), order.end());
      std::vector<std::vector<ChartPoint>> sorted;
      sorted.reserve(hidden.size());
      for (const auto& [a, k] : order) sorted.push_back(std::move(hidden[k]));
      const ConvexDifference visible = convex_difference(light2, sorted);
      add_pieces(part.chart, visible.region, part);
      part.visible_area_2d = visible.region.area;
      // A blocker counts when its hidden polygon has positive area inside the light triangle.
      for (std::size_t k = 0; k < hidden.size(); ++k) blockers.insert(hidden_by[k]);
    }
    bp.parts.push_back(std::move(part));
  }
  // Fraction: exact when every light triangle lies in the first one's plane (one chart for all).
  Exact vis = 0, tot = 0;
  double vis_d = 0, tot_d = 0;
  bool coplanar = true;
  const auto first = region::triangle_points(scene, light.front());
  for (const auto& part : bp.parts) {
    const auto lt = region::triangle_points(scene, part.light_triangle);
    for (const auto& v : lt)
      if (orient3d(first[0], first[1], first[2], v) != Sign::Zero) coplanar = false;
    // Within one plane, 2D areas in each triangle's own chart are comparable only if the charts agree.
    if (part.chart.axis != bp.parts.front().chart.axis) coplanar = false;
    vis += part.visible_area_2d;
    tot += part.area_2d;
    vis_d += CGAL::to_double(part.visible_area_2d) * part.chart.area_scale();
    tot_d += CGAL::to_double(part.area_2d) * part.chart.area_scale();
  }
  bp.fraction_exact = coplanar;
  if (coplanar) {
    bp.fraction = vis / tot;
    bp.fraction_value = CGAL::to_double(bp.fraction);
  } else {
    bp.fraction_value = tot_d > 0 ? vis_d / tot_d : 0;
  }
  const bool none_visible = vis == 0, all_visible = vis == tot;
  bp.light_class = none_visible ? LightClass::Umbra : (all_visible ? LightClass::Lit : LightClass::Penumbra);
  bp.blockers.assign(blockers.begin(), blockers.end());
  return bp;
}

bool boxes_meet(const Box3& a, const Box3& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

}  // namespace

Backprojection backproject(const Scene& scene, const TriangleIndex& index, const std::vector<int>& light,
                           const RationalPoint3& p) {
  return backproject_with(scene, light, p,
                          [&](std::size_t, const Box3& box) { return index.triangles_meeting_box(box); });
}

Backprojection backproject(const Scene& scene, const std::vector<int>& light, const RationalPoint3& p,
                           const ReceiverShaft& shaft) {
  if (shaft.candidates.size() != light.size())
    throw std::invalid_argument("backproject: the shaft was built for another light");
  return backproject_with(scene, light, p, [&](std::size_t k, const Box3& box) {
    // Per point: only the shaft's triangles whose box meets the box of p and the light triangle (a triangle
    // meeting conv(p ∪ L) meets that box).
    std::vector<std::int64_t> out;
    const auto& cand = shaft.candidates[k];
    const auto& boxes = shaft.boxes[k];
    for (std::size_t i = 0; i < cand.size(); ++i)
      if (boxes_meet(boxes[i], box)) out.push_back(cand[i]);
    return out;
  });
}

RationalPoint3 interior_point(const PlaneChart& chart, const VisiblePolygon& piece) {
  std::vector<std::array<Exact, 2>> outer;
  std::vector<std::vector<std::array<Exact, 2>>> loops;
  for (const auto& v : piece.outer) outer.push_back(chart.to_2d(v));
  loops.push_back(outer);
  for (const auto& h : piece.holes) {
    std::vector<std::array<Exact, 2>> l;
    for (const auto& v : h) l.push_back(chart.to_2d(v));
    loops.push_back(std::move(l));
  }
  // A horizontal line y = y0 strictly between the lowest outer vertex and the next vertex height (of any
  // loop) crosses the polygon and passes through no vertex.
  std::vector<Exact> ys;
  for (const auto& l : loops)
    for (const auto& v : l) ys.push_back(v[1]);
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  Exact ymin = outer.front()[1], ymax = ymin;
  for (const auto& v : outer) ymin = std::min(ymin, v[1]), ymax = std::max(ymax, v[1]);
  // First gap of distinct vertex heights inside (ymin, ymax).
  auto it = std::upper_bound(ys.begin(), ys.end(), ymin);
  if (it == ys.end()) throw std::logic_error("interior_point: degenerate polygon");
  const Exact y0 = (ymin + *it) / 2;
  std::vector<Exact> xs;
  for (const auto& l : loops)
    for (std::size_t k = 0; k < l.size(); ++k) {
      const auto& a = l[k];
      const auto& b = l[(k + 1) % l.size()];
      if ((a[1] < y0) != (b[1] < y0)) xs.push_back(a[0] + (y0 - a[1]) * (b[0] - a[0]) / (b[1] - a[1]));
    }
  std::sort(xs.begin(), xs.end());
  if (xs.size() < 2) throw std::logic_error("interior_point: no crossing");
  // Crossings alternate outside/inside (no vertex on the line); the first pair bounds an inside interval.
  return chart.to_3d((xs[0] + xs[1]) / 2, y0);
}

}  // namespace exactvis::shadows
