#pragma once
// Do a model's triangles meet only in shared corners and edges (docs/theory.md §10.9, the models of the
// general orthographic aspect graph: open surfaces, non-manifold ones and triangle soups included)?
//
// Corners are compared by exact coordinates (vertex ids need not be shared). Two distinct closed triangles t
// and u may meet only as follows, by the number of corners they share:
//   0: not at all;
//   1 (corner v): only at v, i.e. t's edge opposite v misses u and u's edge opposite v misses t (if the
//      intersection, a convex set holding v, held a second point, the part of the line of the two planes, or
//      of the common plane, beyond v inside both would end on one of the opposite edges inside the other);
//   2 (edge ab, third corners p of t and q of u): only along ab, i.e. not coplanar with p and q on one side of
//      ab (two distinct planes meet in ab's line, which each triangle meets in ab; in one plane, triangles on
//      both sides of ab meet in ab);
//   3: never (two equal triangles overlap).
// Every decision is an exact predicate on the input doubles (CGAL Epick); candidate pairs come from
// kernel/triangle_index (the closed triangles meeting each triangle, exact).
#include "kernel/scene.hpp"

#include <string>

namespace exactvis {

// Input: a scene. Output: "" when every triangle is non-degenerate and every two meet only in shared corners
// and edges; else one line without the file name naming the first offending triangle (or pair) by stable id.
// Cost: O(n log n) for the index, then O(1) exact predicates per pair of triangles that meet.
std::string triangle_contact_problem(const Scene& scene);

}  // namespace exactvis
