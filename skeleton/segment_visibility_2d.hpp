#pragma once
// Segment-to-segment (from-region) visibility in the plane, exact, with a witness.
#include "planar/scene2d.hpp"

#include <optional>
#include <stdexcept>
#include <vector>

namespace exactvis {

struct SegmentVisibility2D {
  bool visible = false;
  Point2 witness_s, witness_t;  // if visible: points of S and T whose open segment lies in the open free space
  std::size_t candidates = 0;   // candidate segments tested
};

// Does some point of S = [s0, s1] see some point of T = [t0, t1]? S and T must have positive length, meet
// no polygon boundary and lie outside the objects (throws std::invalid_argument otherwise).
//
// Method (docs/theory.md, section 7): in the parameter square (sigma, tau) of segments s(sigma) t(tau), the
// free segments form an open set bounded by the curves "s, t and a scene vertex v are collinear". Where two
// such curves cross, or a curve leaves the square or has a pole, the line through two points of
// {vertices, t0, t1} (or through v parallel to T) meets S: finitely many rational sigmas. Between two
// consecutive ones the curves are disjoint graphs tau_v(sigma), so one vertical line sigma* per gap and one tau*
// between consecutive tau_v(sigma*) sample every cell. Each sample is tested exactly; the answer is complete
// (never "not visible" when a witness exists). O(n^2) gaps x O(n) cells x O(n) test = O(n^4) worst case;
// stops at the first witness.
SegmentVisibility2D segment_visibility(const Scene2D& scene, const Point2& s0, const Point2& s1, const Point2& t0,
                                       const Point2& t1);

// Appends to `out` the parameter lambda of the point a + lambda (dx, dy) where that line meets the line through
// p with direction (ex, ey), unless the two are parallel. Exact.
void add_line_crossing(std::vector<Exact>& out, const Point2& a, const Exact& dx, const Exact& dy, const Point2& p,
                       const Exact& ex, const Exact& ey);

// The values of v strictly inside (0, 1), with 0 and 1 added, sorted and distinct: the cuts of [0, 1].
std::vector<Exact> unit_interval_cuts(std::vector<Exact> v);

// Throws std::invalid_argument("<name> has zero length / meets a polygon boundary / lies inside an object")
// unless [a, b] has positive length, meets no polygon boundary and lies outside the objects. O(n).
void require_free_segment(const Scene2D& scene, const Point2& a, const Point2& b, const char* name);

// True iff the open segment (s, t) meets no boundary point (s and t must not lie on a boundary); with s
// outside the objects this means the segment lies in the open free space. Exact, O(n).
bool open_segment_free(const Scene2D& scene, const Point2& s, const Point2& t);

}  // namespace exactvis
