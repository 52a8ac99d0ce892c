#pragma once
// The exact orthographic aspect graph of a closed solid whose front parts are convex (docs/theory.md §10.5):
// non-convex models such as an L-shaped prism or several disjoint convex bodies seen two at a time.
//
// With the front part P_t of every triangle t convex (aspect/closed_solid_fronts), t is seen with positive
// measure from the direction d iff d is strictly on t's outer side and some corner a of t has its line
// {a + s d} missing P_t, i.e. d is outside the cone K_a = cone(P_t - a). Each K_a is the intersection of
// the closed half-spaces of its supporting planes through a and two points of P_t; so the aspect is a
// function of the signs of d against finitely many central planes: the face planes and those supporting
// planes (all EV planes: a corner and an edge of the front part). The partition of the viewing sphere by
// their great circles (aspect/great_circle_arrangement, exact) over-refines the aspect partition; every cell's
// aspect is read off its sign vector (kept up to date while a depth-first walk crosses one circle at a time),
// and aspect/aspect_regions merges cells into regions.
#include "aspect/aspect_graph_3d.hpp"
#include "aspect/closed_solid_fronts.hpp"
#include "kernel/scene.hpp"

namespace exactvis {

// Input: the scene and its fronts (fronts.ok must be true). Output: the orthographic aspect graph (regions,
// adjacency with the EV events naming the circles of the common boundary, cell counts, and, when
// `with_cells`, every sphere cell's exact sample, sign vector and region in `sampled_cells`: O(m) memory per
// cell, for tests and pictures). Cost: m great circles (at most n + 3 n |V|^2 for n triangles, far fewer
// after merging equal planes), the O(m^2) cells of their arrangement, then per cell O(1 + the constraints on
// the circles crossed to reach it) updates of the aspect (one O(m) sign vector is evaluated, at the first face).
// `progress` (optional) receives the fraction done.
AspectGraph3 orthographic_aspect_graph(const Scene& scene, const ClosedSolidFronts& fronts,
                                       void (*progress)(double) = nullptr, bool with_cells = true);

// The number of distinct central planes (great circles) the partition uses; for cost estimates.
std::size_t orthographic_aspect_circles(const Scene& scene, const ClosedSolidFronts& fronts);

}  // namespace exactvis
