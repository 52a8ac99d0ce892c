#pragma once
// Loading scenes from mesh files (OBJ, PLY, OFF, STL) through OpenMesh's readers.
//
// The rules (docs/theory.md, "4. Scene model and ids"):
// - Polygons are fan-triangulated from the face's first vertex: (v0,v1,v2), (v0,v2,v3), ...
// - Triangle id = index in load order over all files, fixed BEFORE zero-area triangles (exact `collinear`)
//   are dropped; dropped ids are absent. Each file with drops prints "FILE: dropped N degenerate triangles"
//   to stderr.
// - Vertex ids: each file's vertices in the file's order, files appended in the order given. (STL has no
//   shared vertices in the file; OpenMesh merges equal positions, in order of first appearance.)
// - Objects: OBJ `g`/`o` groups when the file has any, else connected components over shared vertex ids.
// - Coordinates: OBJ, ASCII OFF, PLY (ASCII and binary, any scalar type) and ASCII STL coordinates are read
//   as exact doubles by us (OpenMesh parses float32); binary STL is float32 by definition. Binary OFF is
//   refused. Any finite double is a coordinate, beyond float32's range too, in every format; NaN, infinities
//   and decimals beyond the largest double are refused with one message (io/mesh_text.hpp).
// - Faces: OBJ, OFF and PLY faces are read by us and must equal OpenMesh's reading; PLY counts are checked
//   against their types and the file size first. UTF-16/32 text is refused by name, a UTF-8 BOM skipped.
#include "kernel/scene.hpp"

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace exactvis {

// Bad input file; what() is one line "FILE: problem".
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Loads several files into one scene (ids continue across files, in the order given).
// Input: paths (non-empty). Output: the scene. Throws InputError on any bad input.
Scene load_scenes(const std::vector<std::string>& paths);

// Loads one file; same as load_scenes({path}).
Scene load_scene(const std::string& path);

// A scene from arrays (the Python module's V, F): vertex i = vertices[i], triangle id f = faces[f] (vertex
// indices), zero-area triangles dropped (their ids absent, counted in degenerate_dropped, not printed),
// objects = connected components over shared vertex indices, named "NAME#component<k>". Throws
// InputError("V: vertex I has a non-finite coordinate") or InputError("F: face F refers to vertex V, out
// of range [0, N)").
Scene scene_from_arrays(const std::vector<Point3>& vertices, const std::vector<std::array<std::int64_t, 3>>& faces,
                        const std::string& name = "arrays");

}  // namespace exactvis
