#pragma once
// Rounding an exact point to doubles, for witnesses that print as plain JSON numbers.
#include "kernel/predicates.hpp"

namespace exactvis {

// The point (or vector) with each coordinate replaced by a double less than one unit in the last place away
// from it (CGAL::to_double, which truncates toward zero); a coordinate beyond the range of doubles stays exact. The result is exact (rationals), so callers re-check it
// with the exact tests before using it in place of `p`. Cost: three conversions.
RationalPoint3 round_to_doubles(const RationalPoint3& p);

}  // namespace exactvis
