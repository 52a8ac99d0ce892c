#pragma once
// Independent oracle for from-region visibility answers (no exactvis headers; GMP rationals only).
//
// - witness_is_valid: a reported witness (p, q) must have p in the source (closed polygon or closed box),
//   q in the relative interior of the target, and an open segment meeting no other triangle.
// - find_robust_free_segment: random sampling that tries to refute a "hidden" answer. A sample counts only
//   when p is in relint(source) (or in the open box), q in relint(target), the open segment is free AND
//   neither endpoint lies on an occluder: then the closed segment is at positive distance from every
//   occluder, so a whole neighbourhood of segments is free and the target is visible (positive measure).
#include "oracles/rational_geometry.hpp"

#include <optional>
#include <string>
#include <vector>

namespace oracle {

using Triangle = std::array<QVec, 3>;

struct Source {
  bool is_box = false;
  std::vector<QVec> polygon;  // convex, planar (when !is_box)
  QVec lo, hi;                // when is_box
};

bool witness_is_valid(const std::vector<Triangle>& scene, std::size_t target, const Source& source, const QVec& p,
                      const QVec& q, std::string* why);

std::optional<std::pair<QVec, QVec>> find_robust_free_segment(const std::vector<Triangle>& scene, std::size_t target,
                                                              const Source& source, int samples,
                                                              unsigned long seed);

}  // namespace oracle
