#pragma once
// A rational number strictly between two distinct numbers of Q(sqrt D) (RootNumber): the exact sample points
// of "breakpoints + decide at a rational sample" sweeps (docs/theory.md section 6, EEE critical line sets).
#include "kernel/number_types.hpp"
#include "kernel/root_number.hpp"

namespace exactvis {

// Input: a < b (exactly; throws std::invalid_argument otherwise). Output: a rational q with a < q < b,
// exactly. The midpoint when both are rational; else a dyadic found by bisection of an enclosing interval
// with exact comparisons (a few dozen steps for gaps down to about 2^-50 of the enclosure width).
Exact rational_strictly_between(const RootNumber& a, const RootNumber& b);

// True iff x is rational (no square-root part); then *q receives its value.
bool root_number_rational(const RootNumber& x, Exact* q);

}  // namespace exactvis
