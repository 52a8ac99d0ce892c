// The potentially visible set of every cell of an NX x NY x NZ grid of view cells over a scene (exact, a
// witness segment per visible triangle), then the whole answer as `exactvis pvs --json` writes it.
//   pvs_grid SCENE.obj NX NY NZ
#include <exactvis/api/pvs.hpp>
#include <exactvis/io/load_scene.hpp>

#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: pvs_grid SCENE NX NY NZ\n";
    return 2;
  }
  try {
    const exactvis::Scene scene = exactvis::load_scene(argv[1]);
    exactvis::api::PvsRequest request;
    request.cells = exactvis::api::grid_view_cells(scene, {std::stol(argv[2]), std::stol(argv[3]), std::stol(argv[4])});
    const exactvis::api::PvsAnswer answer = exactvis::api::pvs(scene, request);
    for (std::size_t c = 0; c < answer.cells.size(); ++c)
      std::cout << "cell " << c << ": " << answer.cells[c].visible.size() << " of " << scene.triangles.size()
                << " triangles visible\n";
    const nlohmann::ordered_json j = exactvis::api::pvs_json(scene, answer, argv[1]);  // as `pvs --json`
    std::cout << "stats " << j["stats"].dump() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "pvs_grid: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
