#pragma once
// Witnesses of from-region visibility (docs/theory.md §5.4, §5.5): a segment from the source to the relative
// interior of the target whose open interior misses every closed occluder, found in a surviving cone of the
// line-set CSG (or, for a target inside a view cell, next to the target), checked exactly, and rounded to
// doubles when the rounded segment is still a witness.
#include "kernel/scene.hpp"
#include "region/candidate_finder.hpp"
#include "region/convex_polygon_3.hpp"
#include "region/real_line_test.hpp"
#include "region/stabbing_pair.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <vector>

namespace exactvis::region {

struct Witness {
  RationalPoint3 p;  // on the source
  RationalPoint3 q;  // in the relative interior of the target
};

// True iff the open segment (p, q) meets no candidate triangle other than `skip` (exact).
bool segment_is_free(const Scene& scene, const std::vector<std::int64_t>& candidates, const RationalPoint3& p,
                     const RationalPoint3& q, std::int64_t skip);

// The witness rounded to the nearest doubles, if that is still a valid witness (exact re-check: p on the
// source per `on_source`, q in relint T, open segment free); std::nullopt otherwise.
std::optional<Witness> round_witness(const Scene& scene, const CandidateFinder& candidates,
                                     const std::function<bool(const RationalPoint3&)>& on_source,
                                     std::int64_t triangle_index, const Witness& w);

// A real line of the open cone K (with its real-line test `test`), found by bisection between a point of K
// with positive and one with negative Plücker form, as the segment between its points on the pair's two
// planes: a directed line crossing relint S' and relint T' (it satisfies every constraint strictly).
// std::nullopt when the bisection finds none (the caller retries: `rng` varies the interior point). Exact.
std::optional<Witness> line_in_cone(const PolyhedralCone6& cone, const RealLineTest& test, const StabbingPair& pair,
                                    std::mt19937_64& rng);

// For a target triangle `tri` meeting the closed cell in `t_in` (positive area): a short segment from inside
// the cell to a random point of t_in, checked free against `cands` (docs/theory.md §5.5); std::nullopt after
// 64 attempts. Exact checks; `seed` fixes the sampling.
std::optional<Witness> witness_inside_cell(const Scene& scene, const std::vector<std::int64_t>& cands,
                                           const Polygon3& t_in, const std::array<RationalPoint3, 3>& tri,
                                           const RationalBox3& cell, std::int64_t target, std::uint64_t seed);

}  // namespace exactvis::region
