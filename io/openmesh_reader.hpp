#pragma once
// The second reader of every mesh file: OpenMesh's. Our own parsers read the coordinates exactly and the
// faces as written; OpenMesh must read the same vertex count, the same faces and (up to float32 rounding) the
// same coordinates, or loading fails (docs/theory.md, section 4).
#include <OpenMesh/Core/Geometry/VectorT.hh>

#include "kernel/scene.hpp"

#include <string>
#include <vector>

namespace exactvis::mesh_io {

// What OpenMesh's reader delivered, in its order: points (float32, file order) and faces as file vertex
// indices (-1 for a handle the file never made), or, when expected faces were given, only whether they
// were exactly those (faces then stays empty: a million faces need not be stored twice).
struct OpenMeshResult {
  std::vector<OpenMesh::Vec3f> points;
  std::vector<std::vector<int>> faces;
  std::size_t face_count = 0;
  bool faces_match = true;  // with expected faces: same count, same lists in the same order
};

// Reads `path` with OpenMesh; if `text` is given, OpenMesh reads that text instead (as format `ext`, e.g.
// "off"). OpenMesh's own messages are silenced. Fails (InputError "PATH: ...") when OpenMesh cannot read it.
OpenMeshResult read_with_openmesh(const std::string& path, const std::string* text = nullptr,
                                  const std::string& ext = "",
                                  const std::vector<std::vector<int>>* expected_faces = nullptr);

// Fails unless OpenMesh read as many points as `exact` and each coordinate within float32's normal range
// equals ours rounded to float32 (up to one float ulp: decimal -> double -> float may round twice).
void check_same_points(const std::string& path, const std::vector<Point3>& exact,
                       const std::vector<OpenMesh::Vec3f>& om);

}  // namespace exactvis::mesh_io
