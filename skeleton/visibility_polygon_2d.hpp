#pragma once
// Visibility polygon of a point in a bounded 2D scene, and the set of edges it sees.
#include "skeleton/scene2d.hpp"

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

// Ids of the edges of which q sees a part of positive length (the "aspect" of q), sorted. Same
// requirements as visibility_polygon. Frame edges are included if seen.
std::vector<int> visible_edges(const Scene2D& scene, const Point2& q);

}  // namespace exactvis
