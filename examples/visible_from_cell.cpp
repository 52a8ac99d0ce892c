// Which triangles of a scene can be seen from a view cell, each visible one with an exact witness segment.
//   visible_from_cell SCENE.obj X0 Y0 Z0 X1 Y1 Z1
#include <exactvis/api/visible.hpp>
#include <exactvis/io/load_scene.hpp>

#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 8) {
    std::cerr << "usage: visible_from_cell SCENE X0 Y0 Z0 X1 Y1 Z1\n";
    return 2;
  }
  try {
    const exactvis::Scene scene = exactvis::load_scene(argv[1]);
    exactvis::api::VisibleRequest request;
    auto c = [&](int i) { return exactvis::Exact(std::stod(argv[i])); };  // a double is an exact rational
    request.source.cell = exactvis::api::cell_box(c(2), c(3), c(4), c(5), c(6), c(7));
    const exactvis::api::VisibleAnswer answer = exactvis::api::visible(scene, request);
    for (const auto& t : answer.triangles) {
      if (!t.visible) continue;
      const auto& w = *t.witness;  // from w.p on the cell to w.q inside the triangle, exact rationals
      std::cout << "triangle " << t.id << " visible, witness (" << CGAL::to_double(w.p.x) << ", "
                << CGAL::to_double(w.p.y) << ", " << CGAL::to_double(w.p.z) << ") -> (" << CGAL::to_double(w.q.x)
                << ", " << CGAL::to_double(w.q.y) << ", " << CGAL::to_double(w.q.z) << ")\n";
    }
    std::cout << answer.visible << " of " << answer.triangles.size() << " triangles visible\n";
  } catch (const std::exception& e) {
    std::cerr << "visible_from_cell: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
