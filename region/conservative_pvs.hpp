#pragma once
// The conservative PVS of one view cell (method `conservative` of `exactvis pvs`, issue #12): a fast
// baseline that can only overestimate (docs/theory.md §5.10).
//
// A triangle is left out only with a proof that it is hidden; every other triangle is listed (without a
// witness: "listed" means "not proved hidden", not "visible"). So the conservative PVS contains the exact
// PVS, and validate reports its extra triangles as false visible.
// - 2.5D scenes (region/extruded_scene.hpp): seed 001's factorization, one wall rectangle at a time
//   (region/wall_umbra.hpp): the target's top-view footprint in the wall's 2D umbra from the cell's
//   footprint, and the vertical umbra bound in every directional plane. Walls come merged into maximal runs
//   (a facade strip, a column between windows), which is the vertical/horizontal umbra merging of a wall's
//   own pieces. When no single wall proves a target hidden, pairs of walls meeting at a footprint endpoint
//   (building corners) are tried (wall_pair_hides_exactly: umbra fusion across two adjacent walls), then
//   chains of walls linked by contacts or by view overlaps (wall_chain_hides_exactly: facade runs with
//   their corners, buildings overlapping across a street).
//   The scene's triangle hierarchy (region/triangle_bvh.hpp) is traversed from the root: a
//   node box proved hidden by one wall hides its whole subtree.
// - Other scenes (fallback): the same wall proofs for the scene's vertical rectangles, when it has any
//   (e.g. tree trunks), then single-occluder culling by the scene's closed convex solids
//   (region/convex_occluder.hpp: tree crowns, closed boxes), used only when both the cell and the target
//   box are strictly apart from the solid's box, so the blocking point is inside the segment. The solids are
//   tried in 2.5D scenes too (after the walls); cells carry no view frustum, so there is no frustum culling.
// - Before those, back faces of closed convex solids (region/back_face_culling.hpp): a triangle of a solid apart
//   from the cell with the whole cell on the solid's side of its plane is hidden by its own solid.
// Floats only choose which wall to try (a double version of the test); each proof is exact.
#include "region/cell_pvs.hpp"
#include "region/single_occluder_culling.hpp"

namespace exactvis::region {

// Input: the context, a cell (lo < hi, else std::invalid_argument), options (threads, hierarchy). Output:
// every triangle not proved hidden (sorted by index, no witnesses); stats.culled = triangles proved
// hidden, stats.boxes_tested / boxes_culled = hierarchy nodes tested / proved hidden, stats.exact_queries =
// exact wall and solid tests run (each proposed by a double test), stats.visible = listed. Deterministic
// (answers and counters do not depend on the thread count). Cost: per tested node or triangle, one double
// test per wall and per solid whose box the cell-to-target segment passes: O((nodes + n) * (walls +
// solids)) double tests in the worst case (scan; the grid tests only the walls near each target's shaft),
// plus one exact test per proposal.
// `search` chooses how candidate occluders are found (region/single_occluder_culling.hpp: the 2D grid, or the
// scan of all, the reference with the same answers); with the grid a target's tests cover only the walls
// near its cell-to-target hull's top view and the solids near its centre segment.
CellPvs conservative_cell_pvs(const PvsContext& context, const RationalBox3& cell, const PvsOptions& options,
                              OccluderSearch search = OccluderSearch::grid);

}  // namespace exactvis::region
