#pragma once
// Brute-force oracles for the 2D visibility complex, with exact rationals (gmpxx) and none of exactvis's
// headers: bitangents in O(n^3), the first boundary point along a ray, the edges a point sees, and a
// generator of random polygonal scenes on an integer grid (degenerate on purpose: collinear vertices across
// objects, parallel edges).
#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace oracle2d {

struct Pt {
  mpq_class x, y;
};
bool operator==(const Pt& a, const Pt& b);
bool operator<(const Pt& a, const Pt& b);  // lexicographic

// A polygon: rings[0] outer boundary, rings[1..] holes; any orientation.
using Ring = std::vector<std::array<double, 2>>;
struct Polygon {
  std::vector<Ring> rings;
};

struct Bitangent {
  Pt a, b;               // a < b lexicographically
  int object_a, object_b;
  std::string kind;      // side (L/R) of object_a, then of object_b, w.r.t. the directed line a -> b
  bool end_a_infinite = false, end_b_infinite = false;
  Pt end_a, end_b;       // first boundary point beyond a (away from b) and beyond b
};

// All free bitangents: vertex pairs (p, q) whose open segment meets no boundary point and lies outside the
// objects, with each object lying in a closed half-plane of the line near p and near q. O(n^3).
std::vector<Bitangent> brute_force_bitangents(const std::vector<Polygon>& scene);

// True iff (x, y) is strictly inside some object. Boundary points are not inside.
bool inside_object(const std::vector<Polygon>& scene, const Pt& p);
bool on_boundary(const std::vector<Polygon>& scene, const Pt& p);

// The edges, as (lexicographically sorted) endpoint pairs, of which p sees a part of positive length.
// p must be in free space. O(n^2 log n) with exact rationals.
std::vector<std::array<Pt, 2>> brute_force_visible_edges(const std::vector<Polygon>& scene, const Pt& p);

// The maximal free segments on the line through p and q (which must meet no vertex): for each, the sorted
// pair of objects at its ends (-1 for infinity).
std::vector<std::array<int, 2>> free_segment_end_pairs(const std::vector<Polygon>& scene, const Pt& p, const Pt& q);

// p and q in the open free space: true iff the closed segment [p, q] meets no boundary and its midpoint is
// outside the objects.
bool open_segment_free(const std::vector<Polygon>& scene, const Pt& p, const Pt& q);

// Random scene of disjoint polygons on a grid of cells x cells (cell size 10, integer coordinates): convex
// polygons, star-shaped non-convex polygons, and rings with holes and islands. May be invalid (a star may
// self-intersect); callers validate and skip. `convex_only`: convex polygons only.
std::vector<Polygon> random_grid_scene(std::uint64_t seed, int cells, bool convex_only = false);

}  // namespace oracle2d
