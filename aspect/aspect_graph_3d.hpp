#pragma once
// The aspect graph of a 3D model (docs/theory.md, "Aspect graphs of polyhedra"): regions of viewpoints
// with one aspect, of any dimension, and their adjacency with the visual event on the common boundary.
// The result type shared by every way of computing it (convex models: aspect/convex_aspect_graph.hpp).
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace exactvis {

// Orthographic: viewpoints are directions d (the viewer at infinity along +d). Perspective: points outside
// the closed model. Plane: perspective viewpoints restricted to a given plane (regions of the plane).
enum class ViewModel { Orthographic, Perspective, Plane };

struct AspectRegion3 {
  int dimension = 0;                  // orthographic 0 .. 2 (on the sphere), perspective 0 .. 3, plane 0 .. 2
  std::vector<std::int64_t> aspect;   // stable ids of the triangles seen with positive measure, ascending
  // A viewpoint of the region, exact: orthographic a direction scaled so that its largest |component| is 1,
  // perspective a point (on the plane for ViewModel::Plane). Taken in a cell of the region's largest dimension.
  Vec3<Exact> sample;
};

// One visual event: EV (a vertex and an edge, scene vertex indices) or EEE (three edges, `edges`). `triangles`
// are the triangles whose visibility the event changes (for a convex model: the face in the event's plane).
struct AspectEvent3 {
  std::string type = "EV";
  int vertex = -1;
  std::array<int, 2> edge{-1, -1};
  std::array<std::array<int, 2>, 3> edges{};  // EEE: the three edges (vertex indices, each sorted)
  std::vector<std::int64_t> triangles;
};

// The EV events of an adjacency from (vertex, edge) -> the ids of the triangles whose visibility differs, in
// key order (the form the graphs collect them in).
inline std::vector<AspectEvent3> ev_events_of(
    const std::map<std::pair<int, std::array<int, 2>>, std::set<std::int64_t>>& triangles_of) {
  std::vector<AspectEvent3> out;
  for (const auto& [ve, tris] : triangles_of) {
    AspectEvent3 e;
    e.vertex = ve.first;
    e.edge = ve.second;
    e.triangles.assign(tris.begin(), tris.end());
    out.push_back(std::move(e));
  }
  return out;
}

struct AspectAdjacency3 {
  int a = 0, b = 0;                   // region ids, a < b
  std::vector<AspectEvent3> events;   // the events on the common boundary (several where events cross)
};

struct AspectGraph3 {
  ViewModel view = ViewModel::Orthographic;
  std::vector<AspectRegion3> regions;
  std::vector<AspectAdjacency3> adjacency;  // sorted by (a, b)
  // Cells of the underlying partition per dimension (orthographic: on the sphere), before merging.
  std::array<std::int64_t, 4> cells{0, 0, 0, 0};
  // Orthographic graphs of non-convex models (aspect/orthographic_aspect_graph,
  // aspect/general_orthographic_aspect_graph) and plane graphs (aspect/plane_aspect_graph) also list every
  // cell of the partition with its region and an exact viewpoint in it (for tests and pictures); empty
  // otherwise. (General graphs: split arcs and their split points share the sign vector of their arc.)
  struct SampledCell {
    int region = 0, dimension = 0;
    Vec3<Exact> direction;
    std::string signs;  // per circle: the sign ('-', '0', '+') of circles[k] . d in this cell
  };
  std::vector<SampledCell> sampled_cells;
  std::vector<Vec3<Exact>> circles;  // the great circles {n . d = 0} of the partition (their normals n)
};

}  // namespace exactvis
