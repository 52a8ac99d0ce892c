#pragma once
// The lines meeting four given lines (transversals), exact over Q(sqrt(D)).
//
// A line x meets line l (or is parallel to it: they meet at infinity) iff side(x, l) = 0. The transversals
// are the real points of { x : side(x, l_i) = 0, i = 1..4 } on the Plücker quadric d.m = 0. See
// docs/theory.md, "Constructions" for the method and every degenerate case.
#include "kernel/plucker_line.hpp"
#include "kernel/root_number.hpp"

#include <array>
#include <vector>

namespace exactvis {

enum class TransversalKind { Finite, Infinite };

struct LinesThroughFourLines {
  TransversalKind kind = TransversalKind::Finite;
  // kind Finite: the 0, 1 or 2 distinct real transversals (d != 0, d.m = 0 exactly). Each is a line meeting
  // every input line at a finite point or being parallel to it (meeting it at infinity). Orientation is
  // arbitrary (deterministic). All coordinates of one result share one root D (lines[k][i].root()).
  // kind Infinite: empty.
  std::vector<PluckerLine<RootNumber>> lines;
  // kind Finite: projective solutions with d = 0 ("lines at infinity": all input lines are parallel to a
  // common plane, whose line at infinity then meets all four). Not lines of R^3, hence not in `lines`.
  int at_infinity = 0;
  // kind Infinite: a basis of the linear space L (dimension 2..5) such that the transversals are exactly the
  // real lines in L (vectors of L with d.m = 0 and d != 0). The basis vectors need not be real lines.
  std::vector<PluckerLine<Exact>> family_basis;
};

// Input: four real lines (d != 0 and d.m = 0 exactly; throws std::invalid_argument otherwise).
// Output: see LinesThroughFourLines.
LinesThroughFourLines lines_through_four_lines(const std::array<PluckerLine<Exact>, 4>& lines);

// Floating-point approximation (d0,d1,d2,m0,m1,m2) of a line, for output only.
std::array<double, 6> to_double(const PluckerLine<RootNumber>& line);

}  // namespace exactvis
