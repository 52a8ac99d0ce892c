#pragma once
// The part of a closed solid in front of each of its triangles, and the certificate that it is convex
// (docs/theory.md §10.5, orthographic aspect graphs of non-convex models).
//
// The scene must bound a solid S: its triangles, with vertices merged by exact coordinates, form a closed
// 2-manifold (every edge on exactly two triangles, consistently oriented) without self-intersections. Each
// connected component is oriented outward (a component with negative signed volume is flipped). For a
// triangle t with outward plane side H_t (open half-space), the *front part* is P_t = closure(S ∩ H_t):
// what can hide t from viewers on its outer side (from its inner side t is always hidden: the ray enters S).
// P_t is empty iff no triangle has a point strictly in H_t. Otherwise let V_t be the corners of the
// triangles clipped to the closure of H_t, over the triangles that have a point in H_t. The certificate: the
// plane of every such triangle has all of V_t on one closed side. Then P_t = conv(V_t) (proof in theory
// §10.5: the boundary of P_t lies in supporting planes), a convex polytope; if the certificate fails for
// some t the model is rejected (the aspect may then change at EEE events, which are not implemented).
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "kernel/vec3.hpp"

#include <string>
#include <vector>

namespace exactvis {

struct TriangleFront {
  Vec3<Exact> outward;              // outward normal of the triangle (not normalised)
  std::vector<Vec3<Exact>> points;  // V_t, distinct, exact; empty = nothing in front of t
};

struct ClosedSolidFronts {
  bool ok = false;
  std::string problem;              // when !ok: why, one line without the file name
  // When !ok: the model is a valid closed solid and only a front part is not convex (outside the class of
  // §10.5; aspect/general_orthographic_aspect_graph may still take it).
  bool outside_class = false;
  // When !ok: the triangles do not form a closed oriented 2-manifold (an edge on one triangle, a non-manifold
  // edge or vertex, or inconsistent orientations): not a closed solid at all. The orthographic route for such
  // models takes every triangle as a two-sided occluder (theory §10.10; aspect/triangle_contacts checks them).
  bool not_solid = false;
  std::vector<TriangleFront> fronts;  // per index into scene.triangles
};

// Input: a scene (degenerate triangles dropped). Output: the fronts, or ok = false with the first problem
// (not closed, non-manifold, self-intersecting, or a front part that is not convex). Cost: CGAL's
// self-intersection test (AABB tree), then O(n^2) exact plane clips and O(n * |V_t|) exact orientation signs
// per triangle for n triangles.
ClosedSolidFronts closed_solid_fronts(const Scene& scene);

}  // namespace exactvis
