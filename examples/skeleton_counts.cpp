// The 3D visibility skeleton of a scene (extremal stabbing lines and the EV/EEE arcs between them), or with
// two object names (or triangle ids) only the part whose lines end on those two objects; prints the counts
// of `exactvis skeleton --json` and the first arcs.
//   skeleton_counts SCENE.obj [A B]
#include <exactvis/api/skeleton.hpp>
#include <exactvis/io/load_scene.hpp>

#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2 && argc != 4) {
    std::cerr << "usage: skeleton_counts SCENE [A B]\n";
    return 2;
  }
  try {
    const exactvis::Scene scene = exactvis::load_scene(argv[1]);
    exactvis::api::SkeletonRequest request;
    if (argc == 4) request.pair = exactvis::api::parse_skeleton_pair(scene, std::string(argv[2]) + "," + argv[3]);
    const exactvis::Skeleton3D skeleton = exactvis::api::skeleton(scene, request);
    const nlohmann::ordered_json j = exactvis::api::skeleton_json(scene, skeleton);  // as `skeleton --json`
    for (std::size_t a = 0; a < j["arcs"].size() && a < 3; ++a) std::cout << "arc " << j["arcs"][a].dump() << "\n";
    std::cout << "counts " << j["counts"].dump() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "skeleton_counts: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
