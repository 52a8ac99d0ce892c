#pragma once
// Independent oracle for exterior visibility answers (no exactvis headers; GMP rationals only), for the
// definition of docs/theory.md §5.6: T is exterior visible iff the rays from points of relint T that meet no
// other closed triangle (at parameters s > 0) have positive measure.
//
// - exterior_witness_is_valid: a reported witness (q, d) must have q in relint T, d != 0 and an open ray
//   {q + s d : s > 0} that meets no closed triangle other than T. The ray is cut where one coordinate has
//   passed every vertex of the scene (beyond that point no triangle can be), and the open segment up to
//   there is tested triangle by triangle.
// - find_robust_escaping_ray: random sampling that tries to refute a "hidden" answer. A sample counts only
//   when q is in relint T, d is not parallel to plane(T), the open ray is free AND q lies on no other closed
//   triangle except ones coplanar with T: then the closed ray keeps a positive distance from every triangle
//   that can block a ray leaving plane(T), so a whole neighbourhood of rays escapes (positive measure).
#include "oracles/visibility_oracle.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace oracle {

bool exterior_witness_is_valid(const std::vector<Triangle>& scene, std::size_t target, const QVec& q, const QVec& d,
                               std::string* why);

// Open ray {q + s d : s > 0} against every closed triangle except `skip`: true iff it meets none.
bool open_ray_escapes(const std::vector<Triangle>& scene, std::size_t skip, const QVec& q, const QVec& d);

// `samples` random rays (q from random positive barycentric weights, d from random integer vectors, every
// eighth one along a random edge-to-edge direction through the scene's vertices); the first robust escaping
// ray found, or std::nullopt.
std::optional<std::pair<QVec, QVec>> find_robust_escaping_ray(const std::vector<Triangle>& scene, std::size_t target,
                                                              int samples, unsigned long seed);

}  // namespace oracle
