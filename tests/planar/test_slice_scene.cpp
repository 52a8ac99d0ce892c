// Sections of 3D meshes by a plane (planar/slice_scene.hpp, read from files by io/scene2d_json.hpp): loops,
// holes from nesting, and clear errors.
#include "io/load_scene.hpp"
#include "io/scene2d_json.hpp"
#include "planar/slice_scene.hpp"
#include "skeleton/visibility_graph_2d.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace exactvis;

namespace {

// Writes boxes as an OBJ (quads), optionally without the last face of the last box.
std::string write_boxes(const std::string& name, const std::vector<std::array<double, 6>>& boxes, bool drop_face = false) {
  const auto path = (std::filesystem::temp_directory_path() / ("exactvis_plane2d_" + name + ".obj")).string();
  std::ofstream o(path);
  int base = 1;
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const auto& c = boxes[b];
    for (double x : {c[0], c[3]})
      for (double y : {c[1], c[4]})
        for (double z : {c[2], c[5]}) o << "v " << x << " " << y << " " << z << "\n";
    const int f[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    const int faces = (drop_face && b + 1 == boxes.size()) ? 5 : 6;
    for (int k = 0; k < faces; ++k)
      o << "f " << base + f[k][0] << " " << base + f[k][1] << " " << base + f[k][2] << " " << base + f[k][3] << "\n";
    base += 8;
  }
  return path;
}

}  // namespace

TEST(Slice2D, TwoBoxesGiveTwoSquares) {
  const auto path = write_boxes("two", {{0, 0, 0, 1, 1, 1}, {2, 0.5, 0, 3, 1.5, 2}});
  const Scene2D s = load_scene2d(path, "z=1/3");
  EXPECT_EQ(s.num_objects, 2);
  // the triangulated side faces add flat vertices; the sections are the unit squares
  for (const Point2& p : s.points) {
    EXPECT_TRUE((p.x >= 0 && p.x <= 1) || (p.x >= 2 && p.x <= 3));
    EXPECT_TRUE(p.y >= 0 && p.y <= Exact(3) / 2);
  }
  EXPECT_EQ(visibility_graph(s).bitangents.size(), 4u);
}

TEST(Slice2D, NestedBoxesGiveAHole) {
  const auto path = write_boxes("nested", {{0, 0, 0, 4, 4, 4}, {1, 1, 1, 3, 3, 3}});
  const Scene2D s = load_scene2d(path, "z=2");
  EXPECT_EQ(s.num_objects, 1);
  ASSERT_EQ(s.rings.size(), 2u);
  EXPECT_TRUE(s.rings[1].hole);
  EXPECT_FALSE(inside_obstacle(s, Point2(2.0, 2.0)));   // inside the cavity: free
  EXPECT_TRUE(inside_obstacle(s, Point2(0.5, 2.0)));
}

TEST(Slice2D, ClearErrors) {
  const auto path = write_boxes("errors", {{0, 0, 0, 1, 1, 1}});
  EXPECT_THROW(load_scene2d(path, "z=1"), InputError);    // through mesh vertices
  EXPECT_THROW(load_scene2d(path, "z=7"), InputError);    // misses the scene
  EXPECT_THROW(load_scene2d(path, "w=0.5"), InputError);  // bad axis
  EXPECT_THROW(load_scene2d(path, "z=abc"), InputError);  // bad value
  const auto open = write_boxes("open", {{0, 0, 0, 1, 1, 1}}, true);
  EXPECT_THROW(load_scene2d(open, "x=0.5"), InputError);  // not watertight
  const auto overlap = write_boxes("overlap", {{0, 0, 0, 2, 2, 2}, {1, 1, 0.5, 3, 3, 1.5}});
  EXPECT_THROW(load_scene2d(overlap, "z=1"), InputError);  // sections overlap
  try {
    load_scene2d(overlap, "z=1");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("slice"), std::string::npos) << e.what();
  }
}

// The section of an in-memory scene (no file): a tetrahedron cut by x = 1/2 is one triangle with exact
// rational corners; the plane's text is parsed exactly and bad text is a SliceError.
TEST(Slice2D, InMemoryTetrahedron) {
  Scene t;
  t.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  t.triangles = {{0, {0, 2, 1}, 0}, {1, {0, 1, 3}, 0}, {2, {0, 3, 2}, 0}, {3, {1, 2, 3}, 0}};
  t.objects = {{"tet"}};
  const SlicePlane plane = parse_slice_plane("x=1/2");
  EXPECT_EQ(plane.axis, 0);
  EXPECT_EQ(plane.value, Exact(1, 2));
  const auto polys = slice_scene(t, plane);
  ASSERT_EQ(polys.size(), 1u);
  ASSERT_EQ(polys[0].rings.size(), 1u);
  ASSERT_EQ(polys[0].rings[0].size(), 3u);
  // Plane coordinates of x = V are (y, z): the section is the triangle (0,0), (1/2,0), (0,1/2).
  int found = 0;
  for (const Point2& p : polys[0].rings[0])
    for (const auto& [y, z] : {std::pair<Exact, Exact>{0, 0}, {Exact(1, 2), 0}, {0, Exact(1, 2)}})
      found += p.x == y && p.y == z;
  EXPECT_EQ(found, 3);
  EXPECT_THROW(parse_slice_plane("q=1"), SliceError);
  EXPECT_THROW(parse_slice_plane("z=1/0"), SliceError);
  EXPECT_THROW(slice_scene(t, parse_slice_plane("x=0")), SliceError);  // through vertices
}
