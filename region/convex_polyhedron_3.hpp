#pragma once
// Exact bounded convex polyhedra (rational vertices), built by clipping a box with closed half-spaces.
//
// Representation: vertices, and faces as vertex loops counter-clockwise seen from outside, each with its
// supporting plane oriented inward (plane.value(x) >= 0 on the polyhedron). Every vertex is a true corner
// (no vertex lies inside an edge or a face) and every face has area, so the loops are strictly convex.
// A polyhedron either has a non-empty interior or is empty (no faces): clipping that leaves only a flat
// polygon, a segment or a point gives the empty polyhedron (docs/theory.md, "Quake 3 maps": a leaf's volume
// is the closure of its interior).
#include "region/convex_polygon_3.hpp"

#include <array>
#include <vector>

namespace exactvis::region {

struct ConvexPolyhedron3 {
  struct Face {
    Plane3 plane;            // inward: plane.value(x) >= 0 for x in the polyhedron, == 0 on the face
    std::vector<int> loop;   // indices into vertices, counter-clockwise seen from outside, >= 3
  };
  std::vector<RationalPoint3> vertices;
  std::vector<Face> faces;
  bool empty() const { return faces.empty(); }
};

// The box [lo, hi]; empty unless lo < hi in every coordinate. 8 vertices, 6 faces.
ConvexPolyhedron3 box_polyhedron(const RationalPoint3& lo, const RationalPoint3& hi);

// The part of `poly` where keep.value(x) >= 0 (the closed half-space on the side of keep's normal);
// empty when that part has no interior. Exact; plane sides are filtered (interval first), intersection
// points computed exactly only on edges the plane crosses. Cost O(V + sum of face sizes).
ConvexPolyhedron3 clip_polyhedron(const ConvexPolyhedron3& poly, const Plane3& keep);

// The box [lo, hi] intersected with every half-space keep[i].value(x) >= 0, by successive clipping.
// Cost O(k (V + E)) for k planes.
ConvexPolyhedron3 intersect_halfspaces(const RationalPoint3& lo, const RationalPoint3& hi,
                                       const std::vector<Plane3>& keep);

// Exact volume (0 for the empty polyhedron), as a sum of signed tetrahedra over the faces' fans.
Exact volume(const ConvexPolyhedron3& poly);

// The boundary as triangles, each face fanned from its first vertex, counter-clockwise seen from outside
// (so (b - a) x (c - a) points outward). None is degenerate. Cost O(sum of face sizes).
std::vector<std::array<RationalPoint3, 3>> boundary_triangles(const ConvexPolyhedron3& poly);

enum class Containment { Outside, Boundary, Interior };

// Where x lies relative to the closed polyhedron (exact, filtered). The empty polyhedron contains nothing.
Containment locate(const ConvexPolyhedron3& poly, const RationalPoint3& x);

// The part of a convex polygon outside a closed convex polyhedron, as convex polygons of positive area:
// piece k is poly ∩ {h_1 >= 0, ..., h_{k-1} >= 0, h_k <= 0} over the solid's inward face planes h_i, skipping
// planes that contain poly (docs/theory.md §8.2). The pieces' interiors are disjoint, they cover poly minus
// the solid up to a set of zero area, and the relative interior of every piece lies outside the closed solid
// (strictly on the outer side of its h_k). Returns {poly} when one face plane has poly on its closed outer
// side (poly meets the solid in at most an edge); nothing when poly lies in the solid. Requires poly convex
// with positive area. Exact. Cost O(faces * poly size).
std::vector<Polygon3> polygon_outside(const Polygon3& poly, const ConvexPolyhedron3& solid);

}  // namespace exactvis::region
