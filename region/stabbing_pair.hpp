#pragma once
// Reduction of a source polygon S and a target triangle T to "stabbing pairs" (S', T'):
// S' = S on one side of plane(T), T' = T on one side of plane(S) (at most 4 pairs). Then every segment from
// S' to T' crosses plane(S) and plane(T) in a fixed direction, the directed lines through relint S' then
// relint T' are exactly the real lines of the open cone {side(x, e) > 0 for every oriented edge e of S' and
// T'}, and such a line meets the closed wedge between the two planes exactly in its segment from S' to T'
// (docs/theory.md §5.2). Parts of S in plane(T) (or of T in plane(S)) carry only a measure-zero set of
// segments and are dropped.
#include "region/convex_polygon_3.hpp"

#include <array>

namespace exactvis::region {

struct StabbingPair {
  Polygon3 source;                              // S': convex, positive area
  Polygon3 target;                              // T': convex, positive area (a piece of T)
  Plane3 source_plane;                          // plane(S), value > 0 on T' side
  Plane3 target_plane;                          // plane(T), value > 0 on S' side
  std::vector<PluckerLine<Exact>> edge_lines;   // oriented edges of S' and T': stabbers have side(x, e) > 0
};

// The pairs of a source polygon and a target triangle (as the polygon overload with a triangle target).
std::vector<StabbingPair> stabbing_pairs(const Polygon3& source, const std::array<RationalPoint3, 3>& target);

// The same for a convex target polygon of positive area (e.g. a face of a box, docs/theory.md §5.8): the
// construction and its properties above hold for any convex polygon, not only triangles. An empty list when
// either polygon is degenerate.
std::vector<StabbingPair> stabbing_pairs(const Polygon3& source, const Polygon3& target);

}  // namespace exactvis::region
