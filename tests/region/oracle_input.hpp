#pragma once
// Scenes and view cells handed to the independent visibility oracle (tests/oracles/visibility_oracle.hpp) as
// its own GMP rationals: the region suites' only link between exactvis types and the oracle's.
#include "kernel/predicates.hpp"
#include "kernel/scene.hpp"
#include "oracles/visibility_oracle.hpp"

#include <vector>

namespace exactvis::region_test {

inline oracle::QVec qv(const Point3& p) { return oracle::qvec(p.x, p.y, p.z); }
inline oracle::QVec qv(const RationalPoint3& p) {
  return {mpq_class(p.x.mpq()), mpq_class(p.y.mpq()), mpq_class(p.z.mpq())};
}

// The scene's triangles, in index order.
inline std::vector<oracle::Triangle> oracle_scene(const Scene& scene) {
  std::vector<oracle::Triangle> os;
  for (const auto& t : scene.triangles) os.push_back({qv(scene.corner(t, 0)), qv(scene.corner(t, 1)), qv(scene.corner(t, 2))});
  return os;
}

// The closed box [lo, hi] as an oracle source.
template <class P>
oracle::Source oracle_box(const P& lo, const P& hi) {
  oracle::Source src;
  src.is_box = true;
  src.lo = qv(lo);
  src.hi = qv(hi);
  return src;
}

}  // namespace exactvis::region_test
