#pragma once
// PLY reading for load_scenes (io/load_scene.hpp): header, vertex coordinates and face lists are read here,
// exactly, and checked against the file's size before anything allocates; OpenMesh's reading must agree.
#include "io/mesh_text.hpp"

#include <string>

namespace exactvis::mesh_io {

// Input: the file's path (for messages and for OpenMesh) and its bytes; `altered`: the bytes differ from
// the file (a byte-order mark was removed), so OpenMesh reads them rather than the file. Output: vertices in
// file order, faces as written. Fails ("PATH: problem") on any malformed, truncated or inconsistent input.
RawMesh load_ply(const std::string& path, const std::string& text, bool altered);

}  // namespace exactvis::mesh_io
