#pragma once
// The arrangement of finitely many great circles on the unit sphere, exactly, as a cell complex with its
// incidences (docs/theory.md §10.6): vertices (directions on two or more circles), arcs (the pieces of each
// circle between consecutive vertices) and faces (the components of the complement), each face with its
// boundary arcs. The orthographic aspect graphs use it instead of the central case of
// aspect/plane_arrangement_3: the same cells, found from the circles' crossings and the cyclic orders
// around circles and vertices instead of by sign vectors, so a cell costs O(its size) and not O(m).
//
// Circle k is {d : normals[k] . d = 0}. Directions are exact rational vectors up to positive scaling
// (stored scaled so that their largest |component| is 1). Arc a runs along its circle counter-clockwise
// about the circle's normal from `from` to `to`; its halfedge 2a goes from -> to, 2a + 1 to -> from. The sphere
// is oriented by the outward normal: a face lies to the left of each of its halfedges.
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"

#include <vector>

namespace exactvis {

struct GreatCircleArrangement {
  std::vector<Vec3<Exact>> vertices;
  std::vector<std::vector<int>> vertex_circles;  // per vertex: the circles through it, ascending
  struct Arc {
    int circle = 0;
    int from = 0, to = 0;            // vertices
    int left = -1, right = -1;       // faces left of halfedge from -> to (the side n . d > 0) and right of it
  };
  std::vector<Arc> arcs;
  struct Face {
    std::vector<int> halfedges;      // its boundary, in order (halfedge h: arc h / 2, reversed if h is odd)
  };
  std::vector<Face> faces;
};

// Input: the normals of distinct great circles (pairwise non-parallel) that span R^3 (else
// std::invalid_argument: then some face would not be a convex polygon). Output: the arrangement; V - E + F = 2
// is checked (std::logic_error otherwise). Cost: O(m^2) vertices, each circle's vertices sorted by angle and
// each vertex's arcs by angle (O(m^2 log m) filtered exact orientation signs), O(V + E + F) to trace faces.
GreatCircleArrangement great_circle_arrangement(const std::vector<Vec3<Exact>>& normals);

// v (non-zero) scaled so that its largest |component| is 1: the convention of every exact direction on the
// viewing sphere here (circle normals, samples).
Vec3<Exact> scaled_to_unit_max(const Vec3<Exact>& v);

// An exact direction strictly inside cell: a face's (the sum of its vertices: every face is a convex
// spherical polygon with at least three vertices), an arc's (the sum of its ends, or normal x from for a
// half circle), scaled so that the largest |component| is 1.
Vec3<Exact> face_sample(const GreatCircleArrangement& arr, int face);
Vec3<Exact> arc_sample(const GreatCircleArrangement& arr, const std::vector<Vec3<Exact>>& normals, int arc);

}  // namespace exactvis
