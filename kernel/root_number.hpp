#pragma once
// Numbers a0 + a1 * sqrt(root) with exact rational a0, a1, root: the field Q(sqrt(D)) in which the lines
// through four lines live. Kept out of widely included headers (CGAL/Sqrt_extension.h is heavy).
// Values from one construction share one root D; CGAL decides signs and comparisons exactly (also across
// different roots, ACDE_TAG = Tag_true), with an interval filter first (FP_TAG = Tag_true).
// Thread safety: with FP_TAG = Tag_true a value caches its interval in a mutable member, so one RootNumber
// object must not be read by two threads at once; give each thread its own copy (each copy has its own cache).
#include "kernel/number_types.hpp"

#include <CGAL/Sqrt_extension.h>

namespace exactvis {

using RootNumber = CGAL::Sqrt_extension<Exact, Exact, CGAL::Tag_true, CGAL::Tag_true>;

}  // namespace exactvis
