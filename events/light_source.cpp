#include "events/light_source.hpp"

#include "kernel/predicates.hpp"

#include <algorithm>
#include <stdexcept>

namespace exactvis {

std::optional<LightSource> light_from_object(const Scene& scene, const std::string& name) {
  for (int oi = 0; oi < static_cast<int>(scene.objects.size()); ++oi) {
    if (scene.objects[oi].name != name) continue;
    LightSource light;
    for (int ti = 0; ti < static_cast<int>(scene.triangles.size()); ++ti)
      if (scene.triangles[ti].object == oi) light.triangles.push_back(ti);
    light.name = name;
    if (light.triangles.empty()) throw std::invalid_argument("object has no triangles");
    return light;
  }
  return std::nullopt;
}

LightSource append_light_polygon(Scene& scene, const std::vector<Point3>& pts) {
  if (pts.size() < 3) throw std::invalid_argument("a polygon needs at least 3 points");
  for (std::size_t k = 1; k + 1 < pts.size(); ++k)
    if (collinear(pts[0], pts[k], pts[k + 1]))
      throw std::invalid_argument("fan triangle " + std::to_string(k) + " has zero area");
  LightSource light;
  const int base = static_cast<int>(scene.vertices.size());
  std::int64_t next_id = scene.triangles.empty() ? 0 : scene.triangles.back().id + 1;
  next_id = std::max<std::int64_t>(next_id, scene.faces_read);
  const int object = static_cast<int>(scene.objects.size());
  scene.objects.push_back({"light"});
  scene.vertices.insert(scene.vertices.end(), pts.begin(), pts.end());
  for (std::size_t k = 1; k + 1 < pts.size(); ++k) {
    light.triangles.push_back(static_cast<int>(scene.triangles.size()));
    scene.triangles.push_back({next_id++, {base, base + static_cast<int>(k), base + static_cast<int>(k) + 1}, object});
  }
  light.appended = true;
  light.name = "light";
  return light;
}

}  // namespace exactvis
