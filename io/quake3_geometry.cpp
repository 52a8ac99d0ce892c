#include "io/quake3_geometry.hpp"

#include "io/write_mesh.hpp"
#include "kernel/predicates.hpp"

#include <tbb/task_group.h>

#include <memory>

namespace exactvis::quake3 {

using region::Plane3;

region::Plane3 front_halfspace(const BspPlane& plane) {
  return Plane3{Vec3<Exact>(Exact(double(plane.normal[0])), Exact(double(plane.normal[1])),
                            Exact(double(plane.normal[2]))),
                Exact(double(plane.dist))};
}

WorldBox world_box(const BspMap& map) {
  const BspModel& w = map.models.at(0);
  return {{Exact(double(w.mins[0])), Exact(double(w.mins[1])), Exact(double(w.mins[2]))},
          {Exact(double(w.maxs[0])), Exact(double(w.maxs[1])), Exact(double(w.maxs[2]))}};
}

std::int32_t leaf_containing(const BspMap& map, const RationalPoint3& x) {
  std::int32_t c = map.root();
  while (c >= 0) {
    const BspNode& n = map.nodes[c];
    c = n.children[region::plane_side(front_halfspace(map.planes[n.plane]), x) == Sign::Positive ? 0 : 1];
  }
  return -(c + 1);
}

namespace {

// Levels of the tree below which a subtree is done by one task, iteratively (a hostile file may be deep).
constexpr int kParallelLevels = 10;

void clip_subtree(const BspMap& map, std::int32_t node, ConvexPolyhedron3 cell, int level,
                  std::vector<ConvexPolyhedron3>& out, tbb::task_group& tasks) {
  struct Item {
    std::int32_t node;
    ConvexPolyhedron3 cell;
  };
  std::vector<Item> stack;
  stack.push_back({node, std::move(cell)});
  while (!stack.empty()) {
    Item item = std::move(stack.back());
    stack.pop_back();
    const BspNode& n = map.nodes[item.node];
    const Plane3 front = front_halfspace(map.planes[n.plane]);
    for (int k = 0; k < 2; ++k) {
      ConvexPolyhedron3 child = region::clip_polyhedron(item.cell, k == 0 ? front : front.flipped());
      const std::int32_t c = n.children[k];
      if (c < 0) {
        out[-(c + 1)] = std::move(child);  // each leaf is reached once (read_bsp checks the tree)
      } else if (!child.empty()) {
        if (level < kParallelLevels) {
          auto cell = std::make_shared<ConvexPolyhedron3>(std::move(child));  // task_group needs a const callable
          tasks.run([&map, c, level, &out, &tasks, cell] {
            clip_subtree(map, c, std::move(*cell), level + 1, out, tasks);
          });
        } else {
          stack.push_back({c, std::move(child)});
        }
      }
    }
  }
}

// Appends a triangle with the next id, or counts it as dropped when its corners are collinear (exact).
void add_triangle(Scene& scene, const std::array<int, 3>& t, int object) {
  const std::int64_t id = scene.faces_read++;
  if (collinear(to_rational(scene.vertices[t[0]]), to_rational(scene.vertices[t[1]]),
                to_rational(scene.vertices[t[2]]))) {
    ++scene.degenerate_dropped;
    return;
  }
  scene.triangles.push_back({id, t, object});
}

void add_solid_triangles(std::vector<OpaqueTriangle>& out, const OpaqueSolid& solid) {
  for (const auto& t : region::boundary_triangles(solid.volume)) out.push_back({t, solid.index});
}

}  // namespace

std::vector<ConvexPolyhedron3> leaf_volumes(const BspMap& map) {
  std::vector<ConvexPolyhedron3> out(map.leaves.size());
  const WorldBox box = world_box(map);
  ConvexPolyhedron3 world = region::box_polyhedron(box.lo, box.hi);
  if (map.nodes.empty()) {
    out[0] = std::move(world);
    return out;
  }
  if (world.empty()) return out;
  tbb::task_group tasks;
  tasks.run([&] { clip_subtree(map, 0, std::move(world), 0, out, tasks); });
  tasks.wait();
  return out;
}

std::vector<ClusterRegion> cluster_regions(const BspMap& map, const std::vector<ConvexPolyhedron3>& volumes) {
  std::vector<ClusterRegion> regions(static_cast<std::size_t>(map.cluster_count()));
  for (std::size_t i = 0; i < map.leaves.size(); ++i) {
    const std::int32_t c = map.leaves[i].cluster;
    if (!map.world_leaf[i] || c < 0 || volumes[i].empty()) continue;
    regions[c].leaves.push_back(static_cast<std::int32_t>(i));
    regions[c].volumes.push_back(volumes[i]);
  }
  return regions;
}

std::vector<ClusterRegion> cluster_regions(const BspMap& map) { return cluster_regions(map, leaf_volumes(map)); }

ConvexPolyhedron3 brush_polyhedron(const BspMap& map, std::int32_t brush) {
  const BspBrush& b = map.brushes.at(brush);
  std::vector<Plane3> inside;
  for (std::int32_t s = 0; s < b.n_sides; ++s)
    inside.push_back(front_halfspace(map.planes[map.brush_sides[b.first_side + s].plane]).flipped());
  const WorldBox box = world_box(map);
  return region::intersect_halfspaces(box.lo, box.hi, inside);
}

bool is_solid_brush(const BspMap& map, std::int32_t brush) {
  return (map.shaders[map.brushes.at(brush).shader].content_flags & kContentsSolid) != 0;
}

std::vector<std::int32_t> solid_world_brushes(const BspMap& map) {
  std::vector<std::int32_t> out;
  const BspModel& w = map.models.at(0);
  for (std::int32_t b = w.first_brush; b < w.first_brush + w.n_brushes; ++b)
    if (is_solid_brush(map, b)) out.push_back(b);
  return out;
}

const char* occluders_name(Occluders occluders) { return occluders == Occluders::Leaves ? "leaves" : "brushes"; }

std::vector<OpaqueSolid> opaque_solids(const BspMap& map, Occluders occluders) {
  std::vector<OpaqueSolid> out;
  if (occluders == Occluders::Leaves) {
    std::vector<ConvexPolyhedron3> volumes = leaf_volumes(map);
    for (std::size_t i = 0; i < map.leaves.size(); ++i)
      if (map.world_leaf[i] && map.leaves[i].cluster == -1 && !volumes[i].empty())
        out.push_back({static_cast<std::int32_t>(i), std::move(volumes[i])});
    return out;
  }
  const std::vector<std::int32_t> brushes = solid_world_brushes(map);
  std::vector<ConvexPolyhedron3> volumes(brushes.size());
  tbb::task_group tasks;
  for (std::size_t i = 0; i < brushes.size(); ++i)
    tasks.run([&, i] { volumes[i] = brush_polyhedron(map, brushes[i]); });
  tasks.wait();
  for (std::size_t i = 0; i < brushes.size(); ++i)
    if (!volumes[i].empty()) out.push_back({brushes[i], std::move(volumes[i])});
  return out;
}

std::vector<OpaqueTriangle> opaque_triangles(const BspMap& map, Occluders occluders) {
  std::vector<OpaqueTriangle> out;
  for (const OpaqueSolid& s : opaque_solids(map, occluders)) add_solid_triangles(out, s);
  return out;
}

Scene opaque_scene(const BspMap& map, Occluders occluders) {
  Scene scene;
  const std::string prefix = occluders == Occluders::Leaves ? "leaf_" : "brush_";
  for (const OpaqueSolid& s : opaque_solids(map, occluders)) {
    const int object = static_cast<int>(scene.objects.size());
    scene.objects.push_back({prefix + std::to_string(s.index)});
    const int base = static_cast<int>(scene.vertices.size());
    for (const RationalPoint3& v : s.volume.vertices)
      scene.vertices.push_back({CGAL::to_double(v.x), CGAL::to_double(v.y), CGAL::to_double(v.z)});
    for (const auto& face : s.volume.faces)
      for (std::size_t i = 1; i + 1 < face.loop.size(); ++i) {
        add_triangle(scene, {base + face.loop[0], base + face.loop[i], base + face.loop[i + 1]}, object);
      }
  }
  return scene;
}

void write_opaque_obj(const std::string& path, const BspMap& map, Occluders occluders) {
  write_scene_mesh(path, opaque_scene(map, occluders));
}

Scene drawn_scene(const BspMap& map) {
  Scene scene;
  for (const BspVertex& v : map.vertices)
    scene.vertices.push_back({double(v.position[0]), double(v.position[1]), double(v.position[2])});
  for (std::size_t f = 0; f < map.faces.size(); ++f) {
    const BspFace& face = map.faces[f];
    if (face.type != kFacePolygon && face.type != kFaceMesh) continue;
    const int object = static_cast<int>(scene.objects.size());
    scene.objects.push_back({"face_" + std::to_string(f)});
    for (std::int32_t k = 0; k + 2 < face.n_mesh_vertices; k += 3) {
      std::array<int, 3> t;
      for (int j = 0; j < 3; ++j) t[j] = face.first_vertex + map.mesh_vertices[face.first_mesh_vertex + k + j];
      add_triangle(scene, t, object);
    }
  }
  return scene;
}

}  // namespace exactvis::quake3
