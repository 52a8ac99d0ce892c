#pragma once
// 2.5D scenes (issue #12, method `conservative`, seed 001 Leyvand et al. 2003): the exact detection rule and
// the wall rectangles the conservative method's proofs use (docs/theory.md §5.9).
//
// Rule: a scene is 2.5D when every triangle is either horizontal (its three z coordinates are equal) or one
// half of a vertical wall rectangle: two triangles whose xy projections lie on one segment [a, b] (exact
// 2D orientation = 0), whose corners are all among the four corners {a, b} x {z_lo, z_hi} and whose missing
// corners are opposite, so that their closed union is exactly the rectangle [a, b] x [z_lo, z_hi]. Footprint
// polygons extruded from a ground plane (walls split into rectangles, windows cut as grid holes; horizontal
// roofs and ground) are 2.5D by this rule; a sloped roof, a gable, a tree crown are not. All tests compare
// the input doubles exactly or use the filtered exact orientation; nothing is rounded.
#include "kernel/scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace exactvis::region {

// A closed vertical rectangle [a, b] x [z_lo, z_hi] (a < b lexicographically in (x, y); z_lo < z_hi) that is
// the union of closed scene triangles (so whatever meets it meets a scene triangle).
struct WallRectangle {
  double ax = 0, ay = 0, bx = 0, by = 0;  // footprint segment, exact input doubles
  double z_lo = 0, z_hi = 0;
};

struct ExtrudedScene {
  bool is_25d = false;  // every triangle horizontal or half of a wall rectangle
  std::string reason;   // when !is_25d: the first triangle that breaks the rule, e.g. "triangle id 7 is sloped"
  std::int64_t horizontal = 0;     // horizontal triangles
  std::int64_t wall_triangles = 0; // triangles paired into wall rectangles
  // The occluders: every paired rectangle, plus the maximal runs of rectangles merged along a common line
  // (equal z range, sharing an endpoint) and stacked on a common footprint (sharing a z value), and runs of
  // runs; overlapping rectangles are kept (each is a valid occluder). Found in any scene, 2.5D or not.
  std::vector<WallRectangle> walls;
};

// Input: any scene. Output: the rule's verdict and the wall rectangles. Cost: O(n log n) (hash maps).
ExtrudedScene detect_extruded_scene(const Scene& scene);

}  // namespace exactvis::region
