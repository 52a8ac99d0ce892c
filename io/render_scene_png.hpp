#pragma once
// A picture of a 3D result over its scene (`exactvis visible|pvs|events|export --png`), rendered by VTK
// offscreen (io/headless_display.hpp gives the X display Debian's VTK needs). The picture is layers: triangle
// meshes with one colour per triangle (optionally translucent), line sets of one colour and width, and a
// legend (a coloured box per entry with its label) and a title in the top-left corner. The camera looks at
// the bounding box of everything drawn from above one corner (up = +z), perspective, the box filling the
// view. Display only: coordinates are double approximations and nothing here decides a result.
#include "kernel/scene.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace exactvis {

using Rgb = std::array<unsigned char, 3>;

// Palette colour number v (hues by the golden angle, alternating lightness: neighbours differ); v < 0: grey.
Rgb palette_colour(std::int64_t v);

// Triangles with a colour each (parallel to `triangles`); `opacity` < 1 draws the layer translucent.
struct PictureMesh {
  std::vector<std::array<Point3, 3>> triangles;
  std::vector<Rgb> colours;
  double opacity = 1.0;
  bool lit = true;  // shaded by VTK's headlight; false: flat colour (surfaces seen edge-on stay visible)
  bool cull_back_faces = false;  // true: a closed room whose faces point inwards is seen through its outer walls
};

// Segments of one colour and width (pixels).
struct PictureLines {
  std::vector<std::array<Point3, 2>> segments;
  Rgb colour{0, 0, 0};
  double width = 1.0;
};

struct LegendEntry {
  std::string label;
  Rgb colour;
};

struct ScenePicture {
  std::vector<PictureMesh> meshes;
  std::vector<PictureLines> lines;
  std::vector<LegendEntry> legend;
  std::string title;  // one line, drawn above the legend; empty: none
};

// The scene's triangles as one mesh layer, triangle i coloured colours[i] (parallel to scene.triangles).
PictureMesh scene_mesh(const Scene& scene, const std::vector<Rgb>& colours);

// The 12 edges of the axis-aligned box lo..hi as segments (a view cell drawn as a wire box).
std::vector<std::array<Point3, 2>> box_edges(const Point3& lo, const Point3& hi);

// Input: the destination (a temporary .png path from io/atomic_file.hpp's writers), the picture, its size
// in pixels (each 16 .. 8192). Output: whether the PNG writer succeeded; throws OutputError
// ("PATH: cannot render: ...") when no display can be had or the size is out of range. An empty picture
// gives the background with the legend. Cost: VTK's software OpenGL, about linear in what is drawn.
bool render_scene_png(const std::string& temp_path, const ScenePicture& picture, int width, int height);

}  // namespace exactvis
