// The EV visual events of a scene (vertex-edge critical line families with their exact free intervals),
// printed as the command line's JSON (`exactvis events --kinds EV --json`).
//   visual_events SCENE.obj
#include <exactvis/api/events.hpp>
#include <exactvis/io/load_scene.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: visual_events SCENE\n";
    return 2;
  }
  try {
    const exactvis::Scene scene = exactvis::load_scene(argv[1]);
    exactvis::api::EventsRequest request;
    request.eee = false;  // EEE events are quadratic in the number of edges: restrict them with a light
    const exactvis::api::EventsAnswer answer = exactvis::api::events(scene, request);
    for (const exactvis::EvEvent& ev : answer.ev.events)
      std::cout << "EV vertex " << ev.vertex << " edge [" << ev.edge[0] << ", " << ev.edge[1] << "]: "
                << ev.intervals.size() << " free interval(s)\n";
    const nlohmann::json j = exactvis::api::events_json(scene, answer);
    std::cout << "counts " << j["counts"].dump() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "visual_events: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
