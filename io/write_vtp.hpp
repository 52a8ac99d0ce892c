#pragma once
// VTK XML PolyData (.vtp) writers (through the VTK library; VTK stays out of this header). Files are written
// atomically (see atomic_file.hpp): on failure an OutputError is thrown and no file is left.
#include "kernel/scene.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace exactvis {

// Named per-cell arrays; each must have one value per cell (triangle or polyline).
struct IntArray {
  std::string name;
  std::vector<std::int64_t> values;
};
struct DoubleArray {
  std::string name;
  std::vector<double> values;
};
struct CellArrays {
  std::vector<IntArray> ints;
  std::vector<DoubleArray> doubles;
};

// Input: output path (.vtp), scene, optional extra per-triangle arrays (in the order of Scene::triangles).
// Output: the file: points = Scene::vertices (same indices), one triangle cell per scene triangle, cell arrays
// "id" (stable triangle id), "object" (object index) and the extras. Throws OutputError (also for an extra
// array of the wrong length or a reserved name).
void write_scene_vtp(const std::string& path, const Scene& scene, const CellArrays& extra = {});

// Input: output path, polylines (each >= 2 points), optional per-polyline arrays.
// Output: one polyline cell per input polyline.
void write_polylines_vtp(const std::string& path, const std::vector<std::vector<Point3>>& polylines,
                         const CellArrays& per_line = {});

// Convenience: segments as 2-point polylines.
void write_segments_vtp(const std::string& path, const std::vector<std::pair<Point3, Point3>>& segments,
                        const CellArrays& per_segment = {});

// Input: output path, a triangle surface (points; triangles as point indices) with one `name` value per
// triangle, and polylines (each >= 2 points) with one `name` value per polyline. Output: one file whose
// cells are the polylines then the triangles (VTK's cell order), with the cell arrays `name` and "kind"
// (1 for a polyline, 2 for a triangle). Used for pictures of partitions (a surface coloured by region with
// the boundary curves). Throws OutputError.
void write_surface_with_lines_vtp(const std::string& path, const std::vector<Point3>& points,
                                  const std::vector<std::array<int, 3>>& triangles,
                                  const std::vector<std::int64_t>& triangle_values,
                                  const std::vector<std::vector<Point3>>& polylines,
                                  const std::vector<std::int64_t>& polyline_values, const std::string& name);

}  // namespace exactvis
