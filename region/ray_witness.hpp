#pragma once
// Float ray casts that *propose* witnesses of from-cell visibility, and the exact re-check that accepts
// them (docs/theory.md §5.7: floats accept only through an exact check). Used by the exact PVS to decide
// the obviously visible triangles before any line-space query.
#include "region/cell_pvs.hpp"

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

namespace exactvis::region {

// Every triangle whose bounding box meets the closed segment [p, q] (and possibly a few more): the segment is
// cut into pieces of length about `piece_length` (at most 64) and the index is asked for the box of each
// piece (interval bounds, so the boxes cover the exact segment). Indices into Scene::triangles, sorted,
// without repeats. Cost: O(pieces (log n + k)), following the segment rather than its bounding box.
std::vector<std::int64_t> segment_candidates(const TriangleIndex& index, const RationalPoint3& p,
                                             const RationalPoint3& q, double piece_length);

// The exact acceptance test of a proposed witness (docs/theory.md §5.7): p in the open cell, q in the
// relative interior of triangle `target`, and the closed segment [p, q] meets no other closed scene triangle.
// Then every segment near (p, q) is free too (the occluders are closed and at positive distance), so T is
// visible with positive measure; (p, q) is in particular a witness of §5.1. Exact predicates only.
bool is_robust_cell_witness(const PvsContext& context, const RationalBox3& cell, std::int64_t target,
                            const Witness& w);

// Up to `rays` Embree rays from random points of the cell to random points of relint(target) (exact
// barycentric points, positive weights); the first ray Embree reports unblocked whose segment passes
// is_robust_cell_witness is returned, with its endpoints rounded to doubles when the rounded segment passes too.
// std::nullopt proves nothing (the caller then runs the exact query). `cell_approx` is the cell in doubles
// (any nearby box: samples outside the exact cell are skipped). Deterministic for a given rng state.
std::optional<Witness> ray_witness(const PvsContext& context, const RationalBox3& cell, const Box3& cell_approx,
                                   std::int64_t target, int rays, std::mt19937_64& rng);

}  // namespace exactvis::region
