#include "io/write_pvs_check_vtp.hpp"

#include "io/atomic_file.hpp"

namespace exactvis {

void write_pvs_check_vtp(const std::string& path, const Scene& scene, const std::vector<int>& status,
                         const std::vector<WitnessSegment>& witnesses, const region::RationalBox3& cell) {
  if (status.size() != scene.triangles.size())
    throw OutputError(path + ": status does not match the scene's triangles");
  std::vector<std::vector<Point3>> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (bool high : {false, true}) {
      std::vector<Point3>& face = faces.emplace_back();
      for (const auto& c : region::box_face(cell, axis, high))
        face.push_back({CGAL::to_double(c.x), CGAL::to_double(c.y), CGAL::to_double(c.z)});
    }
  write_triangle_state_vtp(path, scene, status, {"status", false, kStatusFalseInvisible, -1}, witnesses, faces);
}

}  // namespace exactvis
