#pragma once
// Writing a scene as a mesh file, chosen by extension. Atomic (see atomic_file.hpp): on failure an
// OutputError is thrown and no file is left.
//   .obj: written here: `v` lines with the shortest decimal that reads back as the same double (exact round
//         trip), then the triangles in id order with a `g <object name>` line whenever the object changes, so
//         load_scene gives back the same vertices, triangles (ids renumbered 0..n-1 if some were absent) and
//         objects (object names must be distinct).
//   .off, .ply, .stl: through OpenMesh's writers (ASCII, 17 significant digits; STL stores float32). OpenMesh's
//         half-edge mesh cannot hold non-manifold faces: such faces get their own copies of their vertices,
//         so vertex indices and connected components (the objects of these formats) may differ.
#include "kernel/scene.hpp"

#include <string>

namespace exactvis {

void write_scene_mesh(const std::string& path, const Scene& scene);

}  // namespace exactvis
