#include "io/svg_2d.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace exactvis {
namespace {

double unit(const SvgDocument2D& d) { return std::max(d.hi_x - d.lo_x, d.hi_y - d.lo_y) / 800.0; }

std::string num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// A world coordinate in SVG units.
double to_svg(const SvgDocument2D& d, double v) {
  if (!std::isfinite(v)) v = std::copysign(std::numeric_limits<double>::max(), v);
  return v * d.scale;
}
std::string coord(const SvgDocument2D& d, double v) { return num(to_svg(d, v)); }

}  // namespace

SvgDocument2D svg_document(double lo_x, double lo_y, double hi_x, double hi_y) {
  SvgDocument2D d;
  const double big = std::max({std::fabs(lo_x), std::fabs(lo_y), std::fabs(hi_x), std::fabs(hi_y)});
  if (!(big <= 1e15)) d.scale = std::ldexp(1.0, -std::max(0, std::ilogb(std::isfinite(big) ? big : 1e308) - 40));
  lo_x = to_svg(d, lo_x), lo_y = to_svg(d, lo_y), hi_x = to_svg(d, hi_x), hi_y = to_svg(d, hi_y);
  const double m = 0.02 * std::max({hi_x - lo_x, hi_y - lo_y, 1e-9});
  d.lo_x = lo_x - m;
  d.lo_y = lo_y - m;
  d.hi_x = hi_x + m;
  d.hi_y = hi_y + m;
  return d;
}

SvgDocument2D svg_document(const Scene2D& s) {
  if (s.points.empty()) return svg_document(0, 0, 1, 1);
  double lo_x = s.points[0].ax, hi_x = lo_x, lo_y = s.points[0].ay, hi_y = lo_y;
  for (const Point2& p : s.points) {
    lo_x = std::min(lo_x, p.ax), hi_x = std::max(hi_x, p.ax);
    lo_y = std::min(lo_y, p.ay), hi_y = std::max(hi_y, p.ay);
  }
  return svg_document(lo_x, lo_y, hi_x, hi_y);
}

void svg_rings(SvgDocument2D& doc, const std::vector<std::vector<std::array<double, 2>>>& rings,
               const std::string& fill, const std::string& stroke, double fill_opacity) {
  std::string path;
  for (const auto& r : rings) {
    for (std::size_t i = 0; i < r.size(); ++i) path += (i ? "L" : "M") + coord(doc, r[i][0]) + "," + coord(doc, r[i][1]) + " ";
    if (!r.empty()) path += "Z ";
  }
  doc.items.push_back("<path d=\"" + path + "\" fill=\"" + fill + "\" fill-opacity=\"" + num(fill_opacity) +
                      "\" fill-rule=\"evenodd\" stroke=\"" + stroke + "\" stroke-width=\"" + num(unit(doc)) +
                      "\"/>");
}

void svg_segment(SvgDocument2D& doc, std::array<double, 2> a, std::array<double, 2> b, const std::string& stroke,
                 double width_ratio, bool dashed) {
  doc.items.push_back("<line x1=\"" + coord(doc, a[0]) + "\" y1=\"" + coord(doc, a[1]) + "\" x2=\"" + coord(doc, b[0]) +
                      "\" y2=\"" + coord(doc, b[1]) + "\" stroke=\"" + stroke + "\" stroke-width=\"" + num(unit(doc) * width_ratio) +
                      "\"" + (dashed ? " stroke-dasharray=\"" + num(4 * unit(doc)) + "\"" : "") + "/>");
}

void svg_point(SvgDocument2D& doc, std::array<double, 2> p, const std::string& fill) {
  doc.items.push_back("<circle cx=\"" + coord(doc, p[0]) + "\" cy=\"" + coord(doc, p[1]) + "\" r=\"" + num(3 * unit(doc)) +
                      "\" fill=\"" + fill + "\"/>");
}

void svg_label(SvgDocument2D& doc, std::array<double, 2> p, const std::string& text) {
  doc.labels.push_back({p, text});
}

void svg_legend(SvgDocument2D& doc, SvgLegendEntry::Swatch swatch, const std::string& colour, const std::string& label) {
  doc.legend.push_back({swatch, colour, label});
}

