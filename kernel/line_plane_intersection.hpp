#pragma once
// Intersection of a directed line with the plane through three points (exact rational construction).
#include "kernel/predicates.hpp"

namespace exactvis {

enum class LinePlaneKind {
  Point,           // one intersection point
  Parallel,        // line parallel to the plane, not in it: no point
  Contained,       // line lies in the plane: every point
  DegenerateInput  // the three plane points are collinear, or the line's two points coincide (d = 0)
};

struct LinePlaneIntersection {
  LinePlaneKind kind = LinePlaneKind::DegenerateInput;
  RationalPoint3 point;  // kind == Point: the exact intersection point
  Exact t = 0;           // kind == Point, point form only: point = p + t (q - p); t in [0,1] iff on [p,q]
};

// Line through p then q vs plane through t0, t1, t2 (points with double or exact coordinates).
// Output: kind; for Point the exact point and its parameter t along p->q.
LinePlaneIntersection line_plane_intersection(const Point3& p, const Point3& q, const Point3& t0,
                                              const Point3& t1, const Point3& t2);
LinePlaneIntersection line_plane_intersection(const RationalPoint3& p, const RationalPoint3& q,
                                              const RationalPoint3& t0, const RationalPoint3& t1,
                                              const RationalPoint3& t2);

// Line given by exact Plücker coordinates (d, m) (must be a real line: d != 0, d.m = 0, else
// DegenerateInput) vs plane through t0, t1, t2. Output: kind and, for Point, the exact point
// X = (n x m + w d) / (n . d) where n.X = w is the plane; t is left 0 (no origin on the line).
LinePlaneIntersection line_plane_intersection(const PluckerLine<Exact>& line, const RationalPoint3& t0,
                                              const RationalPoint3& t1, const RationalPoint3& t2);

}  // namespace exactvis
