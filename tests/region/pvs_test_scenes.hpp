#pragma once
// Small adversarial scenes for the PVS suites: a closed room with a pinhole, triangles sharing edges,
// ground coplanar with building bottoms, built triangle by triangle with ids in insertion order.
#include "kernel/scene.hpp"

#include <random>
#include <string>

namespace exactvis::pvs_test {

struct SceneBuilder {
  Scene scene;
  SceneBuilder() { scene.objects.push_back({"object0"}); }
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
    scene.faces_read++;
    return t.id;
  }
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
  // Closed box (shared corners, 12 triangles).
  void box(const Point3& lo, const Point3& hi) {
    for (int axis = 0; axis < 3; ++axis)
      for (double w : {lo[axis], hi[axis]})
        rect(axis, w, lo[(axis + 1) % 3], hi[(axis + 1) % 3], lo[(axis + 2) % 3], hi[(axis + 2) % 3]);
  }
};

// A closed room [0,10]^3 whose wall x = 0 has a square hole of side `hole` (0: no hole) centred at a random
// point (fixed by `seed`), the wall tiled around it by rectangles meeting exactly at the hole's edges;
// inside, `inner` small random triangles. Object "room" holds the walls, "inside" the triangles.
inline Scene pinhole_room(double hole, int inner, unsigned seed) {
  std::mt19937 rng(seed);
  auto coord = [&](double lo, double hi) { return lo + (hi - lo) * static_cast<double>(rng() % 1024) / 1024.0; };
  SceneBuilder b;
  b.scene.objects[0].name = "room";
  const double cy = coord(3, 7), cz = coord(3, 7);
  const double y0 = cy - hole / 2, y1 = cy + hole / 2, z0 = cz - hole / 2, z1 = cz + hole / 2;
  if (hole > 0) {
    b.rect(0, 0, 0, y0, 0, 10);
    b.rect(0, 0, y1, 10, 0, 10);
    b.rect(0, 0, y0, y1, 0, z0);
    b.rect(0, 0, y0, y1, z1, 10);
  } else {
    b.rect(0, 0, 0, 10, 0, 10);
  }
  b.rect(0, 10, 0, 10, 0, 10);
  for (int axis = 1; axis < 3; ++axis)
    for (double w : {0.0, 10.0}) b.rect(axis, w, 0, 10, 0, 10);
  b.object("inside");
  for (int i = 0; i < inner; ++i) {
    const Point3 c{coord(1, 9), coord(1, 9), coord(1, 9)};
    b.triangle({c.x, c.y, c.z}, {c.x + coord(-1, 1), c.y + coord(0.1, 1), c.z}, {c.x, c.y + coord(-1, 1), c.z + coord(0.1, 1)});
  }
  return b.scene;
}

// A fan of six triangles around the origin sharing edges (some folded), on a ground square coplanar with the
// bottom of a closed box standing on it.
inline Scene shared_edges_and_coplanar_ground() {
  SceneBuilder b;
  const Point3 c{0, 0, 1};
  const Point3 r[6] = {{2, 0, 1}, {1, 2, 1.5}, {-1, 2, 1}, {-2, 0, 2}, {-1, -2, 1}, {1, -2, 0.5}};
  for (int i = 0; i < 6; ++i) b.triangle(c, r[i], r[(i + 1) % 6]);
  b.object("building");
  b.box({3, -1, 0}, {5, 1, 2});
  b.object("ground");
  b.rect(2, 0, -8, 8, -8, 8);
  return b.scene;
}

}  // namespace exactvis::pvs_test
