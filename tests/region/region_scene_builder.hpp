#pragma once
// The region suites' scene builder: triangles added one by one with ids in insertion order, each with its
// own three vertices (so nothing is shared unless coordinates coincide), grouped into named objects.
#include "kernel/scene.hpp"

#include <cstdint>
#include <string>

namespace exactvis::region_test {

struct SceneBuilder {
  Scene scene;
  SceneBuilder() { scene.objects.push_back({"object0"}); }
  // Starts a new object: the triangles added next belong to it.
  void object(const std::string& name) { scene.objects.push_back({name}); }
  int add_vertex(const Point3& p) {
    scene.vertices.push_back(p);
    return static_cast<int>(scene.vertices.size()) - 1;
  }
  std::int64_t triangle(const Point3& a, const Point3& b, const Point3& c) {
    SceneTriangle t;
    t.id = static_cast<std::int64_t>(scene.triangles.size());
    t.v = {add_vertex(a), add_vertex(b), add_vertex(c)};
    t.object = static_cast<int>(scene.objects.size()) - 1;
    scene.triangles.push_back(t);
    scene.faces_read = static_cast<std::int64_t>(scene.triangles.size());
    return t.id;
  }
  // Quad a-b-c-d as two triangles (a,b,c), (a,c,d).
  void quad(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    triangle(a, b, c);
    triangle(a, c, d);
  }
  // The axis-aligned rectangle [u0,u1] x [v0,v1] in the plane coordinate `axis` = w (u = axis+1, v = axis+2).
  void rect(int axis, double w, double u0, double u1, double v0, double v1) {
    auto P = [&](double u, double v) {
      Point3 p;
      p[axis] = w;
      p[(axis + 1) % 3] = u;
      p[(axis + 2) % 3] = v;
      return p;
    };
    quad(P(u0, v0), P(u1, v0), P(u1, v1), P(u0, v1));
  }
  // Closed axis-aligned box (12 triangles, outward orientation), faces in the order x = hi, x = lo, y = hi,
  // y = lo, z = hi, z = lo (the bottom is the last two triangles).
  void box(const Point3& lo, const Point3& hi) {
    auto P = [&](int i, int j, int k) { return Point3{i ? hi.x : lo.x, j ? hi.y : lo.y, k ? hi.z : lo.z}; };
    quad(P(1, 0, 0), P(1, 1, 0), P(1, 1, 1), P(1, 0, 1));
    quad(P(0, 0, 0), P(0, 0, 1), P(0, 1, 1), P(0, 1, 0));
    quad(P(0, 1, 0), P(0, 1, 1), P(1, 1, 1), P(1, 1, 0));
    quad(P(0, 0, 0), P(1, 0, 0), P(1, 0, 1), P(0, 0, 1));
    quad(P(0, 0, 1), P(1, 0, 1), P(1, 1, 1), P(0, 1, 1));
    quad(P(0, 0, 0), P(0, 1, 0), P(1, 1, 0), P(1, 0, 0));
  }
};

}  // namespace exactvis::region_test
