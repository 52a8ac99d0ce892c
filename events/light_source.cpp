#include "events/light_source.hpp"

#include "kernel/predicates.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace exactvis {
namespace {

double parse_coordinate(const std::string& s, const std::string& spec) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  while (used < s.size() && std::isspace(static_cast<unsigned char>(s[used]))) ++used;
  if (s.empty() || used != s.size() || !std::isfinite(v))
    throw std::invalid_argument("--light '" + spec + "': '" + s + "' is not a finite number");
  return v;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep)) out.push_back(item);
  if (!s.empty() && s.back() == sep) out.push_back("");
  return out;
}

}  // namespace

LightSource select_light(Scene& scene, const std::string& spec) {
  LightSource light;
  for (int oi = 0; oi < static_cast<int>(scene.objects.size()); ++oi) {
    if (scene.objects[oi].name != spec) continue;
    for (int ti = 0; ti < static_cast<int>(scene.triangles.size()); ++ti)
      if (scene.triangles[ti].object == oi) light.triangles.push_back(ti);
    light.name = spec;
    if (light.triangles.empty()) throw std::invalid_argument("--light '" + spec + "': object has no triangles");
    return light;
  }
  if (spec.find(',') == std::string::npos)
    throw std::invalid_argument("--light '" + spec + "': no scene object has this name, and it is not a polygon "
                                "'x,y,z;x,y,z;x,y,z'");
  std::vector<Point3> pts;
  for (const auto& p : split(spec, ';')) {
    const auto c = split(p, ',');
    if (c.size() != 3)
      throw std::invalid_argument("--light '" + spec + "': point '" + p + "' needs 3 comma-separated coordinates");
    pts.push_back({parse_coordinate(c[0], spec), parse_coordinate(c[1], spec), parse_coordinate(c[2], spec)});
  }
  if (pts.size() < 3) throw std::invalid_argument("--light '" + spec + "': a polygon needs at least 3 points");
  for (std::size_t k = 1; k + 1 < pts.size(); ++k)
    if (collinear(pts[0], pts[k], pts[k + 1]))
      throw std::invalid_argument("--light '" + spec + "': fan triangle " + std::to_string(k) + " has zero area");
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
