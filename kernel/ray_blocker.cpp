#include "kernel/ray_blocker.hpp"

#include "kernel/segment_triangle_intersection.hpp"

#include <cmath>
#include <stdexcept>
#include <unordered_set>

namespace exactvis {
namespace {

Interval interval_of(const Exact& x) { return Interval(enclosing_interval(x)); }
Vec3<Interval> interval_of(const RationalPoint3& p) { return {interval_of(p.x), interval_of(p.y), interval_of(p.z)}; }
Vec3<Interval> interval_of(const Point3& p) { return {Interval(p.x), Interval(p.y), Interval(p.z)}; }

Interval orient3d_interval(const Vec3<Interval>& a, const Vec3<Interval>& b, const Vec3<Interval>& c,
                           const Vec3<Interval>& d) {
  return dot(cross(b - a, c - a), d - a);
}

bool certainly_positive(const Interval& x) { return x.inf() > 0; }
bool certainly_negative(const Interval& x) { return x.sup() < 0; }

// True when interval arithmetic proves that the open segment (a, b) misses the closed triangle t (the
// exact test's own case analysis, kernel/segment_triangle_intersection.cpp, with only the conclusions an
// interval can certify: both ends strictly on one side of the plane, or a crossing line that passes two
// edges on opposite sides).
bool certainly_misses(const Vec3<Interval>& a, const Vec3<Interval>& b, const std::array<Vec3<Interval>, 3>& t) {
  const Interval oa = orient3d_interval(t[0], t[1], t[2], a);
  const Interval ob = orient3d_interval(t[0], t[1], t[2], b);
  if ((certainly_positive(oa) && certainly_positive(ob)) || (certainly_negative(oa) && certainly_negative(ob)))
    return true;
  const bool crossing =
      (certainly_positive(oa) && certainly_negative(ob)) || (certainly_negative(oa) && certainly_positive(ob));
  if (!crossing) return false;
  bool pos = false, neg = false;
  for (int k = 0; k < 3; ++k) {
    const Interval s = orient3d_interval(a, b, t[k], t[(k + 1) % 3]);
    pos |= certainly_positive(s);
    neg |= certainly_negative(s);
  }
  return pos && neg;
}

// Level at which the segment is first cut (2^level pieces): pieces of about four triangles' size on a
// surface-like scene of n triangles (sqrt(n) triangles across it).
int start_level(std::int64_t n) {
  const double across = std::sqrt(static_cast<double>(std::max<std::int64_t>(n, 1))) / 4.0;
  int level = 0;
  while (level < 10 && static_cast<double>(std::int64_t{1} << (level + 1)) <= across) ++level;
  return level;
}

}  // namespace

RaySpan ray_span(const Box3& box, const RationalPoint3& origin, const Vec3<Exact>& dir) {
  if (CGAL::sign(dir.x) == 0 && CGAL::sign(dir.y) == 0 && CGAL::sign(dir.z) == 0)
    throw std::invalid_argument("ray_span: zero direction");
  RaySpan span;
  span.origin = origin;
  span.dir = dir;
  if (box.empty()) return span;
  // Parameters of the closed slab [lo_k, hi_k] along each axis, intersected (exact rationals).
  Exact s_in(0);
  bool has_out = false;
  Exact s_out(0);
  for (int k = 0; k < 3; ++k) {
    const Exact lo(box.lo[k]), hi(box.hi[k]);
    const int sd = CGAL::sign(dir[k]);
    if (sd == 0) {
      if (origin[k] < lo || origin[k] > hi) return span;  // parallel to the slab and outside it
      continue;
    }
    Exact a = (lo - origin[k]) / dir[k], b = (hi - origin[k]) / dir[k];
    if (sd < 0) std::swap(a, b);
    if (a > s_in) s_in = a;
    if (!has_out || b < s_out) s_out = b;
    has_out = true;
  }
  if (s_out < s_in) return span;  // also covers s_out < 0: the box lies behind the origin
  span.empty = false;
  // Every point beyond s_out is strictly outside the closed box (the axis realising s_out has left its slab);
  // far is a little beyond it, so that the pieces of visit_ray_candidates are spent inside the box.
  const Exact s_near = CGAL::sign(s_in) > 0 ? s_in : Exact(0);
  const Exact s_far = s_out > s_near ? s_out + (s_out - s_near) / Exact(16) : s_out + Exact(1);
  span.near = origin + s_near * dir;
  span.far = origin + s_far * dir;
  return span;
}

void visit_ray_candidates(const TriangleIndex& index, const RaySpan& span,
                          const std::function<bool(std::int64_t)>& visit) {
  if (span.empty) return;
  Vec3<Interval> o, f;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    o = interval_of(span.near);
    f = interval_of(span.far);
  }
  const int level0 = start_level(index.size());
  const int max_level = level0 + 12;
  std::unordered_set<std::int64_t> seen;
  // Depth-first over pieces [i / 2^level, (i + 1) / 2^level] of the segment, nearest piece first.
  struct Piece {
    int level;
    std::int64_t i;
  };
  std::vector<Piece> stack;
  for (std::int64_t i = (std::int64_t{1} << level0) - 1; i >= 0; --i) stack.push_back({level0, i});
  while (!stack.empty()) {
    const Piece piece = stack.back();
    stack.pop_back();
    const double scale = std::ldexp(1.0, -piece.level);  // exact power of two
    Box3 box;
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const Interval t(static_cast<double>(piece.i) * scale, static_cast<double>(piece.i + 1) * scale);
      // Points o + t (f - o), t in the piece: each coordinate is affine in t, so this interval encloses them.
      for (int k = 0; k < 3; ++k) {
        const Interval c = o[k] + t * (f[k] - o[k]);
        box.lo[k] = c.inf();
        box.hi[k] = c.sup();
      }
    }
    const std::vector<std::int64_t> cands = index.candidates_in_box(box);
    if (cands.size() > 16 && piece.level < max_level) {
      stack.push_back({piece.level + 1, 2 * piece.i + 1});
      stack.push_back({piece.level + 1, 2 * piece.i});
      continue;
    }
    for (const std::int64_t c : cands)
      if (seen.insert(c).second && !visit(c)) return;
  }
}

std::int64_t open_ray_blocker(const Scene& scene, const TriangleIndex& index, const Box3& scene_box,
                              const RationalPoint3& origin, const Vec3<Exact>& dir, std::int64_t skip) {
  const RaySpan span = ray_span(scene_box, origin, dir);
  if (span.empty) return -1;
  Vec3<Interval> a, b;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    a = interval_of(span.origin);
    b = interval_of(span.far);
  }
  std::int64_t blocker = -1;
  visit_ray_candidates(index, span, [&](std::int64_t c) {
    if (c == skip) return true;
    const SceneTriangle& t = scene.triangles[static_cast<std::size_t>(c)];
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const std::array<Vec3<Interval>, 3> ti{interval_of(scene.corner(t, 0)), interval_of(scene.corner(t, 1)),
                                             interval_of(scene.corner(t, 2))};
      if (certainly_misses(a, b, ti)) return true;
    }
    if (open_segment_meets_closed_triangle(span.origin, span.far, to_rational(scene.corner(t, 0)),
                                           to_rational(scene.corner(t, 1)), to_rational(scene.corner(t, 2)))) {
      blocker = c;
      return false;
    }
    return true;
  });
  return blocker;
}

}  // namespace exactvis
