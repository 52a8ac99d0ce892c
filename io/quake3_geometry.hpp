#pragma once
// The exact geometry of a Quake 3 map (docs/theory.md, "Quake 3 maps"): leaf volumes, cluster regions,
// brush polytopes, the opaque occluders as triangles, and the drawn triangles.
//
// Conventions:
// - Numbers: the map's float32 plane and bound numbers are taken exactly as rationals; all constructions
//   below are exact (region::ConvexPolyhedron3). Only opaque_scene / write_opaque_obj round, for display.
// - The world box is model 0's bounds [mins, maxs]. Everything is clipped to it.
// - A node's front child is the open side normal . p > dist, its back child the closed side <= dist; a leaf's
//   volume is the closure of its cell: the world box intersected with the closed half-spaces met on the path
//   from the root (node 0) to the leaf. A leaf whose cell has no interior (it lies outside the world box, or
//   it is flat) has the empty volume. Leaves not reached from node 0 (q3map2's unused leaf 0 and the leaves
//   of brush models) have the empty volume and belong to no cluster region.
// - A brush is the world box intersected with {p : normal . p <= dist} over its sides.
#include "io/quake3_bsp.hpp"
#include "kernel/scene.hpp"
#include "region/convex_polyhedron_3.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace exactvis::quake3 {

using region::ConvexPolyhedron3;

// The closed half-space normal . p >= dist of a map plane (its front side, closed), exactly.
region::Plane3 front_halfspace(const BspPlane& plane);

// The world box, model 0's [mins, maxs] (exact).
struct WorldBox {
  RationalPoint3 lo, hi;
};
WorldBox world_box(const BspMap& map);

// The leaf whose cell contains x, by descent from the root (front iff normal . x > dist, exactly).
// Returns a leaf index; x outside the world box still gets the leaf of the unbounded cell. Cost O(depth).
std::int32_t leaf_containing(const BspMap& map, const RationalPoint3& x);

// Every leaf's volume, indexed by leaf (see the conventions above). The leaves' volumes of the world tree
// partition the world box: their interiors are disjoint and their volumes sum to the box's exactly.
// Cost: two polyhedron clips per node (O(nodes * polyhedron size)); uses all cores (oneTBB) on the upper
// levels of the tree.
std::vector<ConvexPolyhedron3> leaf_volumes(const BspMap& map);

// A cluster's region: the union of the volumes of its world leaves with non-empty volume.
struct ClusterRegion {
  std::vector<std::int32_t> leaves;        // leaf indices, increasing
  std::vector<ConvexPolyhedron3> volumes;  // volumes[i] is leaf leaves[i]'s
};
// Indexed by cluster, 0 .. map.cluster_count() - 1 (a cluster without leaves has an empty region).
// Takes the volumes of leaf_volumes(map), or computes them.
std::vector<ClusterRegion> cluster_regions(const BspMap& map, const std::vector<ConvexPolyhedron3>& volumes);
std::vector<ClusterRegion> cluster_regions(const BspMap& map);

// The polytope of brush `brush` (0 <= brush < map.brushes.size()), clipped to the world box.
// Cost O(sides * polyhedron size).
ConvexPolyhedron3 brush_polyhedron(const BspMap& map, std::int32_t brush);

// True iff a brush's shader has the solid content bit (kContentsSolid).
bool is_solid_brush(const BspMap& map, std::int32_t brush);
// The world model's (model 0's) solid brushes, increasing.
std::vector<std::int32_t> solid_world_brushes(const BspMap& map);

// What blocks sight:
//   Leaves:  the world leaves of cluster -1 (the compiled solid space, what the compiler's vis treated as
//            opaque, including never-drawn vis blockers);
//   Brushes: the world model's brushes whose shader has the solid content bit (what a player's eye meets,
//            detail brushes included).
enum class Occluders { Leaves, Brushes };
const char* occluders_name(Occluders occluders);  // "leaves" | "brushes"

// One opaque convex solid: a leaf or brush index, and its non-empty volume.
struct OpaqueSolid {
  std::int32_t index = 0;
  ConvexPolyhedron3 volume;
};
// The opaque solids with non-empty volume, by increasing index. Cost: leaf_volumes, or one
// brush_polyhedron per solid brush.
std::vector<OpaqueSolid> opaque_solids(const BspMap& map, Occluders occluders);

// The boundary triangles of the opaque solids (region::boundary_triangles: outward, none degenerate),
// each with the index of its leaf or brush. Faces shared by two touching solids appear once per solid.
struct OpaqueTriangle {
  std::array<RationalPoint3, 3> corners;
  std::int32_t solid = 0;  // leaf or brush index
};
std::vector<OpaqueTriangle> opaque_triangles(const BspMap& map, Occluders occluders);

// The opaque triangles as a Scene for display and for the mesh-based subcommands: one object per solid,
// named "leaf_N" or "brush_N"; each corner is rounded to a double (to within one ulp, CGAL::to_double),
// which is exact for the many corners that are doubles already (axis-aligned integer geometry); triangles
// that rounding makes degenerate are dropped and counted in Scene::degenerate_dropped.
Scene opaque_scene(const BspMap& map, Occluders occluders);

// Writes opaque_scene as OBJ (io/write_mesh: one `g leaf_N` / `g brush_N` group per solid; atomic).
void write_opaque_obj(const std::string& path, const BspMap& map, Occluders occluders);

// The drawn triangles of polygon and mesh faces (types 1 and 3; patches and billboards are skipped) of
// every model, in face order, one object per face named "face_N"; positions are the float32 vertices,
// exact. Scene::faces_read counts the triangles before degenerate ones are dropped.
Scene drawn_scene(const BspMap& map);

}  // namespace exactvis::quake3
