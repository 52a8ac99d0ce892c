#pragma once
// PNG pictures of partitions (`exactvis aspect --png`) through VTK's offscreen rendering (io/headless_display.hpp provides the X display VTK
// needs): panels side by side, each a triangle surface coloured by integer values (a fixed palette; -1
// grey) with black curves, seen by an orthographic or a perspective camera. Display only.
#include "kernel/scene.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace exactvis {

struct PngPanel {
  std::vector<Point3> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::int64_t> values;          // per triangle: palette index, -1 grey
  std::vector<std::vector<Point3>> curves;   // drawn black
  Point3 focal{0, 0, 0};                     // the camera looks at focal
  Point3 eye{0, 0, 1};                       // perspective: the camera position; orthographic: focal + direction
  bool orthographic = true;
  Point3 up{0, 0, 1};
  double view_angle = 45;                    // perspective: degrees
};

// Input: path (.png), panels (>= 1), the size of one square panel in pixels. Output: the file (atomically).
// Throws OutputError.
void render_panels_png(const std::string& path, const std::vector<PngPanel>& panels, int panel_pixels);

}  // namespace exactvis
