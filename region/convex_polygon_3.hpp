#pragma once
// Exact convex polygons in 3D (rational vertices), the plane operations from-region visibility needs, and
// the polygon and box helpers of its queries: validation of a source polygon, membership tests, random
// interior points, box faces and enclosing boxes.
#include "kernel/predicates.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <cstdint>
#include <random>
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

// Throws std::invalid_argument with a clear message unless `poly` is a convex planar polygon of positive
// area with >= 3 vertices and no repeated consecutive vertices.
void validate_source_polygon(const Polygon3& poly);

// Closed convex polygon membership (p in the polygon's plane and on the inner side of every edge). Exact.
bool in_closed_polygon(const RationalPoint3& p, const Polygon3& poly);

// Strictly inside the triangle t (its relative interior). Exact.
bool in_triangle_relative_interior(const RationalPoint3& q, const std::array<RationalPoint3, 3>& t);

// The corners of scene.triangles[index] as exact rationals.
std::array<RationalPoint3, 3> triangle_points(const Scene& scene, std::int64_t index);

// --- random interior points (sampling) ---
// n random strictly positive barycentric weights (integers in [1, 2^20]).
std::vector<long> random_weights(std::size_t n, std::mt19937_64& rng);
// The point with those weights (one per vertex): exact, in the relative interior of the convex polygon.
RationalPoint3 weighted_point(const Polygon3& poly, const std::vector<long>& w);
// The same point in double arithmetic, from the polygon's double approximation (heuristics only).
Point3 weighted_point_approx(const std::vector<Point3>& poly, const std::vector<long>& w);
// The vertices rounded to doubles (heuristics only).
std::vector<Point3> approximate_polygon(const Polygon3& poly);
// weighted_point(poly, random_weights(poly.size(), rng)).
RationalPoint3 random_interior_point(const Polygon3& poly, std::mt19937_64& rng);

// --- boxes ---
// An axis-aligned box with exact rational corners (a view cell given as num/den); lo <= hi componentwise.
struct RationalBox3 {
  RationalPoint3 lo, hi;
};
// The box of doubles as exact rationals.
RationalBox3 exact_box(const Box3& b);
// The face of the box on plane coordinate `axis` = lo (high = false) or hi (high = true): a square with
// vertices in the order (u, v) = (lo, lo), (hi, lo), (hi, hi), (lo, hi), u = axis + 1, v = axis + 2 (mod 3).
Polygon3 box_face(const RationalBox3& b, int axis, bool high);
// Closed box membership. Exact.
bool in_closed_box(const RationalPoint3& p, const RationalBox3& b);
// The box rounded to doubles (nearest, CGAL::to_double): for choosing and ordering only, never for a decision.
Box3 approximate_box(const RationalBox3& b);
// A double box containing all the points (interval bounds of their exact coordinates).
Box3 enclosing_box(const std::vector<RationalPoint3>& pts);

}  // namespace exactvis::region
