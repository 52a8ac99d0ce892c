#pragma once
// Witnesses of exterior visibility (docs/theory.md §5.6): a ray (q, d) from a point q of the relative
// interior of a triangle T in direction d that escapes to infinity, checked exactly in a form that proves
// by itself that the escaping rays of T have positive measure (Lemma 5.6.2):
//   1. q lies in relint T;
//   2. d is not parallel to plane(T) (d . n_T != 0);
//   3. q lies on no closed scene triangle other than T, except triangles coplanar with T (those never meet
//      a ray leaving plane(T));
//   4. the open ray {q + s d : s > 0} meets no closed scene triangle other than T.
// Conditions 1, 2, 4 are the definition's escaping ray; 3 makes the closed ray keep a positive distance from
// every triangle that could block a nearby ray, so an open neighbourhood of (q, d) escapes too.
#include "kernel/round_to_doubles.hpp"
#include "util/mix_seed.hpp"
#include "kernel/predicates.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"

#include <cstdint>
#include <optional>

namespace exactvis::region {

struct ExteriorWitness {
  RationalPoint3 q;  // in the relative interior of the triangle
  Vec3<Exact> d;     // direction of the escaping ray (any positive multiple is the same ray)
};

// Which condition a candidate witness fails (Valid: none).
enum class ExteriorWitnessCheck { Valid, NotInRelativeInterior, ParallelToTriangle, OnOtherTriangle, Blocked };

// Input: scene, its index, bounding_box(scene), the triangle (index into Scene::triangles), a candidate.
// Output: the first condition above that fails, or Valid. Exact. Cost: one open_ray_blocker query
// (kernel/ray_blocker.hpp) plus the candidates at q. Thread-safe.
ExteriorWitnessCheck check_exterior_witness(const Scene& scene, const TriangleIndex& index, const Box3& scene_box,
                                            std::int64_t triangle_index, const ExteriorWitness& w);

// The witness with q and d rounded to the nearest doubles where that still passes check_exterior_witness
// (first d alone, then q and d), else the witness as given. Makes JSON output plain numbers when possible.
ExteriorWitness round_exterior_witness(const Scene& scene, const TriangleIndex& index, const Box3& scene_box,
                                       std::int64_t triangle_index, const ExteriorWitness& w);

// True iff every corner of scene triangle `other` lies in the plane of scene triangle `t` (exact orient3d).
bool coplanar_triangles(const Scene& scene, std::int64_t t, std::int64_t other);

// The escaping ray of a from-region witness segment (p on a face of a box strictly enclosing the scene, q in
// relint T, open segment (q, p) free): d = p - q. (Beyond p the ray is outside the box, where nothing is.)
ExteriorWitness witness_from_segment(const RationalPoint3& p_on_box, const RationalPoint3& q);

}  // namespace exactvis::region
