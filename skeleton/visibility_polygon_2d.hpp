#pragma once
// Visibility polygon of a point in a bounded 2D scene, and the set of edges it sees.
#include "planar/scene2d.hpp"

#include <vector>

namespace exactvis {

// The regularized visibility region of q: the closure of the interior of the set of points p such that
// the segment qp meets no object interior (needles of measure zero are dropped, as CGAL's
// Regularization_category = true does). Vertices counterclockwise, exact, consecutive duplicates removed
// (collinear vertices may remain where the ray meets a vertex).
struct VisibilityPolygon2D {
  std::vector<Point2> vertices;
};

// Input: a scene with a frame (with_frame) and a point q in free space (not on a boundary, not inside an
// object). Throws std::invalid_argument otherwise. O(n log n) by one angular sweep.
VisibilityPolygon2D visibility_polygon(const Scene2D& scene, const Point2& q);

// Visibility polygons of many points at once, each exactly equal to visibility_polygon(scene, q), from one
// rotational sweep of all directions (skeleton/rotational_visibility_2d) in which the points are viewers
// that block nothing: O((n + K + m + total output) log n) for m points and K visible vertex pairs, instead
// of O(m n log n). Pays off for many points (the scene's K log n is shared). Same requirements as
// visibility_polygon (std::invalid_argument otherwise); equal points are allowed.
std::vector<VisibilityPolygon2D> visibility_polygons(const Scene2D& scene, const std::vector<Point2>& points);

// Ids of the edges of which q sees a part of positive length (the "aspect" of q), sorted. Same
// requirements as visibility_polygon. Frame edges are included if seen.
std::vector<int> visible_edges(const Scene2D& scene, const Point2& q);

}  // namespace exactvis
