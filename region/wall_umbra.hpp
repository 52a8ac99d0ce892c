#pragma once
// The occlusion proof of method `conservative` in 2.5D (docs/theory.md §5.10): seed 001's factorization of
// from-region visibility into a horizontal component (2D footprints, seen from above) and a vertical one
// (the umbra in each vertical "directional plane"), here for one wall rectangle and decided exactly.
//
// A target region R (a triangle or a box: its xy projection inside conv(Q_1..Q_k), its z inside
// [z_lo, z_hi]) is hidden from the closed cell C by the closed wall W = [a, b] x [w_lo, w_hi] when
//  (horizontal) the cell's xy rectangle and every Q_j lie strictly on opposite sides of the line ab, and
//   every segment from a cell corner to a Q_j meets the segment [a, b]: then every segment from C to R
//   crosses [a, b] in its projection, at a parameter lambda in [lambda_min, lambda_max] inside (0, 1);
//  (vertical) the height of such a crossing, (1 - lambda) z_p + lambda z_q, lies in [w_lo, w_hi] for all
//   lambda in that range and all heights z_p of the cell and z_q of R (linear: checked at the ends).
// Then every segment from C to R meets W (a union of closed scene triangles) at an interior point, so R is
// hidden: a proof, never an estimate. lambda = A / (A + B) with A, B the distances of the two endpoints'
// projections to the line ab: its extremes come from the extremes of A over the cell's corners and of B over
// the Q_j (linear functionals), so no square roots appear.
#include "region/convex_polygon_3.hpp"
#include "region/extruded_scene.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace exactvis::region {

// A target region in this test's terms: xy points whose convex hull contains its projection, and its z range.
struct UmbraTarget {
  std::vector<Point3> points;  // only x, y are used
  double z_lo = 0, z_hi = 0;
};

// The cell and the wall as prepared once per (cell, wall) in doubles: a proposal filter only (it may
// reject a wall that would pass, never is its acceptance final: wall_hides_exactly decides).
struct WallFromCell {
  bool usable = false;   // the cell's xy rectangle is strictly on one side of the wall's line (in doubles)
  double side = 0;       // +1 or -1: the sign of the line functional on the cell
  double a_min = 0, a_max = 0;  // extremes of side * f over the cell corners (f(p) = (b - a) x (p - a))
};
WallFromCell prepare_wall(const WallRectangle& wall, const Box3& cell_approx);

// Double-precision version of the test (a proposal: true means "worth the exact test").
bool wall_may_hide(const WallRectangle& wall, const WallFromCell& prepared, const Box3& cell_approx,
                   const UmbraTarget& target);

// The exact test described above. Exact rational arithmetic throughout; cost O(k) products for k points.
bool wall_hides_exactly(const WallRectangle& wall, const RationalBox3& cell, const UmbraTarget& target);

// Umbra fusion of two adjacent walls (docs/theory.md §5.10, "Two walls"): R is hidden from C by W1 ∪ W2 when
// their closed footprint segments share a point (a building's corner, adjacent facades), the cell and every
// Q_j lie strictly on opposite sides of each wall's line, the vertical condition holds for each wall with its
// own lambda range, and every segment from a cell corner to a Q_j meets [a1, b1] or [a2, b2]. Then every
// segment from C to R meets W1 or W2 at an interior point (the proof in theory §5.10), though neither wall
// alone need hide R. Exact; cost O(k) products. wall_pair_may_hide is its double proposal (without the
// footprint contact, which callers choose by shared endpoints).
bool wall_pair_hides_exactly(const WallRectangle& w1, const WallRectangle& w2, const RationalBox3& cell,
                             const UmbraTarget& target);
bool wall_pair_may_hide(const WallRectangle& w1, const WallFromCell& p1, const WallRectangle& w2,
                        const WallFromCell& p2, const Box3& cell_approx, const UmbraTarget& target);

// Umbra fusion along a chain of walls (docs/theory.md §5.10, "A chain of walls"): R is hidden from C by
// W_1 ∪ ... ∪ W_m when the cell and every Q_j lie strictly on opposite sides of each wall's line with the
// vertical condition for each wall (its own lambda range), every segment from a cell corner to a Q_j meets
// some footprint, and the walls are joined by links, each either a contact (the closed footprints share a
// point: a facade run with its corners) or a view overlap (from every point of the cell's footprint and of
// conv(Q_j), some ray meets both footprints: an endpoint of one is seen in front of or behind the other,
// so the gap between them is closed as seen from both ends: two buildings overlapping across a street).
// (The two-wall theorem is the case m = 2 with a contact.) `links` are pairs of indices into `walls` the
// caller proposes; each is checked exactly, those that fail are dropped, and the answer is true when the
// walls joined by the links that hold include a chain that meets every corner-to-Q_j segment.
// Exact; cost O(m k) products plus O(links) footprint contacts. An empty or unlinked chain gives false.
bool wall_chain_hides_exactly(const std::vector<WallRectangle>& walls,
                              const std::vector<std::pair<std::size_t, std::size_t>>& links, const RationalBox3& cell,
                              const UmbraTarget& target);
// Double proposals: one wall's side and height conditions ((i) and (iii)) and whether some cell-corner-to-Q_j
// segment crosses its footprint (a wall no such segment crosses adds nothing to a chain but its contacts);
// and the chain's covering condition (every corner-to-Q_j segment crosses some footprint).
bool wall_may_join_chain(const WallRectangle& wall, const WallFromCell& prepared, const Box3& cell_approx,
                         const UmbraTarget& target);
bool wall_chain_may_cover(const std::vector<WallRectangle>& walls, const Box3& cell_approx, const UmbraTarget& target);
// Double proposal of a view-overlap link between two walls (the exact one is inside wall_chain_hides_exactly).
bool walls_views_may_overlap(const WallRectangle& u, const WallRectangle& v, const Box3& cell_approx,
                             const UmbraTarget& target);

}  // namespace exactvis::region
