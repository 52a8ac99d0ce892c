#pragma once
// The exact aspect graph of a closed convex model (docs/theory.md, "Aspect graphs of polyhedra").
//
// A triangle of a closed convex model is seen with positive measure from a viewpoint iff the viewpoint is
// strictly on the outer side of its plane (orthographic: n . d > 0 for the outward normal n). So the aspect
// is a function of the sign vector of the viewpoint with respect to the face planes:
//   orthographic: the arrangement of the great circles orthogonal to the face normals = the traces on the
//     unit sphere of the central plane arrangement {n . d = 0} (one plane per normal up to sign),
//   perspective: the arrangement of the face planes, restricted to the cells outside the model (at least
//     one positive sign),
//   on a plane of viewpoints: the same arrangement with the viewpoint plane added, restricted to the cells in
//     that plane (their traces: the partition of the plane by the lines where face planes cross it).
// Both are computed by aspect/plane_arrangement_3.hpp; regions by aspect/aspect_regions.hpp. Along any
// chain of cells lower in upper's closure the set of positive planes only grows, so adjacent regions'
// aspects are nested and differ exactly by the faces of the planes the lower cell lies on and the upper
// does not (the events, each named by its plane's EV generator).
#include "aspect/aspect_graph_3d.hpp"
#include "aspect/convex_model.hpp"
#include "kernel/scene.hpp"

namespace exactvis {

// Input: the scene and its convex model (model.convex must be true); view Orthographic or Perspective.
// Output: the aspect graph. Cost: the arrangement, O(m^2) cells orthographic and O(m^3) perspective for m
// face planes, each with O(m) filtered exact sign evaluations.
// `progress` (optional) receives the fraction done of the arrangement, the bulk of the work.
AspectGraph3 convex_aspect_graph(const Scene& scene, const ConvexModel& model, ViewModel view,
                                 void (*progress)(double) = nullptr);

// The same for perspective viewpoints on the plane {normal . x = offset} (normal != 0), view = Plane:
// regions of the plane outside the model, of dimension 0 .. 2. Cost: O(m^3) arrangement cells (the
// arrangement of the face planes and the viewpoint plane), of which O(m^2) lie in the plane.
AspectGraph3 convex_aspect_graph_on_plane(const Scene& scene, const ConvexModel& model, const Vec3<Exact>& normal,
                                          const Exact& offset, void (*progress)(double) = nullptr);

}  // namespace exactvis
