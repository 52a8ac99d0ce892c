#pragma once
// The exact arrangement of a receiver's discontinuity curves, segments and conic arcs (docs/theory.md
// section 11, "The arrangement"): CGAL's Arrangement_2 with Arr_conic_traits_2 over CORE's algebraic numbers,
// in the receiver's (u, v) frame, with the triangle's three sides. Its bounded faces are the faces of the
// discontinuity mesh: `shadows` reports them (the constrained triangulation of receiver_faces is for
// display).
//
// A curve is a sequence of exact (u, v) points. Without a conic it is the polyline through them (EV and D0
// segments). With a conic (the exact rational conic of an EEE surface, every point exactly on it) it is the
// arc of that conic from the first point to the last through the others: the arc's orientation is the turn
// of (first, a middle point, last), which is the traversal direction of any arc of a conic branch (a branch is
// convex), and every given point is checked to lie on the constructed arc (exact). When the conic is
// degenerate (a line pair: zero determinant) or the check fails, the curve enters as the polyline through its
// points and is counted in `chord_curves` (these faces are then chord polygons).
//
// Faces get an exact rational sample strictly inside: on a boundary edge, a rational x strictly inside its
// x-range avoiding every vertex's x, then a rational y strictly between that edge's y and the nearest other
// edge's y on the face's side (all exact comparisons of algebraic numbers). The area is a double: the
// boundary integral of (x dy - y dx) / 2 over 64-piece polylines of each arc (abscissae cosine-graded, so
// vertical tangents at the arcs' ends do not spoil the convergence), Richardson-extrapolated with 32 pieces
// (segments exact in double). Where no curve is a conic arc, faces are polygons with rational vertices and
// callers can take their exact area from the constrained triangulation (receiver_faces) instead.
#include "kernel/number_types.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace exactvis::shadows {

struct ArrangementCurve {
  std::vector<std::array<Exact, 2>> points;  // exact (u, v) points in order, at least 2
  // The conic through the points (coefficients of u^2, uv, v^2, u, v, 1), or none for a polyline.
  std::optional<std::array<Exact, 6>> conic;
};

struct ReceiverArrangement {
  struct Face {
    double area_uv = 0;             // (u, v) area, double
    std::array<Exact, 2> sample;    // exact, strictly inside the face
    bool conic_bounded = false;     // some boundary edge lies on a conic arc
  };
  std::vector<Face> faces;          // the bounded faces inside the unit triangle (an arc that leaves the
                                    // triangle between its points may bound faces outside: left out)
  std::vector<int> query_faces;     // the face of each query point (on an edge or vertex: a face next to
                                    // it; -1 outside the triangle)
  std::size_t vertices = 0, edges = 0;
  std::size_t conic_arcs = 0;       // curves inserted as conic arcs
  std::size_t chord_curves = 0;     // curves with a conic inserted as polylines (degenerate or check failed)
  // CGAL 5.5's Arr_conic_traits_2 violates its own preconditions on some valid inputs (an inconsistent sweep
  // order: Multiset.h "comp_f(object, nodeP->object) != LARGER"), seen where an arc and a segment, or two
  // arcs, touch tangentially (an EEE arc starting where an EV segment ends). Then the curves are inserted one
  // by one (zone walks) instead of by one sweep; failing that, the certified polyline arrangement is built
  // (`polyline`, exact faces); failing that, the arrangement is rebuilt (sweep, then one by
  // one) with each arc's first and last pieces (between its first two and last two points) as chords
  // (`trimmed_arcs`); a face sample is then taken outside every such chord's lens triangle (the triangle of
  // the chord and the conic's tangents at its ends, which holds the arc piece: exact), so it is on the
  // same side of every true arc as of its chord; `uncertified_samples` counts faces where no edge gave such
  // a sample, `uncertified_lenses` chords whose lens could not be certified. If that fails too, nothing
  // else is filled, `failed` is set and `failure` holds CGAL's message (callers fall back, see shadow_mesh).
  std::size_t trimmed_arcs = 0, uncertified_samples = 0, uncertified_lenses = 0;
  // Built by the certified polyline fallback (shadows/polyline_arrangement.hpp) after CGAL's conic traits
  // failed on the arcs as given: the faces are the exact arrangement's (combinatorially, with certified
  // samples), each arc a chain of `arc_pieces` chords in total, areas doubles with a bound.
  bool polyline = false;
  std::size_t arc_pieces = 0;
  bool failed = false;
  std::string failure;
};

// Input: curves inside the closed unit triangle u, v >= 0, u + v <= 1 (its sides are added), query points
// (e.g. the triangulation's face samples) inside it. Output: the bounded faces with samples and areas, the
// face of each query. Exact (areas double). Cost: the sweep, O((n + k) log n) for n curves and k crossings
// (CORE arithmetic), plus O(F * E) for the samples (each face's vertical probe tests every edge) and one
// batched point-location sweep for all queries, O((E + Q) log E) (where CGAL's sweep throws, the naive
// location, O(E) per query; never the walk along a line, which can fail to end with these traits).
ReceiverArrangement receiver_arrangement(const std::vector<ArrangementCurve>& curves,
                                         const std::vector<std::array<Exact, 2>>& queries = {});

// Debugging aid: with EXACTVIS_DUMP_ARRANGEMENTS=DIR set, writes the curves to DIR/arrangement_<n>.txt (n a
// process-wide counter): a first line "# why", then per curve a line "curve <points> <0|1>", the conic's six
// coefficients when 1, then one "u v" line per point (exact rationals; tests/shadows/test_polyline_arrangement
// reads them back). Without the variable it does nothing. receiver_arrangement calls it for every receiver
// where CGAL's conic traits failed, compute_shadows for every receiver whose arrangement failed.
void dump_arrangement_curves(const std::vector<ArrangementCurve>& curves, const std::string& why);

}  // namespace exactvis::shadows
