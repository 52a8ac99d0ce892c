#pragma once
// The exact orthographic aspect of a general polyhedral model from one direction (docs/theory.md §10.9):
// the triangles seen with positive measure by the viewer at infinity along +d.
//
// Any model whose triangles meet only in shared corners and edges (no crossings, no overlapping coplanar
// triangles); triangles are two-sided, the model need not be closed. For a triangle t not parallel to d let
// H_t be the closed half-space of t's plane on the viewer's side (n_t . (x - a_t) has the sign of n_t . d, or
// is 0). A point x of t is hidden iff its ray {x + s d, s > 0} meets another triangle u, and that happens
// in H_t, so iff the image of x along d lies in the image of u ∩ H_t. So t is in the aspect iff
// T' \ ∪_u proj_d(u ∩ H_t) has positive area (T' = t's image), decided by CGAL's regularized Boolean set
// operations (Polygon_set_2) on exact rationals (the lazy exact kernel: interval filter, exact fallback).
// Occluders in t's plane and occluders seen edge-on have null images and are left out: they change the
// hidden set by a null set only (they meet t's image in a null set, because triangles do not overlap).
// A triangle parallel to d has a null image and is never in the aspect.
//
// Every triangle in the aspect carries a witness: a point strictly inside it whose open ray towards the viewer
// meets no closed scene triangle (re-checked exactly by kernel/ray_first_hit before it is returned).
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "kernel/vec3.hpp"

#include <cstdint>
#include <vector>

namespace exactvis {

class TriangleIndex;

struct DirectionAspect {
  std::vector<std::int64_t> aspect;  // stable ids of the triangles seen, ascending
  struct Witness {
    std::int64_t triangle = -1;  // stable id
    Vec3<Exact> point;           // strictly inside the triangle; {point + s d, s > 0} meets no scene triangle
  };
  std::vector<Witness> witnesses;    // one per entry of `aspect`, same order
};

// Input: the scene, d != 0 (exact), and optionally the scene's spatial index (built here when null; pass it
// when calling for many directions). Output: the aspect with one exact witness per visible triangle.
// Throws std::invalid_argument for d = 0. Cost: per triangle, the occluders whose image boxes meet its image
// (O(n) box tests), one aggregated exact union of their clipped images and one difference, O(k log k) for k
// occluder edges in general position; the witnesses one exact ray cast each.
DirectionAspect direction_aspect(const Scene& scene, const Vec3<Exact>& d, const TriangleIndex* index = nullptr);

}  // namespace exactvis
