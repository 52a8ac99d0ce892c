#pragma once
// 2D benchmark scenes of convex polygons in layouts that scale (bench_complex2d, bench_segments2d).
#include "planar/scene2d.hpp"

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace exactvis::bench {

// Random convex polygon (k vertices on a jittered circle) centred at (cx, cy) with radius r.
inline PolygonInput2D convex_polygon(std::mt19937_64& rng, double cx, double cy, double r, int k) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> ang;
  for (int i = 0; i < k; ++i) ang.push_back(6.283185307179586 * (i + 0.8 * u(rng)) / k);
  PolygonInput2D p;
  p.rings.emplace_back();
  for (double a : ang) p.rings[0].emplace_back(cx + r * std::cos(a), cy + r * std::sin(a));
  return p;
}

// Layouts with the same polygon count: "grid" (m x m cells), "row" (one line of polygons: heavy
// occlusion, few bitangents), "ring" (polygons on a circle: almost all pairs see each other).
inline Scene2D make_scene(const std::string& layout, int polygons, int k, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<PolygonInput2D> ps;
  if (layout == "grid") {
    const int m = static_cast<int>(std::ceil(std::sqrt(polygons)));
    for (int i = 0; i < polygons; ++i)
      ps.push_back(convex_polygon(rng, 10.0 * (i % m) + u(rng), 10.0 * (i / m) + u(rng), 3.0 + u(rng), k));
  } else if (layout == "row") {
    for (int i = 0; i < polygons; ++i) ps.push_back(convex_polygon(rng, 10.0 * i, u(rng), 4.0 + 0.5 * u(rng), k));
  } else {  // ring
    const double R = 10.0 * polygons / 6.283185307179586 + 10;
    for (int i = 0; i < polygons; ++i) {
      const double a = 6.283185307179586 * i / polygons;
      ps.push_back(convex_polygon(rng, R * std::cos(a), R * std::sin(a), 2.0, k));
    }
  }
  return make_scene2d(ps);
}

}  // namespace exactvis::bench
