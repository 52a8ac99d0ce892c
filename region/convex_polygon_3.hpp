#pragma once
// Exact convex polygons in 3D (rational vertices) and the plane operations from-region visibility needs.
#include "kernel/predicates.hpp"

#include <vector>

namespace exactvis::region {

using Polygon3 = std::vector<RationalPoint3>;  // convex, vertices in order

// Plane {x : normal . x = offset}; value(x) = normal . x - offset (exact, positive on the normal's side).
struct Plane3 {
  Vec3<Exact> normal;
  Exact offset;
  Exact value(const RationalPoint3& x) const { return dot(normal, x) - offset; }
  Plane3 flipped() const { return {-normal, -offset}; }
};

// Exact sign of plane.value(x), filtered (interval arithmetic first).
Sign plane_side(const Plane3& plane, const Point3& x);
Sign plane_side(const Plane3& plane, const RationalPoint3& x);

// The plane through a, b, c with normal (b - a) x (c - a). Requires non-collinear points.
Plane3 plane_through(const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& c);
// The plane of a polygon (through its first three non-collinear vertices).
Plane3 plane_of(const Polygon3& poly);

// The part of `poly` where plane.value >= 0 (Sutherland-Hodgman, exact). May return fewer than 3 points.
Polygon3 clip_polygon(const Polygon3& poly, const Plane3& plane);

// True iff the polygon has fewer than 3 vertices or all its vertices are collinear (zero area).
bool is_degenerate(const Polygon3& poly);

// Arithmetic mean of the vertices.
RationalPoint3 centroid(const Polygon3& poly);

// True iff every vertex v has plane.value(v) == 0.
bool lies_in_plane(const Polygon3& poly, const Plane3& plane);

}  // namespace exactvis::region
