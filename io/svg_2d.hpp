#pragma once
// Minimal SVG drawing of planar results (scenes, bitangents, visibility polygons, aspect regions).
// Coordinates are world coordinates (y up); the document flips y. Drawing uses double approximations of
// exact points: pictures are for people, never for decisions.
#include "planar/scene2d.hpp"

#include <array>
#include <utility>
#include <string>
#include <vector>

namespace exactvis {

// One row of a picture's legend: a swatch (an area, a line, a dashed line or a point) and what it means.
struct SvgLegendEntry {
  enum class Swatch { Area, Line, Dashed, Point } swatch = Swatch::Area;
  std::string colour;  // "#rrggbb"
  std::string label;
};

struct SvgDocument2D {
  double lo_x = 0, lo_y = 0, hi_x = 1, hi_y = 1;  // box shown, in SVG units (world times `scale`)
  double scale = 1;                               // SVG unit per world unit: 1, or a power of 2 below 1
                                                  // when the world box is too large for SVG viewers
  std::vector<std::string> items;                 // SVG elements, in drawing order
  std::vector<std::pair<std::array<double, 2>, std::string>> labels;  // world point, text (drawn upright)
  std::vector<SvgLegendEntry> legend;             // drawn in the top-left corner, in this order
  bool axes = true;                               // x and y axes with ticks in world units along the box
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
// A text label centred at world point p (e.g. a region id), drawn upright above the drawing.
void svg_label(SvgDocument2D& doc, std::array<double, 2> p, const std::string& text);
// Appends a legend row.
void svg_legend(SvgDocument2D& doc, SvgLegendEntry::Swatch swatch, const std::string& colour, const std::string& label);
// Tick step for a range of length `span`: 1, 2 or 5 times a power of ten, 2 to 5 steps across the range.
double svg_tick_step(double span);
// The scene's objects (frame excluded), grey.
void svg_scene(SvgDocument2D& doc, const Scene2D& scene);

// Writes the document (drawing, then labels, axes and legend on top) to `path` itself (whole-or-nothing output: write it through OutputFiles or
// write_atomically, io/atomic_file); throws std::runtime_error("PATH: cannot write") on failure.
void svg_write(const SvgDocument2D& doc, const std::string& path);

// A distinct colour for index i (golden-ratio hue walk), as "#rrggbb".
std::string svg_colour(int i);

}  // namespace exactvis
