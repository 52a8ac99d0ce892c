#pragma once
// Small adversarial scenes for the PVS suites: a closed room with a pinhole, triangles sharing edges,
// ground coplanar with building bottoms, built triangle by triangle with ids in insertion order.
#include "kernel/scene.hpp"
#include "tests/region/region_scene_builder.hpp"

#include <random>
#include <string>

namespace exactvis::pvs_test {

using SceneBuilder = region_test::SceneBuilder;

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
