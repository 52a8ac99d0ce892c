#pragma once
// The exact aspect graph of a closed solid whose front parts are convex (aspect/closed_solid_fronts, the
// class of docs/theory.md §10.5) for perspective viewpoints on the plane Q = {z = H}: the partition of Q
// outside the solid by the traces of the EV event surfaces that are real for that class (theory §10.8).
//
// With P_t convex, triangle t is seen with positive measure from a point p outside the solid iff p is
// strictly on t's outer side and some corner a of t has the segment [a, p] missing P_t, i.e. p is outside
// U_a = {a + s (y - a) : y in P_t, s >= 1} (the shadow volume of P_t lit from a). U_a is the intersection of
// the closed half-spaces of the EV planes through a and an edge of P_t that support P_t (the cone from a)
// and of the facets of P_t facing a. So t's visibility on Q is a function of the sides of p against the
// trace of t's plane and the trace lines, in Q, of the planes bounding the convex polygon
// Q ∩ closure(H_t) ∩ (∩_a U_a); only the lines meeting that polygon (in an edge when it is 2D) are kept. The
// kept lines, clipped to a box holding all their crossings, go to an exact CGAL Arrangement_2 (segments over
// lazy exact rationals); every vertex, edge and face inside the box is a cell, its aspect read at an exact
// sample, cells with an empty aspect (inside the solid) dropped and the rest merged by aspect/aspect_regions.
#include "aspect/aspect_graph_3d.hpp"
#include "aspect/closed_solid_fronts.hpp"
#include "kernel/scene.hpp"

namespace exactvis {

// Input: the scene, its fronts (fronts.ok must be true, else std::invalid_argument) and the height H of the
// viewpoint plane z = H. Output: the aspect graph, view = ViewModel::Plane: regions of Q outside the solid
// (dimension 0 .. 2, samples (x, y, H) exact), adjacency with the EV events of the lines on the common
// boundary (a corner and a scene edge in its plane; a face plane's trace by the triangle's first vertex and
// opposite edge), cells of the partition per dimension; with `with_cells`, `circles` holds the trace lines
// as (A, B, C) for {A x + B y + C = 0} and `sampled_cells` every cell (region -1 inside the solid) with its
// sample and sign vector against those lines (for tests and pictures). Cost: per triangle one exact hull
// and O(k^2) exact signs for its k candidate constraints; then for L kept lines the O(L^2) cells of their
// arrangement, each read with O(L) exact signs (O(L^3) in all).
// `progress` (optional) receives the fraction done.
AspectGraph3 plane_aspect_graph(const Scene& scene, const ClosedSolidFronts& fronts, const Exact& height,
                                void (*progress)(double) = nullptr, bool with_cells = true);

// The same on any plane {normal . p = offset} (normal != 0, else std::invalid_argument): the partition is
// computed in the chart whose parameters (x, y) are the two coordinates other than normal's dominant axis k
// (its largest |component|; z, then x on ties), taken in increasing axis order, p_k solved for; `circles` are the trace
// lines in those parameters, samples are points of the plane. z = H is normal (0, 0, 1), offset H.
AspectGraph3 plane_aspect_graph(const Scene& scene, const ClosedSolidFronts& fronts, const Vec3<Exact>& normal,
                                const Exact& offset, void (*progress)(double) = nullptr, bool with_cells = true);

// The number of distinct trace lines the partition of z = H (or of {normal . p = offset}) uses; for cost
// estimates. Cost: the setup of plane_aspect_graph (no arrangement).
std::size_t plane_aspect_lines(const Scene& scene, const ClosedSolidFronts& fronts, const Exact& height);
std::size_t plane_aspect_lines(const Scene& scene, const ClosedSolidFronts& fronts, const Vec3<Exact>& normal,
                               const Exact& offset);

}  // namespace exactvis
