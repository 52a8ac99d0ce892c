#pragma once
// The line through a point P meeting two lines a and b: the intersection of the planes (P, a) and (P, b).
#include "kernel/predicates.hpp"

namespace exactvis {

enum class PointTwoLinesKind {
  Unique,          // exactly one line through P meets both a and b (at finite points)
  None,            // the only candidate (in both planes) is parallel to a or to b: it meets that one only
                   // at infinity, so no line of R^3 through P meets both; `line` holds that candidate
  Infinite,        // P lies on a or on b, or the planes (P,a) and (P,b) coincide: a whole pencil of lines
  DegenerateInput  // a or b is not a real line (d = 0 or d.m != 0)
};

struct LineThroughPointMeetingTwoLines {
  PointTwoLinesKind kind = PointTwoLinesKind::DegenerateInput;
  // Unique / None: the line through P with direction n_a x n_b (n_a, n_b the normals P x d - m of the two
  // planes), as exact Plücker coordinates (d, P x d). Its orientation is this deterministic choice.
  PluckerLine<Exact> line;
};

// Inputs: P (double or exact coordinates), a and b as exact Plücker lines (d, m).
LineThroughPointMeetingTwoLines line_through_point_meeting_two_lines(const RationalPoint3& p,
                                                                     const PluckerLine<Exact>& a,
                                                                     const PluckerLine<Exact>& b);
LineThroughPointMeetingTwoLines line_through_point_meeting_two_lines(const Point3& p,
                                                                     const PluckerLine<Exact>& a,
                                                                     const PluckerLine<Exact>& b);

// Exact Plücker coordinates of the directed line through p then q (d = q - p, m = p x q).
PluckerLine<Exact> exact_line_through(const Point3& p, const Point3& q);
PluckerLine<Exact> exact_line_through(const RationalPoint3& p, const RationalPoint3& q);

}  // namespace exactvis
