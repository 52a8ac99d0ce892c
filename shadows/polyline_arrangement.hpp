#pragma once
// The certified polyline arrangement of a receiver's curves (docs/theory.md section 11, "Certified polyline
// arrangement"): the fallback of receiver_arrangement where CGAL 5.5's conic traits fail. Every conic arc is
// a chain of pieces between exact rational points ON its conic; each piece has its lens (the triangle of its
// chord and the conic's tangents at its ends, which holds the piece) and is split at a rational point of the
// conic (a line through the arc's first point with a rational direction meets the conic again at a rational
// point) until exact tests certify that replacing every piece by its chord changes no crossing, no vertex
// order and no incidence (the conditions are listed in the .cpp and proved in the theory). The arrangement
// of the chords and the other segments is then an exact rational segment arrangement (CGAL
// Arr_segment_traits_2 over Gmpq: it cannot fail) with the same faces as the true arrangement of the arcs.
// Face samples are taken outside every piece's sliver (the region between the piece and its chord), so
// they lie in the true face; areas are doubles (each chord edge replaced by a 16-piece polyline of its arc),
// their error at most the slivers' areas along the face's boundary.
#include "shadows/conic_arrangement.hpp"

#include <array>
#include <vector>

namespace exactvis::shadows {

// Input: as receiver_arrangement (curves in the closed unit triangle, queries); `max_rounds` bounds the
// refinement rounds (each splits every piece that failed a test). Output: the faces (samples exact and
// certified, areas double), the face of each query, `polyline` set and `arc_pieces` the number of chords;
// `failed` (with `failure`) when some test still fails after `max_rounds` (e.g. a true tangency between an
// arc and another curve away from their ends, which no split removes). Exact. Cost per round: O(n^2) exact
// lens tests for n pieces and segments (double boxes filter), plus O(K^2) per lens for its K neighbours;
// then the segment sweep O((n + k) log n) and O(F E) for the samples.
ReceiverArrangement polyline_arrangement(const std::vector<ArrangementCurve>& curves,
                                         const std::vector<std::array<Exact, 2>>& queries = {}, int max_rounds = 12);

}  // namespace exactvis::shadows
