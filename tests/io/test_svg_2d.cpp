// io/svg_2d: the tick step rule and the upright overlays (labels, legend, axes) of a written picture.
#include "io/svg_2d.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace exactvis {
namespace {

TEST(Svg2D, TickStepIsOneTwoOrFiveTimesAPowerOfTenWithTwoToFiveSteps) {
  for (const double span : {1e-9, 0.37, 1.0, 3.0, 7.5, 10.0, 42.0, 999.0, 1234.5, 6e14}) {
    const double s = svg_tick_step(span);
    const double mantissa = s / std::pow(10.0, std::floor(std::log10(s) + 1e-9));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9)
        << span << " -> " << s;
    EXPECT_GE(span / s, 2.0 - 1e-9) << span;
    EXPECT_LE(span / s, 5.0 + 1e-9) << span;
  }
  EXPECT_EQ(svg_tick_step(10.0), 2.0);
  EXPECT_EQ(svg_tick_step(0.0), 1.0);
  EXPECT_EQ(svg_tick_step(std::nan("")), 1.0);
}

TEST(Svg2D, LabelsLegendAndAxesAreWritten) {
  SvgDocument2D doc = svg_document(0, 0, 10, 5);
  svg_label(doc, {3, 2}, "7");
  svg_legend(doc, SvgLegendEntry::Swatch::Dashed, "#d62728", "dashed thing");
  const std::string path = (std::filesystem::temp_directory_path() / "exactvis_test_svg_2d.svg").string();
  svg_write(doc, path);
  std::ifstream in(path);
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  EXPECT_NE(svg.find(">7</text>"), std::string::npos);
  EXPECT_NE(svg.find(">dashed thing</text>"), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);
  // Upright label at (3, 2): x = 3, y = -2 shifted down by a third of the font (the label is centred).
  EXPECT_NE(svg.find("<text x=\"3\" y=\"-1."), std::string::npos);
  // x ticks every 2 over [0, 10] (with the 2% margin): 0, 2, ..., 10.
  for (const char* t : {">0</text>", ">2</text>", ">10</text>"}) EXPECT_NE(svg.find(t), std::string::npos) << t;
  // Without axes: no tick labels.
  doc.axes = false;
  doc.legend.clear();
  doc.labels.clear();
  svg_write(doc, path);
  std::ifstream in2(path);
  const std::string bare((std::istreambuf_iterator<char>(in2)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  EXPECT_EQ(bare.find("<text"), std::string::npos);
}

}  // namespace
}  // namespace exactvis