double svg_tick_step(double span) {
  if (!(span > 0) || !std::isfinite(span)) return 1;
  const double raw = span / 5, p = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

void svg_scene(SvgDocument2D& doc, const Scene2D& s) {
  for (int obj = 0; obj < s.num_objects; ++obj) {
    std::vector<std::vector<std::array<double, 2>>> rings;
    for (const Ring2D& r : s.rings) {
      if (r.object != obj || static_cast<int>(&r - &s.rings[0]) == s.frame_ring) continue;
      rings.emplace_back();
      for (int i = 0; i < r.size; ++i) rings.back().push_back({s.points[r.first + i].ax, s.points[r.first + i].ay});
    }
    svg_rings(doc, rings, "#9a9a9a", "#303030");
  }
}

void svg_write(const SvgDocument2D& d, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
  const double w = d.hi_x - d.lo_x, h = d.hi_y - d.lo_y;
  const double px = 900, py = std::max(100.0, 900 * h / std::max(w, 1e-12));
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(px) << "\" height=\"" << num(py)
      << "\" viewBox=\"" << num(d.lo_x) << " " << num(-d.hi_y) << " " << num(w) << " " << num(h) << "\">\n";
  out << "<rect x=\"" << num(d.lo_x) << "\" y=\"" << num(-d.hi_y) << "\" width=\"" << num(w) << "\" height=\""
      << num(h) << "\" fill=\"white\"/>\n<g transform=\"scale(1,-1)\">\n";
  for (const auto& item : d.items) out << item << "\n";
  out << "</g>\n";
  // Upright overlays in SVG coordinates (y down): labels, axes, legend. Sizes in screen-pixel units.
  const double u = unit(d), font = 11 * u;
  auto text = [&](double x, double y, const std::string& t, const char* anchor) {
    out << "<text x=\"" << num(x) << "\" y=\"" << num(y) << "\" font-size=\"" << num(font)
        << "\" font-family=\"sans-serif\" text-anchor=\"" << anchor << "\">" << t << "</text>\n";
  };
  for (const auto& [p, t] : d.labels) text(to_svg(d, p[0]), -to_svg(d, p[1]) + 0.35 * font, t, "middle");
  if (d.axes) {
    // Ticks along the bottom and left edges, at a 1-2-5 step of the SVG units (world units unless the
    // picture is scaled down for huge coordinates), labelled in world units; at most 12 per axis.
    const std::string style = "\" stroke=\"#505050\" stroke-width=\"" + num(u) + "\"/>\n";
    out << "<line x1=\"" << num(d.lo_x) << "\" y1=\"" << num(-d.lo_y) << "\" x2=\"" << num(d.hi_x) << "\" y2=\""
        << num(-d.lo_y) << style << "<line x1=\"" << num(d.lo_x) << "\" y1=\"" << num(-d.lo_y) << "\" x2=\""
        << num(d.lo_x) << "\" y2=\"" << num(-d.hi_y) << style;
    auto world = [&](double t) {
      const double w = t / d.scale;
      return std::isfinite(w) ? num(std::abs(t) < 1e-12 * (d.hi_x - d.lo_x + d.hi_y - d.lo_y) ? 0.0 : w) : std::string();
    };
    const double sx = svg_tick_step(d.hi_x - d.lo_x), sy = svg_tick_step(d.hi_y - d.lo_y);
    int n = 0;
    for (double x = std::ceil(d.lo_x / sx) * sx; x <= d.hi_x && n < 12; x += sx, ++n) {
      out << "<line x1=\"" << num(x) << "\" y1=\"" << num(-d.lo_y) << "\" x2=\"" << num(x) << "\" y2=\""
          << num(-d.lo_y - 5 * u) << style;
      text(x, -d.lo_y - 7 * u, world(x), "middle");
    }
    n = 0;
    for (double y = std::ceil(d.lo_y / sy) * sy; y <= d.hi_y && n < 12; y += sy, ++n) {
      out << "<line x1=\"" << num(d.lo_x) << "\" y1=\"" << num(-y) << "\" x2=\"" << num(d.lo_x + 5 * u) << "\" y2=\""
          << num(-y) << style;
      text(d.lo_x + 7 * u, -y + 0.35 * font, world(y), "start");
    }
  }
  if (!d.legend.empty()) {
    const double x0 = d.lo_x + 12 * u, y0 = -d.hi_y + 10 * u, row = 16 * u;
    std::size_t longest = 0;
    for (const auto& e : d.legend) longest = std::max(longest, e.label.size());
    out << "<rect x=\"" << num(x0 - 4 * u) << "\" y=\"" << num(y0 - 4 * u) << "\" width=\""
        << num(30 * u + 0.6 * font * static_cast<double>(longest)) << "\" height=\""
        << num(row * static_cast<double>(d.legend.size()) + 6 * u)
        << "\" fill=\"white\" fill-opacity=\"0.85\" stroke=\"#808080\" stroke-width=\"" << num(0.5 * u) << "\"/>\n";
    for (std::size_t i = 0; i < d.legend.size(); ++i) {
      const SvgLegendEntry& e = d.legend[i];
      const double y = y0 + row * static_cast<double>(i);
      switch (e.swatch) {
        case SvgLegendEntry::Swatch::Area:
          out << "<rect x=\"" << num(x0) << "\" y=\"" << num(y) << "\" width=\"" << num(16 * u) << "\" height=\""
              << num(10 * u) << "\" fill=\"" << e.colour << "\" stroke=\"#303030\" stroke-width=\"" << num(0.5 * u)
              << "\"/>\n";
          break;
        case SvgLegendEntry::Swatch::Point:
          out << "<circle cx=\"" << num(x0 + 8 * u) << "\" cy=\"" << num(y + 5 * u) << "\" r=\"" << num(3 * u)
              << "\" fill=\"" << e.colour << "\"/>\n";
          break;
        default:
          out << "<line x1=\"" << num(x0) << "\" y1=\"" << num(y + 5 * u) << "\" x2=\"" << num(x0 + 16 * u)
              << "\" y2=\"" << num(y + 5 * u) << "\" stroke=\"" << e.colour << "\" stroke-width=\"" << num(1.5 * u)
              << "\""
              << (e.swatch == SvgLegendEntry::Swatch::Dashed ? " stroke-dasharray=\"" + num(3 * u) + "\"" : "")
              << "/>\n";
      }
      text(x0 + 22 * u, y + 9 * u, e.label, "start");
    }
  }
  out << "</svg>\n";
  out.close();
  if (!out) throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
}

std::string svg_colour(int i) {
  const double h = std::fmod(0.13 + 0.618033988749895 * i, 1.0) * 6.0;
  const double s = 0.55, v = 0.95;
  const double c = v * s, x = c * (1 - std::fabs(std::fmod(h, 2.0) - 1)), m = v - c;
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0: r = c, g = x; break;
    case 1: r = x, g = c; break;
    case 2: g = c, b = x; break;
    case 3: g = x, b = c; break;
    case 4: r = x, b = c; break;
    default: r = c, b = x; break;
  }
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int((r + m) * 255), int((g + m) * 255), int((b + m) * 255));
  return buf;
}

}  // namespace exactvis
