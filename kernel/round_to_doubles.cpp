#include "kernel/round_to_doubles.hpp"

#include <cmath>

namespace exactvis {

RationalPoint3 round_to_doubles(const RationalPoint3& p) {
  RationalPoint3 out = p;
  for (int k = 0; k < 3; ++k) {
    const double x = CGAL::to_double(p[k]);
    if (std::isfinite(x)) out[k] = Exact(x);  // else keep the exact value (no infinity enters a witness)
  }
  return out;
}

}  // namespace exactvis
