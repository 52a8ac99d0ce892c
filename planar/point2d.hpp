#pragma once
// Exact planar points and the filtered planar predicates of the 2D visibility complex.
//
// A Point2 holds exact rational coordinates (2D scene files give doubles, slices of 3D scenes give
// rationals) together with their interval enclosures, so the filter layer of filtered_sign costs no GMP
// work. Every predicate returns an exact sign (docs/theory.md, section 7).
#include "kernel/filtered_predicate.hpp"

namespace exactvis {

struct Point2 {
  Exact x, y;
  Interval ix, iy;  // enclosures of x and y, for the interval filter
  double ax = 0, ay = 0;  // nearest doubles, for heuristics and drawing only
  Point2() : ix(0), iy(0) {}
  Point2(const Exact& X, const Exact& Y);
  Point2(double X, double Y) : Point2(Exact(X), Exact(Y)) {}
  friend bool operator==(const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(const Point2& a, const Point2& b) { return !(a == b); }
};

// Coordinate of p in the evaluation number type NT (Interval or Exact).
template <class NT> NT px(const Point2& p) {
  if constexpr (std::is_same_v<NT, Exact>) return p.x; else return p.ix;
}
template <class NT> NT py(const Point2& p) {
  if constexpr (std::is_same_v<NT, Exact>) return p.y; else return p.iy;
}

// Sign of cross(b - a, c - a): Positive iff a, b, c turn counterclockwise.
Sign orientation2(const Point2& a, const Point2& b, const Point2& c);
// Sign of cross(u1 - u0, v1 - v0) for the vectors u = u1-u0 and v = v1-v0.
Sign cross_sign(const Point2& u0, const Point2& u1, const Point2& v0, const Point2& v1);
// Sign of dot(u1 - u0, v1 - v0).
Sign dot_sign(const Point2& u0, const Point2& u1, const Point2& v0, const Point2& v1);
// Signs of the coordinates of u1 - u0.
Sign dx_sign(const Point2& u0, const Point2& u1);
Sign dy_sign(const Point2& u0, const Point2& u1);

// Angular order of vectors around the origin, starting at direction (1,0) and turning counterclockwise:
// -1 if u = u1-u0 comes before v = v1-v0, 0 if same direction, +1 if after. Vectors must be non-zero.
int compare_angle(const Point2& u0, const Point2& u1, const Point2& v0, const Point2& v1);

// True iff direction d = d1-d0 lies in the OPEN counterclockwise sector from direction a = a1-a0 to
// direction b = b1-b0 (a sector of angle in (0, 2pi); a == b in direction means the full turn minus a).
bool in_open_ccw_sector(const Point2& d0, const Point2& d1, const Point2& a0, const Point2& a1,
                        const Point2& b0, const Point2& b1);

// Exact intersection of the line through c with direction d1-d0 and the line through a and b (the lines
// must not be parallel).
Point2 line_intersection(const Point2& c, const Point2& d0, const Point2& d1, const Point2& a, const Point2& b);

// True iff the closed segments [a,b] and [c,d] share a point.
bool segments_intersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

}  // namespace exactvis
