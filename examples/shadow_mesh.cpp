// The exact discontinuity mesh of an area light (a scene object, e.g. "lamp"): per receiver triangle its
// umbra, penumbra and lit faces, then the counts of `exactvis shadows --json`.
//   shadow_mesh SCENE.obj LIGHT_OBJECT
#include <exactvis/api/shadows.hpp>
#include <exactvis/events/light_source.hpp>
#include <exactvis/io/load_scene.hpp>

#include <iostream>
#include <optional>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: shadow_mesh SCENE LIGHT_OBJECT\n";
    return 2;
  }
  try {
    const exactvis::Scene scene = exactvis::load_scene(argv[1]);
    const std::optional<exactvis::LightSource> light = exactvis::light_from_object(scene, argv[2]);
    if (!light) throw std::invalid_argument(std::string("no object named ") + argv[2]);
    exactvis::shadows::ShadowOptions options;
    options.light = light->triangles;
    options.receivers = exactvis::api::parse_receivers(scene, "all", options.light);  // every other triangle
    const exactvis::shadows::ShadowResult result = exactvis::api::shadows(scene, options);
    for (const auto& r : result.receivers) {
      int umbra = 0, lit = 0;
      for (const auto& f : r.faces) {
        umbra += f.light_class == exactvis::shadows::LightClass::Umbra;
        lit += f.light_class == exactvis::shadows::LightClass::Lit;
      }
      std::cout << "receiver " << scene.triangles[r.triangle].id << ": " << r.faces.size() << " faces (umbra "
                << umbra << ", lit " << lit << ")\n";
    }
    std::cout << "counts " << exactvis::api::shadows_json(scene, result, options.light)["counts"].dump() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "shadow_mesh: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
