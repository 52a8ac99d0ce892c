#pragma once
// VTK PolyData (.vtp) output of planar results, in the plane z = 0, for ParaView.
#include <array>
#include <string>
#include <vector>

namespace exactvis {

struct VtpCells2D {
  std::vector<std::vector<std::vector<std::array<double, 2>>>> polygons;  // each: rings (outer, holes...)
  std::vector<int> polygon_values;                                         // one per polygon ("value")
  std::vector<std::array<std::array<double, 2>, 2>> lines;
  std::vector<int> line_values;                                            // one per line ("value")
};

// Writes polygons (each ring as its own polygon cell; holes get value -1) and lines, with an integer cell
// array "value" and a cell array "kind" (0 polygon ring, 1 hole ring, 2 line); points as doubles. Writes
// `path` itself (whole-or-nothing output: write it through OutputFiles or write_atomically, io/atomic_file).
// Throws std::runtime_error ("PATH: cannot write (VTK's error)") on failure; VTK's own log stays silent.
void write_vtp_2d(const std::string& path, const VtpCells2D& cells);

}  // namespace exactvis
