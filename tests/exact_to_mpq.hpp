#pragma once
// The bridge from the kernel's exact numbers to the oracles' GMP rationals (tests/oracles/rational_geometry):
// a value copy, so the oracles keep sharing no arithmetic with the code they check.
#include "kernel/number_types.hpp"
#include "kernel/vec3.hpp"
#include "oracles/rational_geometry.hpp"

#include <gmpxx.h>

namespace exactvis::exact_to_mpq {

// Input: an exact rational. Output: the same rational as a GMP mpq_class. Cost: one copy.
inline mpq_class q(const Exact& x) {
  mpq_class r;
  mpq_set(r.get_mpq_t(), x.mpq());
  return r;
}

// Input: an exact vector. Output: the same vector as the oracles' QVec.
inline oracle::QVec qv(const Vec3<Exact>& v) { return {q(v.x), q(v.y), q(v.z)}; }

}  // namespace exactvis::exact_to_mpq
