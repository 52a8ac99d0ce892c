#pragma once
// The first scene triangle met by an open ray along a line with exact coordinates in Q or Q(sqrt D) (the
// lines of the 3D visibility skeleton's nodes; docs/theory.md section 9, "Maximal free segments").
#include "kernel/number_types.hpp"
#include "kernel/ray_first_hit.hpp"
#include "kernel/root_number.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"
#include "kernel/vec3.hpp"

#include <array>

namespace exactvis {

// Input: the scene, its spatial index and bounding box (bounding_box(scene)), a point `origin` on or inside
// that box and a direction `dir` != 0 (coordinates rational or in one common Q(sqrt D)).
// Output: the stable id of the closed scene triangle met first by the open ray {origin + s dir : s > 0}
// (a triangle coplanar with the ray counts from its first point; ties go to the lowest triangle index), or
// -1 when the ray leaves the scene. Exact. Rational rays go through kernel/ray_first_hit (spatial index);
// rays in Q(sqrt D) (EEEE node lines with an irrational root) take the candidates of the same interval cover
// (ray_cover_candidates; all triangles only when no direction enclosure excludes 0), reject most by an
// interval filter and decide the rest exactly in Q(sqrt D). Cost: O(32 log n + k) plus the exact tests.
// `origin_on`: the edge line the origin is known to lie on, if any (passed to ray_first_hit for rational
// rays, which then need no exact arithmetic for the structural zeros of that edge's planes; the result is
// the same with or without it, wrong knowledge gives wrong answers).
std::int64_t line_first_hit(const Scene& scene, const TriangleIndex& index, const Box3& box,
                            const Vec3<RootNumber>& origin, const Vec3<RootNumber>& dir,
                            const RayOriginOnEdgeLine& origin_on = {});

// One open segment (from, to) (from != to; coordinates rational or in one Q(sqrt D)) tested against many
// closed triangles: its interval enclosures and, when rational, its rational endpoints are computed once.
// meets(a, b, c) is true iff the open segment meets the closed triangle (a, b, c), exactly: an interval
// filter (docs/theory.md section 9) rejects the triangles the segment certainly misses, the rest go to the
// exact test (the kernel's filtered rational test, or Q(sqrt D) arithmetic). Cost per triangle: about 40
// interval operations when rejected. Keeps references to `from` and `to` (which must outlive it). Not
// thread-safe (RootNumber caches): one object per thread.
class OpenSegmentTest {
 public:
  OpenSegmentTest(const Vec3<RootNumber>& from, const Vec3<RootNumber>& to);
  bool meets(const Point3& a, const Point3& b, const Point3& c) const;

 private:
  const Vec3<RootNumber>& from_;
  const Vec3<RootNumber>& to_;
  bool rational_ = false;
  Vec3<Exact> from_q_, to_q_;  // set when rational_
  std::array<std::array<double, 2>, 3> lo_hi_from_, lo_hi_to_;  // enclosures [lo, hi] per axis
};

// True iff the open segment (from, to) (from != to) meets the closed triangle (a, b, c), exactly
// (OpenSegmentTest for one triangle).
bool open_segment_meets_triangle(const Vec3<RootNumber>& from, const Vec3<RootNumber>& to, const Point3& a,
                                 const Point3& b, const Point3& c);

// True iff every coordinate is rational; then *out receives the rational vector.
bool rational_vector(const Vec3<RootNumber>& v, Vec3<Exact>* out);

}  // namespace exactvis
