#pragma once
// Recognising a closed convex model and its face planes, exactly (docs/theory.md, "Aspect graphs of
// polyhedra", convex models).
//
// A scene is a *closed convex model* when
//   (a) every triangle's plane supports the model: all triangle corners lie in one closed half-space of it,
//       and not all corners lie in one plane (the convex hull is three-dimensional);
//   (b) the triangles, each oriented outward (away from the corners), form a cycle: for every pair of
//       corner points p, q the directed edges p->q and q->p occur equally often (edges are matched by exact
//       coordinates, not vertex ids, so T-junctions are not closed);
//   (c) the outward signed volume of the triangles equals the volume of the convex hull of the corners.
// By (a) every triangle lies on the hull boundary; by (b) the number of triangles covering a point of the
// boundary (a 2-cycle on a sphere) is the same number d almost everywhere; by (c) d = 1. So the triangles
// cover the hull boundary exactly once, and a triangle is seen (with positive measure) from a viewpoint
// iff the viewpoint is strictly on the outer side of its plane (orthographic: d . n > 0).
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace exactvis {

// One face plane of a convex model: {x : normal . x = offset}, the model on the side normal . x <= offset.
struct ModelPlane {
  Vec3<Exact> normal;                   // outward; scaled so that its largest |component| is 1
  Exact offset;
  std::vector<std::int64_t> triangles;  // stable ids of the triangles in this plane, ascending
  // The EV generator naming this plane's event: the smallest-id triangle's first vertex and its opposite
  // edge (scene vertex indices); the lines through the vertex meeting the edge sweep the plane.
  int vertex = -1;
  std::array<int, 2> edge{-1, -1};
};

struct ConvexModel {
  bool convex = false;
  std::string problem;                  // when !convex: why, one line without the file name
  std::vector<ModelPlane> planes;       // ordered by their smallest triangle id
  std::vector<int> plane_of;            // per index into scene.triangles: its plane
};

// Input: a scene (degenerate triangles already dropped). Output: the planes if the scene is a closed convex
// model as defined above, else convex = false and the first failing condition in `problem`.
// Cost: O(P * C) filtered orient3d tests for P distinct planes and C distinct corners, O(n log n) for the
// edge matching, one CGAL convex hull of the corners, exact volumes.
ConvexModel convex_model(const Scene& scene);

}  // namespace exactvis
