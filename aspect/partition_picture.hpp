#pragma once
// Pictures of aspect partitions of convex models, for display only (VTP files, docs/cli.md): a triangulated
// viewing sphere or a square of the viewpoint plane, each triangle labelled with the region of the viewpoint
// at its centroid, and the boundary curves (the great circles of the face normals, or the trace lines of
// the face planes). Floating point throughout: the labels of triangles that straddle a boundary are those
// of their centroids; the exact partition is the aspect graph itself.
#include "aspect/aspect_graph_3d.hpp"
#include "aspect/convex_model.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace exactvis {

struct PartitionPicture {
  std::vector<Point3> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::int64_t> triangle_region;  // region id; -1 inside the model (plane pictures)
  std::vector<std::vector<Point3>> curves;    // boundary polylines
  std::vector<std::int64_t> curve_plane;      // per curve: the model plane index it belongs to (the first)
};

// The unit sphere (an octahedron subdivided `subdivisions` times: 8 * 4^subdivisions triangles), graph
// orthographic.
PartitionPicture sphere_picture(const ConvexModel& model, const AspectGraph3& graph, int subdivisions);

// Orthographic graphs of non-convex models (aspect/orthographic_aspect_graph: graph.circles and the cells'
// sign vectors): the same sphere, each triangle labelled with the region of the partition cell holding its
// centroid (the centroid's sign vector against the circles, exact signs of its double coordinates), and the
// circles drawn. Cost: triangles x circles signs.
PartitionPicture sphere_picture_of_cells(const AspectGraph3& graph, int subdivisions);

// The square [x0, x1] x [y0, y1] of the plane z = h (cells x cells squares, two triangles each), graph
// computed on that plane.
PartitionPicture plane_picture(const ConvexModel& model, const AspectGraph3& graph, double h, double x0, double y0,
                               double x1, double y1, int cells);

// Plane graphs of non-convex models (aspect/plane_aspect_graph: graph.circles are the trace lines (A, B, C)
// of {A x + B y + C = 0}, and the cells' sign vectors): the square as for plane_picture, each triangle
// labelled with the region of the cell holding its centroid (-1 inside the model), and the lines drawn.
// Cost: triangles x lines signs.
PartitionPicture plane_picture_of_cells(const AspectGraph3& graph, double h, double x0, double y0, double x1,
                                        double y1, int cells);

}  // namespace exactvis
