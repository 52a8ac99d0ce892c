#pragma once
// Segment-to-segment (from-region) visibility in the plane answered from the visibility complex: exact, with
// a witness (docs/theory.md, section 7, "Segment-to-segment visibility from the complex").
#include "skeleton/complex_walk_2d.hpp"
#include "skeleton/segment_visibility_2d.hpp"

namespace exactvis {

// Counters of one query.
struct ComplexSegmentStats2D {
  std::size_t breakpoints = 0;  // sigmas computed (lines of visible pairs, ring edges, t0/t1 not parallel to S)
  std::size_t walks = 0;        // visibility polygons walked (one per gap of sigma, until a witness)
};

// Does some point of S = [s0, s1] see some point of T = [t0, t1]? Same contract and same answer as
// segment_visibility (S and T of positive length, outside the objects, meeting no boundary; else
// std::invalid_argument), on the index of the scene's complex (complex_walk_index).
//
// Method: in the square of segments s(sigma) t(tau), the free set R is open and bounded by the curves
// "s, t and a vertex collinear". The leftmost point of the closure of a component of R is a square corner, a
// point where a curve meets tau = 0 or 1 (the line through t0 or t1 and a vertex), or where two curves cross
// on the closure of R: then the segment passes through two vertices that see each other along it, a strict
// pair or a ring edge of the visibility graph. So the sigmas where S meets those O(n + K) lines cut [0, 1]
// into gaps such that every component of R spans a whole gap. For the middle s* of each gap, the points of T
// that s* sees are those strictly inside the visibility polygon of s*, walked in the complex; T is cut at its
// crossings with the polygon and the middle of each piece is tested (exact point in polygon). The witness
// (s*, t) is re-checked exactly (open segment free) before it is returned. Cost: O(n + K) gaps (K = visible
// vertex pairs) x one walk each, stopping at the first witness; the O(n^4) segment_visibility is the
// reference.
SegmentVisibility2D segment_visibility_in_complex(const ComplexWalkIndex2D& index, const Point2& s0,
                                                  const Point2& s1, const Point2& t0, const Point2& t1,
                                                  ComplexSegmentStats2D* stats = nullptr);

}  // namespace exactvis
