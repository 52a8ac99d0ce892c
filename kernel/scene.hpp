#pragma once
// The scene model: a triangle soup with stable ids, grouped into objects.
//
// Ids (docs/theory.md, "Scene ids"): triangles are numbered in load order, polygons fan-triangulated from
// their first vertex, files in the order given; a triangle's id is fixed before degenerate (zero-area)
// triangles are dropped, so a dropped triangle's id is simply absent. Vertex ids are indices into
// Scene::vertices, numbered in load order over all files (each file's vertices appended in file order).
#include "kernel/vec3.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace exactvis {

struct SceneTriangle {
  std::int64_t id = 0;          // stable id (load order, before dropping degenerate triangles)
  std::array<int, 3> v{};       // indices into Scene::vertices
  int object = 0;               // index into Scene::objects
};

struct SceneObject {
  std::string name;             // OBJ group/object name, or "<file>#component<k>"
};

struct Scene {
  std::vector<Point3> vertices;
  std::vector<SceneTriangle> triangles;  // sorted by id
  std::vector<SceneObject> objects;
  std::int64_t faces_read = 0;           // triangles before dropping degenerate ones
  std::int64_t degenerate_dropped = 0;

  const Point3& corner(const SceneTriangle& t, int k) const { return vertices[t.v[k]]; }
  // Index into `triangles` of the triangle with stable id `id`, or -1.
  std::int64_t index_of_id(std::int64_t id) const;
};

struct Box3 {
  Point3 lo, hi;
  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
};

Box3 bounding_box(const Scene& scene);
// The bounding box of one triangle's corners.
Box3 triangle_box(const Scene& scene, const SceneTriangle& t);

// The common part of two boxes (empty() if they do not overlap).
Box3 intersection(const Box3& a, const Box3& b);

}  // namespace exactvis
