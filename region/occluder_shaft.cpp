#include "region/occluder_shaft.hpp"

namespace exactvis::region {

std::vector<Plane3> shaft_planes(const StabbingPair& pair) {
  std::vector<RationalPoint3> pts = pair.source;
  pts.insert(pts.end(), pair.target.begin(), pair.target.end());
  std::vector<Plane3> planes{pair.source_plane, pair.target_plane};
  auto consider = [&](const Polygon3& edges_of, const Polygon3& vertices_of) {
    for (std::size_t i = 0; i < edges_of.size(); ++i) {
      const auto& a = edges_of[i];
      const auto& b = edges_of[(i + 1) % edges_of.size()];
      for (const auto& c : vertices_of) {
        if (collinear(a, b, c)) continue;
        const Plane3 pl = plane_through(a, b, c);
        bool pos = false, neg = false;
        for (const auto& p : pts) {
          const int s = CGAL::sign(pl.value(p));
          pos |= s > 0;
          neg |= s < 0;
        }
        if (pos && neg) continue;
        planes.push_back(neg ? pl.flipped() : pl);
      }
    }
  };
  consider(pair.source, pair.target);
  consider(pair.target, pair.source);
  return planes;
}

namespace {

// A shaft plane with its coefficients also as intervals, for a filtered side test without conversions.
struct FilteredPlane {
  Plane3 exact;
  Interval a, b, c, d;
  explicit FilteredPlane(const Plane3& p)
      : exact(p), a(enclosing_interval(p.normal.x)), b(enclosing_interval(p.normal.y)),
        c(enclosing_interval(p.normal.z)), d(enclosing_interval(p.offset)) {}
  // Exact: is plane.value(x) > 0?
  bool positive(const Point3& x) const {
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const Interval v = a * x.x + b * x.y + c * x.z - d;
      if (v.inf() > 0) return true;
      if (v.sup() <= 0) return false;
    }
    return plane_side(exact, x) == Sign::Positive;
  }
};

}  // namespace

std::vector<ShaftOccluder> shaft_occluders(const Scene& scene, const std::vector<std::int64_t>& candidates,
                                           std::int64_t target, const StabbingPair& pair) {
  std::vector<FilteredPlane> planes;
  for (const auto& p : shaft_planes(pair)) planes.emplace_back(p);
  std::vector<ShaftOccluder> out;
  for (const std::int64_t idx : candidates) {
    if (idx == target) continue;
    const auto& st = scene.triangles[idx];
    bool culled = false;
    for (const auto& pl : planes) {
      // Entirely on the closed outer side of a supporting plane: meets the shaft at most in that plane,
      // which only a measure-zero set of stabbing segments touches (docs/theory.md §5.2).
      if (!pl.positive(scene.corner(st, 0)) && !pl.positive(scene.corner(st, 1)) && !pl.positive(scene.corner(st, 2))) {
        culled = true;
        break;
      }
    }
    if (culled) continue;
    const auto tri = triangle_points(scene, idx);
    Polygon3 clipped = clip_polygon({tri[0], tri[1], tri[2]}, pair.source_plane);
    clipped = clip_polygon(clipped, pair.target_plane);
    if (is_degenerate(clipped)) continue;
    if (lies_in_plane(clipped, pair.source_plane) || lies_in_plane(clipped, pair.target_plane)) continue;
    ShaftOccluder occ;
    occ.triangle = idx;
    occ.corners = tri;
    occ.corners_d = {scene.corner(st, 0), scene.corner(st, 1), scene.corner(st, 2)};
    for (std::size_t i = 0; i < clipped.size(); ++i)
      occ.edges.push_back(side_functional(line_through(clipped[i], clipped[(i + 1) % clipped.size()])));
    out.push_back(std::move(occ));
  }
  return out;
}

}  // namespace exactvis::region
