#pragma once
// Minimal SVG drawing of planar results (scenes, bitangents, visibility polygons, aspect regions).
// Coordinates are world coordinates (y up); the document flips y. Drawing uses double approximations of
// exact points: pictures are for people, never for decisions.
#include "planar/scene2d.hpp"

#include <array>
#include <string>
#include <vector>

namespace exactvis {

struct SvgDocument2D {
  double lo_x = 0, lo_y = 0, hi_x = 1, hi_y = 1;  // box shown, in SVG units (world times `scale`)
  double scale = 1;                               // SVG unit per world unit: 1, or a power of 2 below 1
                                                  // when the world box is too large for SVG viewers
  std::vector<std::string> items;                 // SVG elements, in drawing order
};

// A document showing the box [lo, hi] (with a 2% margin). World coordinates beyond 1e15 in magnitude are
// scaled down by a power of two (exact) so that the picture's numbers stay finite and viewers draw it;
// non-finite drawing coordinates are clamped to the largest double.
SvgDocument2D svg_document(double lo_x, double lo_y, double hi_x, double hi_y);
// A document fitted to the scene's vertices.
SvgDocument2D svg_document(const Scene2D& scene);

// Polygons with holes (rings, filled even-odd), a segment, a point, a text label.
void svg_rings(SvgDocument2D& doc, const std::vector<std::vector<std::array<double, 2>>>& rings,
               const std::string& fill, const std::string& stroke, double fill_opacity = 1.0);
void svg_segment(SvgDocument2D& doc, std::array<double, 2> a, std::array<double, 2> b, const std::string& stroke,
                 double width_ratio = 1.0, bool dashed = false);
void svg_point(SvgDocument2D& doc, std::array<double, 2> p, const std::string& fill);
// The scene's objects (frame excluded), grey.
void svg_scene(SvgDocument2D& doc, const Scene2D& scene);

// Writes the document to `path` itself (whole-or-nothing output: write it through OutputFiles or
// write_atomically, io/atomic_file); throws std::runtime_error("PATH: cannot write") on failure.
void svg_write(const SvgDocument2D& doc, const std::string& path);

// A distinct colour for index i (golden-ratio hue walk), as "#rrggbb".
std::string svg_colour(int i);

}  // namespace exactvis
