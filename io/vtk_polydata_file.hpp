#pragma once
// The one way exactvis writes a vtkPolyData as a .vtp file (io-internal: this header names VTK types).
#include <string>

class vtkPolyData;

namespace exactvis {

// Input: a temporary path and the poly data. Output: the file, VTK XML PolyData with appended raw binary data
// (doubles exactly as stored), zlib-compressed; VTK's own messages are silenced (callers report one line).
// Returns false when VTK could not write it. For use inside write_atomically / OutputFiles.
bool write_polydata_file(const std::string& temp_path, vtkPolyData* poly);

// write_polydata_file through write_atomically: the file at `path` whole, or an OutputError and no file.
void write_polydata_vtp(const std::string& path, vtkPolyData* poly);

}  // namespace exactvis
