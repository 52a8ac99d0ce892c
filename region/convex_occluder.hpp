#pragma once
// Closed convex solids of a scene and the single-occluder culling test: a proof, from eight corners each,
// that every segment between two convex sets crosses the solid's surface (docs/theory.md §5.9).
//
// Used as a cheap first "hidden" test before the line-space CSG (PVS hierarchy) and as the single-occluder
// culling of the conservative PVS fallback. Exact: every decision is a filtered exact predicate.
#include "kernel/scene.hpp"
#include "region/convex_polygon_3.hpp"

#include <cstdint>
#include <vector>

namespace exactvis::region {

// A set of scene triangles that bounds a convex polytope P exactly once (the rule of aspect/convex_model:
// supporting planes, matched edges, volume of the hull), so that ∂P is covered by these closed triangles.
struct ConvexSolid {
  int object = 0;                       // index into Scene::objects
  std::vector<std::int64_t> triangles;  // indices into Scene::triangles, ascending
  std::vector<Plane3> facets;           // distinct face planes, value() <= 0 on P
  std::vector<Point3> corners;          // distinct corner points
  Box3 box;                             // bounding box of the corners
};

// Input: a scene. Output: every edge-connected component (triangles sharing an edge, matched by exact
// corner coordinates) of each object that is a closed convex solid; components of fewer than 4 triangles
// are skipped. Order: by object, then by smallest triangle index. Cost: O(n log n) plus one convex-model
// test per component (a CGAL hull of its corners, exact volumes).
std::vector<ConvexSolid> convex_solids(const Scene& scene);

// True iff the closed segment [a, b] meets the closed solid P (exact clipping of the parameter interval by
// the facet half-spaces, compared without divisions). Cost: O(F^2) filtered signs for F facets.
bool segment_meets_solid(const ConvexSolid& solid, const RationalPoint3& a, const RationalPoint3& b);

// True iff the closed box is proved disjoint from the closed solid P: a facet plane leaves all 8 corners
// strictly on its outer side, or an axis strictly separates the corners of P from the box. (Sufficient, not
// necessary: false means "not proved".)
bool box_disjoint_from_solid(const ConvexSolid& solid, const RationalBox3& box);

// Input: a solid, the closed cell C and a closed box B (e.g. a BVH node's box). Output: true proves that
// every segment from a point of C to a point of B has an open interior that meets a closed triangle of the
// solid, so every triangle inside B that is not one of the solid's triangles is hidden from C
// (docs/theory.md §5.9); false means not proved. Method: C and B are proved disjoint from P, and the 64
// corner-to-corner segments meet the closed solid (sufficient by convexity). Cost: 64 segment tests.
bool solid_blocks_box_pair(const ConvexSolid& solid, const RationalBox3& cell, const RationalBox3& box);

}  // namespace exactvis::region
