#pragma once
// Sections of 3D scenes by axis-parallel planes: the 2D scene a plane cuts out of closed meshes
// (docs/theory.md section 7, "Slices of 3D scenes").
//
// Plane coordinates: a cut by z = V has coordinates (x, y), by x = V (y, z), by y = V (z, x). The section of
// the scene's triangles by the plane must consist of closed loops (watertight meshes) that avoid mesh
// vertices; nested loops alternate between outer boundaries and holes (even nesting depth: an outer ring,
// odd: a hole of the ring it lies in directly). Exact: crossing points are rationals.
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "planar/scene2d.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace exactvis {

// A slice that cannot be made (bad plane text, a loop that does not close, ...); one-line what() without a
// file name (io/scene2d_json.hpp prefixes it).
struct SliceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An axis-parallel plane: coordinate `axis` (0 = x, 1 = y, 2 = z) equals `value`; `spec` is its text.
struct SlicePlane {
  int axis = 2;
  Exact value;
  std::string spec;
};

// Parses "x=V", "y=V" or "z=V" (V exact: a decimal literal or num/den). Throws SliceError
// ("bad --slice 'SPEC' (expected x=V, y=V or z=V)" or "bad --slice value 'V'").
SlicePlane parse_slice_plane(const std::string& spec);

// The polygons (outer ring, then holes) cut out of `scene` by `plane`. Throws SliceError when the plane
// passes through a mesh vertex, the section is not a set of closed loops, misses the scene, or its loops
// do not nest consistently. O(n log n + L^2 m) for n triangles and L loops of m vertices.
std::vector<PolygonInput2D> slice_scene(const Scene& scene, const SlicePlane& plane);

}  // namespace exactvis
