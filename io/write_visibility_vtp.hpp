#pragma once
// One .vtp file showing a from-region visibility result: the scene's triangles with cell arrays
// "id" (scene triangle id), "object", "visible" (1 visible, 0 hidden, -1 not queried) and "kind" (0); the
// witness segments as line cells with "id" = the triangle they prove visible and "kind" = 1; the source (the
// view cell's 6 faces, or the source polygon) as polygon cells with "id" = -1 and "kind" = 2. "visible" is a
// float array, NaN on witnesses and source, so colouring by it paints the scene's triangles only.
#include "kernel/scene.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace exactvis {

struct WitnessSegment {
  std::int64_t triangle_id;
  Point3 p, q;  // double approximations of the exact witness, for display only
};

// Input: output path, scene, per-triangle state (parallel to scene.triangles: 1, 0 or -1), witnesses, and the
// source's faces (convex polygons, double approximations for display; empty: no source drawn).
// Output: the file, written atomically (throws OutputError on failure, leaving nothing).
void write_visibility_vtp(const std::string& path, const Scene& scene, const std::vector<int>& state,
                          const std::vector<WitnessSegment>& witnesses,
                          const std::vector<std::vector<Point3>>& source_faces = {});

// The per-cell value array of a triangle-state file: its name (also the active scalars), whether it is a
// float array (else int), and the values of the witness lines and source polygons (NaN in a float array
// leaves them uncoloured).
struct TriangleStateArray {
  std::string name;
  bool is_float;
  double witness_value, source_value;
};

// The layout both write_visibility_vtp and write_pvs_check_vtp write: the scene's points, then per witness
// a line cell (its two points appended), per scene triangle a polygon cell, per source face a polygon cell
// (its points appended); cell arrays "id", "object", `array` and "kind" (1 witness, 0 triangle, 2 source).
// Input: `values` parallel to scene.triangles (the caller checks the size). Output: the file, written
// atomically (throws OutputError on failure). Cost: linear in the scene, witnesses and source.
void write_triangle_state_vtp(const std::string& path, const Scene& scene, const std::vector<int>& values,
                              const TriangleStateArray& array, const std::vector<WitnessSegment>& witnesses,
                              const std::vector<std::vector<Point3>>& source_faces);

}  // namespace exactvis
