#pragma once
// Independent oracles for aspect graphs (no exactvis headers; GMP rationals only).
//
// - convex_*_aspect: the triangles of a closed convex model seen from a viewpoint, by casting a segment
//   from each triangle's centroid towards the viewer and testing it against every other triangle (a
//   different method from the code under test, which uses plane signs). For a closed convex model this is
//   exact: a triangle whose plane faces the viewer strictly is seen whole, one facing away is hidden by the
//   opposite side, one seen edge-on has a null image (not in the aspect).
// - great_circle_counts: vertices and arcs of the arrangement of the great circles orthogonal to given
//   normals, counted directly (distinct intersection directions, points per circle), the faces by Euler's
//   formula F = 2 - V + E, and whether the arrangement is simple (every vertex on exactly two circles).
// - plane_arrangement_is_simple: no two planes parallel, no three through a line, no four through a point.
#include "oracles/rational_geometry.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace oracle {

using OTriangle = std::array<QVec, 3>;

// Orthographic: the viewer at infinity along +d (d != 0). Indices of the triangles seen.
std::vector<int> convex_direction_aspect(const std::vector<OTriangle>& model, const QVec& d);
// Perspective: the viewer at point p (outside the closed model).
std::vector<int> convex_point_aspect(const std::vector<OTriangle>& model, const QVec& p);

// Any model whose triangles meet only in shared corners and edges (no crossings, no coplanar overlaps):
// the triangles seen with positive measure from direction d (the viewer at infinity along +d), by exact
// vertical-slab decomposition of the projection along d: t is seen iff some sample point strictly inside
// t's projection, taken in every trapezoid between consecutive projected edges of every slab between
// consecutive event abscissae (projected corners and edge crossings), has no other triangle in front of t
// (depths compared exactly). A region of positive area seen contains a whole trapezoid; a trapezoid
// crosses no edge, so its points are all seen or all hidden. Two-sided triangles; edge-on ones have no image.
std::vector<int> direction_aspect(const std::vector<OTriangle>& model, const QVec& d);

// Any model whose triangles meet only in shared corners and edges: the triangles seen with positive measure
// from the point p (not on any triangle), by a method of its own: for each triangle t with p off its plane,
// every other triangle is clipped exactly to the pyramid conv(p, t) and projected centrally from p onto t's
// plane (its shadow there, a convex polygon); t is seen iff a sample point strictly inside t, taken in every
// trapezoid of the vertical-slab decomposition of t's and the shadows' edges, lies in no shadow. (The hidden
// part of t is the union of the shadows up to their boundaries, a null set; a trapezoid crosses no edge.)
std::vector<int> point_aspect(const std::vector<OTriangle>& model, const QVec& p);

struct GreatCircleCounts {
  std::int64_t circles = 0, vertices = 0, arcs = 0, faces = 0;
  bool simple = true;
};
GreatCircleCounts great_circle_counts(const std::vector<QVec>& normals);

// Planes n . x = c.
bool plane_arrangement_is_simple(const std::vector<std::pair<QVec, mpq_class>>& planes);

}  // namespace oracle
