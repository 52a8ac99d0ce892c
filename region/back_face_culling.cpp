#include "region/back_face_culling.hpp"

#include "kernel/predicates.hpp"

#include <algorithm>
#include <utility>

namespace exactvis::region {

BackFaceCulling::BackFaceCulling(const PvsContext& context, const RationalBox3& cell) : context_(context) {
  corners_are_doubles_ = true;
  for (int i = 0; i < 8; ++i) {
    RationalPoint3& c = corners_[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k) {
      c[k] = (i >> k) & 1 ? cell.hi[k] : cell.lo[k];
      const double d = CGAL::to_double(c[k]);
      corners_d_[static_cast<std::size_t>(i)][k] = d;
      corners_are_doubles_ = corners_are_doubles_ && Exact(d) == c[k];
    }
  }
  const std::vector<ConvexSolid>& solids = context.solids();
  const std::size_t n = context.scene().triangles.size();
  solid_of_.assign(n, -1);
  known_ = std::make_unique<std::atomic<signed char>[]>(n);
  for (std::size_t t = 0; t < n; ++t) known_[t].store(0, std::memory_order_relaxed);
  for (std::size_t s = 0; s < solids.size(); ++s) {
    const ConvexSolid& solid = solids[s];
    // The closed cell misses the closed solid: their boxes are strictly apart on an axis (exact).
    bool apart = false;
    for (int k = 0; k < 3 && !apart; ++k)
      apart = cell.hi[k] < Exact(solid.box.lo[k]) || cell.lo[k] > Exact(solid.box.hi[k]);
    if (!apart) continue;
    any_ = true;
    for (const std::int64_t t : solid.triangles) solid_of_[static_cast<std::size_t>(t)] = static_cast<std::int32_t>(s);
  }
}

bool BackFaceCulling::hides_triangle(std::int64_t triangle) const {
  if (triangle < 0 || static_cast<std::size_t>(triangle) >= solid_of_.size()) return false;
  const std::int32_t s = solid_of_[static_cast<std::size_t>(triangle)];
  if (s < 0) return false;
  std::atomic<signed char>& known = known_[static_cast<std::size_t>(triangle)];
  const signed char k = known.load(std::memory_order_relaxed);
  if (k != 0) return k > 0;
  const bool hidden = decide(triangle, s);  // deterministic: a race only repeats the same work
  known.store(hidden ? 1 : -1, std::memory_order_relaxed);
  return hidden;
}

bool BackFaceCulling::decide(std::int64_t triangle, std::int32_t s) const {
  const Scene& scene = context_.scene();
  const SceneTriangle& st = scene.triangles[static_cast<std::size_t>(triangle)];
  const Point3 a = scene.corner(st, 0), b = scene.corner(st, 1), c = scene.corner(st, 2);
  if (collinear(a, b, c)) return false;
  // The solid's side of plane(T): T lies in a facet (a flat triangle in the boundary of a convex polytope lies
  // in one supporting plane), so the solid is on one closed side and any corner off the plane tells which.
  Sign inner = Sign::Zero;
  for (const Point3& x : context_.solids()[static_cast<std::size_t>(s)].corners)
    if ((inner = orient3d(a, b, c, x)) != Sign::Zero) break;
  if (inner == Sign::Zero) return false;
  for (std::size_t i = 0; i < 8; ++i) {
    const Sign side = corners_are_doubles_
                          ? orient3d(a, b, c, corners_d_[i])
                          : orient3d(to_rational(a), to_rational(b), to_rational(c), corners_[i]);
    if (side != Sign::Zero && side != inner) return false;  // a corner strictly in front: not proved
  }
  return true;
}

void BackFaceCulling::drop_back_faces(std::vector<ShaftOccluder>& occluders,
                                      const std::function<bool(std::int64_t)>& excluded) const {
  std::vector<std::pair<std::int32_t, bool>> solid_ok;  // solids met in this list: none of their triangles excluded
  auto available = [&](std::int32_t s) {
    if (!excluded) return true;
    for (const auto& [k, ok] : solid_ok)
      if (k == s) return ok;
    const std::vector<std::int64_t>& ts = context_.solids()[static_cast<std::size_t>(s)].triangles;
    const bool ok = std::none_of(ts.begin(), ts.end(), [&](std::int64_t t) { return excluded(t); });
    solid_ok.emplace_back(s, ok);
    return ok;
  };
  std::size_t w = 0;
  for (std::size_t i = 0; i < occluders.size(); ++i) {
    const std::int64_t t = occluders[i].triangle;
    const bool drop =
        !occluders[i].panel_loop && hides_triangle(t) && available(solid_of_[static_cast<std::size_t>(t)]);
    if (drop) continue;
    if (w != i) occluders[w] = std::move(occluders[i]);
    ++w;
  }
  occluders.resize(w);
}

}  // namespace exactvis::region
