#pragma once
// Segment-triangle intersection tests (predicates only: filtered orient3d / projected orient2d signs and
// exact coordinate comparisons, no constructions). Every degenerate case is decided exactly:
// segments of zero length, triangles of zero area (collinear or coincident corners, treated as the point set
// conv{t0,t1,t2}, i.e. a segment or a point), coplanar overlap, touching at edges, vertices or endpoints.
// See docs/theory.md, "Constructions".
#include "kernel/predicates.hpp"

namespace exactvis {

// Closed segment [a,b] vs closed triangle conv{t0,t1,t2}.
// Inputs: points with double (Point3) or exact rational (RationalPoint3) coordinates.
// Output: true iff the two closed point sets share at least one point.
bool segment_meets_closed_triangle(const Point3& a, const Point3& b, const Point3& t0, const Point3& t1,
                                   const Point3& t2);
bool segment_meets_closed_triangle(const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& t0,
                                   const RationalPoint3& t1, const RationalPoint3& t2);

// Open segment (a,b) = [a,b] minus {a,b} vs closed triangle conv{t0,t1,t2}: the test used to re-check a
// witness segment (its endpoints lie on the source and target and must not count as blocked).
// Output: true iff some point strictly between a and b lies in the closed triangle; false when a == b
// (the open segment is empty).
bool open_segment_meets_closed_triangle(const Point3& a, const Point3& b, const Point3& t0, const Point3& t1,
                                        const Point3& t2);
bool open_segment_meets_closed_triangle(const RationalPoint3& a, const RationalPoint3& b,
                                        const RationalPoint3& t0, const RationalPoint3& t1,
                                        const RationalPoint3& t2);

// Transversal crossing: true iff a and b lie strictly on opposite sides of the plane of a non-degenerate
// triangle and the segment passes through the triangle's relative interior (not through an edge or vertex).
// False for zero-area triangles (they have no relative interior of dimension 2) and coplanar segments.
bool segment_crosses_triangle_interior(const Point3& a, const Point3& b, const Point3& t0, const Point3& t1,
                                       const Point3& t2);
bool segment_crosses_triangle_interior(const RationalPoint3& a, const RationalPoint3& b,
                                       const RationalPoint3& t0, const RationalPoint3& t1,
                                       const RationalPoint3& t2);

// Closed point-in-closed-triangle test (any triangle, degenerate ones as their point set).
bool point_in_closed_triangle(const Point3& p, const Point3& t0, const Point3& t1, const Point3& t2);
bool point_in_closed_triangle(const RationalPoint3& p, const RationalPoint3& t0, const RationalPoint3& t1,
                              const RationalPoint3& t2);

}  // namespace exactvis
