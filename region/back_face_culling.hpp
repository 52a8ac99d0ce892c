#pragma once
// Back faces of closed convex solids (docs/theory.md §5.8, "Back faces of closed convex solids"): a triangle T of
// a closed convex solid P (region/convex_occluder.hpp) is hidden from a closed cell C that is strictly apart from
// P and lies entirely on the closed inner side of plane(T). Every segment from a point of C off plane(T) to a
// point of relint T ends inside P's facet, so just before its end it runs through the interior of P, which it
// must have entered through the surface at a point of the open segment off plane(T): a closed triangle of P
// other than T blocks it. The segments from C ∩ plane(T) lie in plane(T): a null set of lines.
//
// Used by method `exact` before a triangle's rays and exact query (the crowns and trunks of a forest: about half
// of their triangles face away from a cell). It only ever hides: a triangle it does not hide goes on as before.
#include "region/cell_pvs.hpp"
#include "region/occluder_shaft.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace exactvis::region {

class BackFaceCulling {
 public:
  // Input: the context (its solids, context.solids(), are built on first use) and a cell with lo < hi.
  // Prepares, per scene triangle, the solid it belongs to when that solid is strictly apart from the cell
  // (bounding boxes strictly apart on an axis, exact). Cost: O(n + triangles of the solids).
  BackFaceCulling(const PvsContext& context, const RationalBox3& cell);

  // False when no triangle can be hidden this way (no solid apart from the cell).
  bool any() const { return any_; }

  // True proves the triangle hidden from the cell (its solid is apart from the cell and the 8 cell corners lie
  // on the closed inner side of its plane); false means not proved. Exact: orient3d of the cell corners against
  // the triangle (double corners: the filtered predicate; rational corners: GMP). Thread-safe. Cost: at most
  // 8 + the solid's corners orientation tests, once per triangle (the answer is cached).
  bool hides_triangle(std::int64_t triangle) const;

  // Removes from the shaft occluders of a stabbing pair whose source lies in the cell those that are scene
  // triangles for which hides_triangle holds and whose solid has no triangle for which `excluded` (may be
  // empty) holds; the order of the others is kept. A line of the pair's cone that meets such a back face B
  // inside the open segment enters the solid before, through a closed triangle of the solid off plane(B) that
  // is an occluder of the pair (or the lines doing so form a null set), so the CSG's free set changes by a null
  // set only (docs/theory.md §5.8): the same answers. Cost: one cached test per occluder, plus one pass over
  // a solid's triangles per solid met when `excluded` is set.
  void drop_back_faces(std::vector<ShaftOccluder>& occluders, const std::function<bool(std::int64_t)>& excluded) const;

 private:
  const PvsContext& context_;
  std::array<RationalPoint3, 8> corners_;
  std::array<Point3, 8> corners_d_;  // the same, when every coordinate is a double exactly
  bool corners_are_doubles_ = false;
  bool any_ = false;
  std::vector<std::int32_t> solid_of_;  // per scene triangle: index into context.solids() (apart), or -1
  std::unique_ptr<std::atomic<signed char>[]> known_;  // per triangle: 0 not yet decided, 1 hidden, -1 not proved
  bool decide(std::int64_t triangle, std::int32_t solid) const;
};

}  // namespace exactvis::region
