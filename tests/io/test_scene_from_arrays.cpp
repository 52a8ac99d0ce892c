// Scenes from arrays (io/load_scene.hpp scene_from_arrays, the Python module's V, F): the same scene as
// loading the same mesh from a file (ids, vertices, zero-area drops, objects as connected components), and
// one-line messages naming the array for bad input.
#include "io/load_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace exactvis;

namespace {

TEST(SceneFromArrays, SameAsTheFile) {
  const std::vector<Point3> V{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}, {6, 5, 5}, {5, 6, 5}, {7, 7, 7}, {0.5, 0.5, 1}};
  const std::vector<std::array<std::int64_t, 3>> F{{0, 1, 2}, {3, 4, 5}, {6, 6, 3}, {1, 2, 7}};
  const std::string path =
      (std::filesystem::temp_directory_path() / ("exactvis_arrays_" + std::to_string(::getpid()) + ".off")).string();
  {
    std::ofstream off(path);
    off << "OFF\n" << V.size() << " " << F.size() << " 0\n";
    for (const auto& v : V) off << v.x << " " << v.y << " " << v.z << "\n";
    for (const auto& f : F) off << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  }
  const Scene a = scene_from_arrays(V, F, "mesh");
  const Scene b = load_scene(path);
  std::filesystem::remove(path);
  ASSERT_EQ(a.triangles.size(), 3u);
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  EXPECT_EQ(a.faces_read, 4);
  EXPECT_EQ(a.degenerate_dropped, 1);
  for (std::size_t i = 0; i < a.triangles.size(); ++i) {
    EXPECT_EQ(a.triangles[i].id, b.triangles[i].id);
    EXPECT_EQ(a.triangles[i].v, b.triangles[i].v);
    EXPECT_EQ(a.triangles[i].object, b.triangles[i].object);
  }
  EXPECT_EQ(a.triangles[2].id, 3);  // the id of the dropped face 2 is absent
  ASSERT_EQ(a.objects.size(), 2u);  // {0, 1, 2, 7} and {3, 4, 5}
  EXPECT_EQ(a.objects[0].name, "mesh#component0");
  EXPECT_EQ(a.triangles[0].object, a.triangles[2].object);
  EXPECT_EQ(a.vertices.size(), V.size());
}

TEST(SceneFromArrays, BadArraysNameTheArray) {
  auto message = [](const std::vector<Point3>& V, const std::vector<std::array<std::int64_t, 3>>& F) -> std::string {
    try {
      scene_from_arrays(V, F);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  const std::vector<Point3> V{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(message(V, {{0, 1, 3}}), "F: face 0 refers to vertex 3, out of range [0, 3)");
  EXPECT_EQ(message(V, {{0, 1, 2}, {-1, 1, 2}}), "F: face 1 refers to vertex -1, out of range [0, 3)");
  EXPECT_EQ(message({{0, 0, 0}, {1, std::nan(""), 0}, {0, 1, 0}}, {{0, 1, 2}}),
            "V: vertex 1 has a non-finite coordinate");
  EXPECT_EQ(message(V, {}), "no error");  // an empty scene is a scene
}

}  // namespace
