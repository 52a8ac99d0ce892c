// io/render_scene_png: pictures read back (size from the PNG header parsed by hand, pixels by VTK's reader)
// and checked for the colours of what was drawn; box_edges against the box's definition.
#include "io/atomic_file.hpp"
#include "io/render_scene_png.hpp"
#include "io_test_util.hpp"
#include "png_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace {

using namespace exactvis;

TEST(RenderScenePng, BoxEdgesAreTheTwelveAxisParallelEdges) {
  const Point3 lo{1, 2, 3}, hi{4, 6, 8};
  const auto edges = box_edges(lo, hi);
  ASSERT_EQ(edges.size(), 12u);
  std::set<std::array<double, 6>> distinct;
  int per_axis[3] = {0, 0, 0};
  for (const auto& e : edges) {
    int differing = 0, axis = -1;
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(e[0][k] == lo[k] || e[0][k] == hi[k]);
      EXPECT_TRUE(e[1][k] == lo[k] || e[1][k] == hi[k]);
      if (e[0][k] != e[1][k]) ++differing, axis = k;
    }
    ASSERT_EQ(differing, 1);
    ++per_axis[axis];
    std::array<double, 6> key{e[0].x, e[0].y, e[0].z, e[1].x, e[1].y, e[1].z};
    if (key[axis] > key[axis + 3]) std::swap(key[axis], key[axis + 3]);
    distinct.insert(key);
  }
  EXPECT_EQ(distinct.size(), 12u);
  EXPECT_EQ(per_axis[0], 4);
  EXPECT_EQ(per_axis[1], 4);
  EXPECT_EQ(per_axis[2], 4);
}

TEST(RenderScenePng, DrawsEachLayerInItsColourAtTheRequestedSize) {
  iotest::TempDir dir;
  unsetenv("DISPLAY");  // the renderer starts its own Xvfb
  ScenePicture pic;
  PictureMesh m;
  m.lit = false;  // flat colours: the pixels are exactly the layer's colours
  m.triangles.push_back({Point3{0, 0, 0}, Point3{4, 0, 0}, Point3{0, 4, 0}});
  m.triangles.push_back({Point3{6, 0, 0}, Point3{10, 0, 0}, Point3{10, 4, 0}});
  m.colours = {Rgb{200, 30, 30}, Rgb{30, 180, 40}};
  pic.meshes.push_back(m);
  pic.lines.push_back({{{Point3{0, 6, 0}, Point3{10, 6, 0}}}, Rgb{20, 40, 220}, 4});
  pic.legend.push_back({"legend", Rgb{240, 200, 0}});
  pic.title = "title";
  const std::string path = dir.file("p.png");
  ASSERT_TRUE(render_scene_png(path, pic, 320, 200));
  const png_test::PngImage img = png_test::read_png(path);
  ASSERT_TRUE(img.valid);
  EXPECT_EQ(img.width, 320);
  EXPECT_EQ(img.height, 200);
  EXPECT_GT(png_test::pixels_like(img, {200, 30, 30}, 0.95), 100);
  EXPECT_GT(png_test::pixels_like(img, {30, 180, 40}, 0.95), 100);
  EXPECT_GT(png_test::pixels_like(img, {20, 40, 220}, 0.95), 20);
  EXPECT_GT(png_test::pixels_like(img, {240, 200, 0}, 0.95), 20);  // the legend's swatch
  EXPECT_GT(img.colours.count({255, 255, 255}) ? img.colours.at({255, 255, 255}) : 0, 320 * 200 / 3);

  // Only the green triangle: no red pixels anywhere.
  m.triangles.resize(1);
  m.colours = {Rgb{30, 180, 40}};
  ScenePicture green;
  green.meshes.push_back(m);
  ASSERT_TRUE(render_scene_png(path, green, 64, 48));
  const png_test::PngImage g = png_test::read_png(path);
  ASSERT_TRUE(g.valid);
  EXPECT_EQ(g.width, 64);
  EXPECT_EQ(g.height, 48);
  EXPECT_GT(png_test::pixels_like(g, {30, 180, 40}, 0.95), 50);
  EXPECT_EQ(png_test::pixels_like(g, {200, 30, 30}, 0.5), 0);
}

TEST(RenderScenePng, SizeOutOfRangeIsAnOutputError) {
  iotest::TempDir dir;
  EXPECT_THROW(render_scene_png(dir.file("p.png"), {}, 8, 100), OutputError);
  EXPECT_THROW(render_scene_png(dir.file("p.png"), {}, 100, 9000), OutputError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("p.png")));
}

}  // namespace
