#pragma once
// The exact PVS of one view cell (method `exact` of `exactvis pvs`): every scene triangle decided exactly.
//
// A BVH over the triangles (region/triangle_bvh.hpp) is traversed from the root, front to back from the cell
// (the nearer child first). A node is culled with no line-space query when a virtual occluder blocks it (a
// box proved hidden earlier in the traversal, region/virtual_occluders.hpp: every segment from the cell to
// the node meets it), or when one wall or one convex solid proves it hidden
// (region/single_occluder_culling.hpp, the proofs of method `conservative`); a node whose box Embree rays do
// not obviously reach gets the exact hidden-box test (region/box_visibility.hpp) with the triangles outside
// its subtree as occluders. A hidden box hides its whole subtree (docs/theory.md §5.8), and a box proved
// hidden by a wall, a solid or the box test joins the virtual occluders (at most options.virtual_occluders,
// larger and nearer first). The triangles of the leaves reached are tested against the virtual occluders,
// then decided one by one on the other cores: Embree rays from the cell to T propose witnesses, and the
// first one that passes the exact check (region/ray_witness.hpp) makes T visible; otherwise a
// single-occluder proof may show T hidden; otherwise the exact from-region query of
// region/from_region_visibility.hpp decides T (visible with an exactly checked witness, or proved hidden).
// So the answer equals `exactvis visible --cell ... --triangles all` on every triangle (docs/theory.md §5.7).
#include "region/cell_pvs.hpp"

namespace exactvis::region {

// Input: the context, a cell with lo < hi in every coordinate (else std::invalid_argument), options
// (threads outside 0 .. kMaxThreads: std::invalid_argument). Output: the visible triangles (sorted by
// index, each with a witness) and counters. Answers, witnesses and counters do not depend on the thread
// count (each triangle's random choices are seeded by options.query.seed and its index; the traversal and
// its virtual occluders run on one thread, only the leaves' triangles are decided in parallel). Cost: n ray
// batches plus one exact query per triangle the rays do not accept and no single occluder hides, minus the
// culled subtrees, plus the box tests and the single-occluder tests (double tests per usable wall / solid).
CellPvs exact_cell_pvs(const PvsContext& context, const RationalBox3& cell, const PvsOptions& options);

// The same with coherence between neighbouring cells (seed 004; docs/theory.md §5.8): `previous` (may be null)
// is the answer of a neighbouring cell of the same scene; each of its visible triangles' witnesses proposes
// witnesses here (its cell point pulled into this cell, or translated by the offset between the cells), tried
// before the Embree rays and accepted only through the exact check of region/ray_witness.hpp. The visible set
// is the same as without `previous` (a proposal only ever accepts a triangle that is visible); witnesses and
// counters then depend on `previous` (stats.neighbour_tries / neighbour_hits count the proposals and hits).
CellPvs exact_cell_pvs(const PvsContext& context, const RationalBox3& cell, const PvsOptions& options,
                       const CellPvs* previous);

}  // namespace exactvis::region
