// The 2D visibility complex of two triangles and a square: free bitangents, edges and faces, exact.
//   complex_2d            (the scene is built in code; load_scene2d("scene.json") reads one from a file)
#include <exactvis/api/complex2d.hpp>

#include <iostream>

int main() {
  using exactvis::Exact;
  using exactvis::Point2;
  auto ring = [](std::vector<std::pair<int, int>> pts) {
    exactvis::PolygonInput2D p;
    p.rings.emplace_back();
    for (auto [x, y] : pts) p.rings.back().emplace_back(Exact(x), Exact(y));
    return p;
  };
  try {
    const exactvis::Scene2D scene = exactvis::make_scene2d(
        {ring({{0, 0}, {2, 0}, {1, 2}}), ring({{4, 1}, {6, 1}, {5, 3}}), ring({{1, 4}, {3, 4}, {3, 6}, {1, 6}})});
    const exactvis::VisibilityComplex2D cx = exactvis::visibility_complex(scene);
    std::cout << cx.graph.bitangents.size() << " free bitangents, " << cx.edges.size() << " edges, "
              << cx.faces.size() << " faces\n";
    const nlohmann::ordered_json j = exactvis::api::complex2d_json(scene, cx);  // as `complex2d --json`
    std::cout << "first bitangent: " << j["bitangents"][0].dump() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "complex_2d: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
