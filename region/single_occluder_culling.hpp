#pragma once
// Single-occluder culling from one view cell: the exact proofs that a triangle or a BVH node box is hidden by
// ONE wall rectangle (region/wall_umbra.hpp, docs/theory.md §5.10), two walls meeting at a footprint endpoint
// (umbra fusion at a building's corner, wall_pair_hides_exactly, §5.10), a chain of walls joined end to end
// (a facade run with its corners, wall_chain_hides_exactly, §5.10) or ONE closed convex solid
// (region/convex_occluder.hpp, §5.9). Shared by method `conservative` (its only hidden test) and method
// `exact` (a cheap proof tried before Embree rays and the line-space query, §5.8).
//
// Floats only choose which wall or solid to try (a double version of each test); every "hidden" answer is an
// exact proof. The target is never hidden by a wall or solid it belongs to: a wall proof needs the target
// strictly on the far side of the wall's line, and a solid owning one of the target's triangles is skipped.
#include "region/cell_pvs.hpp"
#include "region/footprint_grid.hpp"
#include "region/solid_miss_filter.hpp"
#include "region/wall_umbra.hpp"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace exactvis::region {

// Which occluders a target's test tries (docs/theory.md §5.10, "Which walls are tried"). Both give the same
// answers (the grid skips only walls and solids that cannot hide the target); `scan` is the reference the
// tests and bench_pvs_methods compare with.
enum class OccluderSearch {
  grid,  // walls whose footprint box meets the top view of the cell-to-target hull (a 2D grid over the
         // footprints, region/footprint_grid.hpp), their corner partners, solids near the centre segment
  scan,  // every usable wall, corner pair and solid
};

class SingleOccluderCulling {
 public:
  // Input: the context (its walls, context.extruded().walls, and solids, context.solids(), are built on first
  // use) and a cell with lo < hi. Prepares the walls the cell is strictly on one side of and the solids
  // strictly apart from the cell, nearest first, and (search = grid) a 2D grid over each.
  // Cost: O(walls + solids) plus their sort.
  SingleOccluderCulling(const PvsContext& context, const RationalBox3& cell,
                        OccluderSearch search = OccluderSearch::grid);

  // False when no wall or solid can hide anything from this cell (then every test below answers false).
  bool any() const { return !usable_walls_.empty() || !usable_solids_.empty(); }

  // True proves that every segment from the closed cell to the closed triangle meets another scene triangle
  // at a point inside the segment (so the triangle is hidden, §5.1); false means not proved. `hint` is the
  // wall of the last proof nearby (or -1): tried first, updated on a wall proof. Thread-safe (hints are the
  // caller's). Cost (grid): one double test per wall whose footprint box meets the widened top view of the
  // cell-to-target hull (nearest first, stopping at the first proof), per corner pair with such a wall
  // (after the walls), per chain of such walls (after the pairs), and per solid near the segment between box
  // centres, plus an exact test per proposal.
  // Cost (scan): the same over every usable wall, pair and solid.
  bool hides_triangle(std::int64_t triangle, std::ptrdiff_t& hint) const;

  // The same for a BVH node of context.bvh(): true proves every triangle of the node hidden (the proving wall
  // or solid has no triangle inside the node).
  bool hides_node(const BvhNode& node, std::ptrdiff_t& hint) const;

  // Exact wall and solid tests run so far (each was proposed by a double test).
  std::int64_t exact_tests() const { return exact_tests_.load(); }

 private:
  template <class Owns>
  bool hides(const UmbraTarget& target, const Box3& target_box, const Owns& owns_triangle_of,
             std::ptrdiff_t& hint) const;

  bool try_pair(std::size_t w, std::size_t u, const UmbraTarget& target) const;
  // Chains (wall_chain_hides_exactly): the connected components, by shared footprint endpoints and by
  // directions overlapping as seen from the target's centre, of the
  // candidates that may join a chain for this target (wall_may_join_chain); those of 2 walls or more are
  // tried (a pair that touches was tried before and fails the same double covering test again).
  bool try_chains(const std::vector<std::size_t>& candidates, const UmbraTarget& target) const;

  const PvsContext& context_;
  RationalBox3 cell_;
  Box3 approx_;
  OccluderSearch search_;
  std::vector<WallFromCell> prepared_;
  std::vector<std::size_t> usable_walls_, usable_solids_;
  std::vector<std::pair<std::size_t, std::size_t>> corner_pairs_;  // walls sharing a footprint endpoint
  std::vector<std::vector<std::size_t>> partners_;  // per wall: its corner_pairs_ partners (grid search)
  std::vector<std::vector<std::size_t>> links_;     // per wall: usable walls sharing a footprint endpoint
  FootprintGrid wall_grid_, solid_grid_;  // items: positions in usable_walls_ / usable_solids_
  SolidMissFilter solid_filter_;           // grid search: certified rejection before the exact solid test
  mutable std::atomic<std::int64_t> exact_tests_{0};
};

}  // namespace exactvis::region
