#pragma once
// The light of light-restricted events: a named object of the scene, or a polygon appended to the scene.
// (The --light option text is parsed in apps/cli_util.hpp.)
#include "kernel/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace exactvis {

struct LightSource {
  std::vector<int> triangles;  // indices into Scene::triangles
  bool appended = false;       // true when a polygon was added to the scene
  std::string name;            // object name
};

// The scene object named exactly `name` as the light (its triangles), or std::nullopt when no object has
// that name. Throws std::invalid_argument("object has no triangles") for a named object without triangles.
std::optional<LightSource> light_from_object(const Scene& scene, const std::string& name);

// Appends the polygon `points` (planar or not, >= 3 points, fan-triangulated from its first point; every fan
// triangle must have non-zero area) to `scene` as object "light": its vertices get the next vertex ids in
// the order given, its triangles the next triangle ids (after the largest id and after faces_read). Returns
// the light. Throws std::invalid_argument ("a polygon needs at least 3 points", "fan triangle K has zero
// area") and leaves the scene unchanged then.
LightSource append_light_polygon(Scene& scene, const std::vector<Point3>& points);

}  // namespace exactvis
