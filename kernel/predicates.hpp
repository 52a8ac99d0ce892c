#pragma once
// Basic filtered predicates on points given as exact inputs (double or Exact coordinates).
// Every function here returns an exact sign; see filtered_predicate.hpp for the filter.
#include "kernel/filtered_predicate.hpp"
#include "kernel/plucker_line.hpp"

namespace exactvis {

using RationalPoint3 = Vec3<Exact>;

// Convert a point with double or Exact coordinates to the evaluation number type NT.
template <class NT, class C>
Vec3<NT> point_as(const Vec3<C>& p) { return {as<NT>(p.x), as<NT>(p.y), as<NT>(p.z)}; }

// sign of side(line(p1,q1), line(p2,q2)): how the directed line p1->q1 passes the directed line p2->q2.
Sign side_of_lines(const Point3& p1, const Point3& q1, const Point3& p2, const Point3& q2);
Sign side_of_lines(const RationalPoint3& p1, const RationalPoint3& q1, const RationalPoint3& p2,
                   const RationalPoint3& q2);
// sign of side(a, b) for lines given by exact Plücker coordinates.
Sign side_of_lines(const PluckerLine<Exact>& a, const PluckerLine<Exact>& b);

// orient3d(a,b,c,d) = sign of det[b-a, c-a, d-a]: positive iff d lies on the side of plane(a,b,c) that
// (b-a) x (c-a) points to.
Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d);
Sign orient3d(const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& c, const RationalPoint3& d);

// orient2d of the projections of a, b, c onto the coordinate plane orthogonal to `axis` (0, 1 or 2), with
// coordinates taken in cyclic order (axis+1, axis+2): the sign of component `axis` of (b-a) x (c-a).
// For a triangle abc it is the sign of its normal's `axis` component, so it is Zero for all three axes iff
// a, b, c are collinear; and it is the orientation test of the coplanar (projected) configuration.
Sign orient2d_projected(const Point3& a, const Point3& b, const Point3& c, int axis);
Sign orient2d_projected(const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& c, int axis);

// True iff a, b, c are collinear (the triangle abc has zero area).
bool collinear(const Point3& a, const Point3& b, const Point3& c);
bool collinear(const RationalPoint3& a, const RationalPoint3& b, const RationalPoint3& c);

inline RationalPoint3 to_rational(const Point3& p) { return {Exact(p.x), Exact(p.y), Exact(p.z)}; }

}  // namespace exactvis
