#pragma once
// The radiosity-ready mesh of `exactvis shadows` (shadows/shadow_mesh.hpp) as .vtp (VTK XML PolyData) or
// .ply (ASCII): every receiver's conforming triangulation, vertices not shared between receivers.
// Point data: "irradiance" (per vertex, in units of the light's exitance; 0 when not computed).
// Cell data: "class" (0 umbra, 1 penumbra, 2 lit), "receiver" (stable triangle id), "face" (index of the face
// in its receiver's "faces" list of the JSON), "light_fraction", "face_irradiance" (at the face's sample).
// Files are written atomically (io/atomic_file.hpp); on failure OutputError is thrown and no file is left.
#include "kernel/scene.hpp"
#include "shadows/shadow_mesh.hpp"

#include <string>

namespace exactvis {

// Writes the mesh to `path` (through a temporary, for OutputFiles::write).
bool write_shadow_mesh_vtp(const std::string& temp_path, const Scene& scene, const shadows::ShadowResult& result);
bool write_shadow_mesh_ply(const std::string& temp_path, const Scene& scene, const shadows::ShadowResult& result);

}  // namespace exactvis
