#include "region/candidate_finder.hpp"

#include <algorithm>

namespace exactvis::region {

CandidateFinder brute_force_candidates(const Scene& scene) {
  return [&scene](const Box3& box) {
    std::vector<std::int64_t> out;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
      const auto& t = scene.triangles[i];
      bool overlap = true;
      for (int k = 0; k < 3 && overlap; ++k) {
        double lo = scene.corner(t, 0)[k], hi = lo;
        for (int c = 1; c < 3; ++c) {
          lo = std::min(lo, scene.corner(t, c)[k]);
          hi = std::max(hi, scene.corner(t, c)[k]);
        }
        overlap = hi >= box.lo[k] && lo <= box.hi[k];
      }
      if (overlap) out.push_back(static_cast<std::int64_t>(i));
    }
    return out;
  };
}

CandidateFinder index_candidates(const TriangleIndex& index) {
  return [index](const Box3& box) { return index.candidates_in_box(box); };
}

}  // namespace exactvis::region
