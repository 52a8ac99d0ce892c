#pragma once
// Hand-built models for the exterior visibility suites: boxes, a box with a slit, T-junctions, shared faces,
// duplicates. Vertices are shared by exact position, so closed boxes are closed shells.
#include "kernel/scene.hpp"

#include <cmath>
#include <map>
#include <tuple>

namespace exactvis::exterior_test {

struct ModelBuilder {
  Scene scene;
  std::map<std::tuple<double, double, double>, int> ids;
  ModelBuilder() { scene.objects.push_back({"model"}); }
  int vertex(const Point3& p) {
    const auto key = std::make_tuple(p.x, p.y, p.z);
    const auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    scene.vertices.push_back(p);
    return ids[key] = static_cast<int>(scene.vertices.size()) - 1;
  }
  std::int64_t triangle(const Point3& a, const Point3& b, const Point3& c) {
    SceneTriangle t;
    t.id = static_cast<std::int64_t>(scene.triangles.size());
    t.v = {vertex(a), vertex(b), vertex(c)};
    scene.triangles.push_back(t);
    scene.faces_read = static_cast<std::int64_t>(scene.triangles.size());
    return t.id;
  }
  void quad(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    triangle(a, b, c);
    triangle(a, c, d);
  }
  // The faces of [lo, hi] (12 triangles), the top face (z = hi) unless `top` is false.
  void box(const Point3& lo, const Point3& hi, bool top = true) {
    auto P = [&](int i, int j, int k) { return Point3{i ? hi.x : lo.x, j ? hi.y : lo.y, k ? hi.z : lo.z}; };
    quad(P(0, 0, 0), P(0, 1, 0), P(1, 1, 0), P(1, 0, 0));
    if (top) quad(P(0, 0, 1), P(1, 0, 1), P(1, 1, 1), P(0, 1, 1));
    quad(P(1, 0, 0), P(1, 1, 0), P(1, 1, 1), P(1, 0, 1));
    quad(P(0, 0, 0), P(0, 0, 1), P(0, 1, 1), P(0, 1, 0));
    quad(P(0, 1, 0), P(0, 1, 1), P(1, 1, 1), P(1, 1, 0));
    quad(P(0, 0, 0), P(1, 0, 0), P(1, 0, 1), P(0, 0, 1));
  }
};

// The unit box whose top face (z = 1) is two rectangles x <= 1/2 - h and x >= 1/2 + h (a slit of width
// 2h, closed when h = 0), and a small horizontal target triangle inside at z = 1/2 under the slit (the last
// triangle).
inline Scene slit_box(double h) {
  ModelBuilder b;
  b.box({0, 0, 0}, {1, 1, 1}, /*top=*/false);
  b.quad({0, 0, 1}, {0.5 - h, 0, 1}, {0.5 - h, 1, 1}, {0, 1, 1});
  b.quad({0.5 + h, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0.5 + h, 1, 1});
  b.triangle({0.4, 0.4, 0.5}, {0.6, 0.4, 0.5}, {0.5, 0.6, 0.5});
  return b.scene;
}

}  // namespace exactvis::exterior_test
