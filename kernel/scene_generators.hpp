#pragma once
// Deterministic scene generators for tests and benchmarks.
//
// Same (kind, triangles, seed) -> the same scene on every platform: std::mt19937_64 (fully specified by the
// standard) with our own integer mapping, and all coordinates are integers times 1/64 (exact doubles), so
// vertices shared within an object are shared indices and closed meshes have real connectivity.
#include "kernel/scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace exactvis {

// The kinds generate_scene accepts: "random", "town", "forest", "room".
const std::vector<std::string>& scene_generator_kinds();

// Input: kind (see above), triangles = requested count (10 .. 10^7 accepted), seed.
// Output: a scene with ids 0..n-1 (none dropped: no triangle is degenerate), one object per building / tree /
// piece of furniture / ground / room shell / triangle (random). The count is exactly `triangles` except for
// tiny requests below a kind's smallest scene (town 14, forest 24, room 24 triangles), which give that
// smallest scene. Throws std::invalid_argument for an unknown kind or a count out of range.
//   random: independent triangles in a box, each its own object.
//   town:   ground + a grid of box buildings whose walls have rectangular window openings (walls are
//           triangulated around the holes; roofs are fans), open at the bottom.
//   forest: ground + trees, each a closed box trunk and a subdivided octahedron crown meeting at one vertex.
//   room:   a closed box room (faces subdivided) with closed subdivided furniture boxes standing on the floor.
//   town, forest and room end with a "filler" triangle strip object (curb / path / rug) that absorbs the
//   remainder so the count is exact.
Scene generate_scene(const std::string& kind, std::int64_t triangles, std::uint64_t seed);

}  // namespace exactvis
