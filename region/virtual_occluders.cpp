#include "region/virtual_occluders.hpp"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <optional>
#include <utility>

namespace exactvis::region {

namespace {

// Sign of x: -1, 0, 1, or 2 when an interval cannot tell.
int sign3(const Interval& x) {
  if (x.inf() > 0) return 1;
  if (x.sup() < 0) return -1;
  if (x.inf() == 0 && x.sup() == 0) return 0;
  return 2;
}
int sign3(const Exact& x) { return CGAL::sign(x); }
int sign3(double x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

// Does the closed segment a + t (b - a), t in [0, 1], meet the closed box [lo, hi]? Every slab gives a lower
// and an upper bound on t as a fraction num / den with den > 0 (the bounds 0 and 1 have den = 1); the
// segment meets the box iff no slab is missed by a segment parallel to it and every lower bound <= every
// upper bound: l.num * u.den <= u.num * l.den (cross-multiplied, positive denominators). nullopt: the number
// type could not decide (intervals). A definite miss is definite even if other comparisons are undecided.
template <class NT>
std::optional<bool> clip(const std::array<NT, 3>& a, const std::array<NT, 3>& b, const std::array<NT, 3>& lo,
                         const std::array<NT, 3>& hi) {
  std::array<NT, 4> lnum, lden, unum, uden;
  int nl = 1, nu = 1;
  lnum[0] = NT(0), lden[0] = NT(1), unum[0] = NT(1), uden[0] = NT(1);
  bool undecided = false;
  for (int k = 0; k < 3; ++k) {
    const NT d = b[k] - a[k];
    const int s = sign3(d);
    if (s == 2) return std::nullopt;
    if (s == 0) {  // parallel to the slab: inside it or missing the box
      const int sl = sign3(a[k] - lo[k]), sh = sign3(hi[k] - a[k]);
      if (sl == -1 || sh == -1) return false;
      if (sl == 2 || sh == 2) undecided = true;
      continue;
    }
    if (s > 0) {
      lnum[nl] = lo[k] - a[k], lden[nl++] = d;
      unum[nu] = hi[k] - a[k], uden[nu++] = d;
    } else {
      lnum[nl] = a[k] - hi[k], lden[nl++] = -d;
      unum[nu] = a[k] - lo[k], uden[nu++] = -d;
    }
  }
  for (int i = 0; i < nl; ++i)
    for (int j = 0; j < nu; ++j) {
      const int s = sign3(unum[j] * lden[i] - lnum[i] * uden[j]);
      if (s == -1) return false;
      if (s == 2) undecided = true;
    }
  if (undecided) return std::nullopt;
  return true;
}

std::array<double, 3> arr(const Point3& p) { return {p.x, p.y, p.z}; }

bool double_meets(const Point3& a, const Point3& b, const Box3& v) {
  // Floats only reject (a false "miss" only costs a proof not made).
  return clip(arr(a), arr(b), arr(v.lo), arr(v.hi)).value_or(false);
}

double squared_gap(const Box3& x, const Point3& c) {
  double s = 0;
  for (int k = 0; k < 3; ++k) {
    const double g = std::max({x.lo[k] - c[k], c[k] - x.hi[k], 0.0});
    s += g * g;
  }
  return s;
}

}  // namespace

bool segment_meets_box(const RationalPoint3& a, const Point3& b, const Box3& v) {
  {
    // Enclosures of the exact coordinates first (mpq_get_d), then the filter under upward rounding.
    const std::array<std::pair<double, double>, 3> ea{enclosing_interval(a.x), enclosing_interval(a.y),
                                                      enclosing_interval(a.z)};
    CGAL::Protect_FPU_rounding<true> guard;
    const std::optional<bool> r =
        clip<Interval>({Interval(ea[0]), Interval(ea[1]), Interval(ea[2])},
                       {Interval(b.x), Interval(b.y), Interval(b.z)},
                       {Interval(v.lo.x), Interval(v.lo.y), Interval(v.lo.z)},
                       {Interval(v.hi.x), Interval(v.hi.y), Interval(v.hi.z)});
    if (r) return *r;
  }
  return *clip<Exact>({a.x, a.y, a.z}, {Exact(b.x), Exact(b.y), Exact(b.z)},
                      {Exact(v.lo.x), Exact(v.lo.y), Exact(v.lo.z)}, {Exact(v.hi.x), Exact(v.hi.y), Exact(v.hi.z)});
}

std::array<Point3, 8> corners_of(const Box3& b) {
  std::array<Point3, 8> c;
  for (int k = 0; k < 8; ++k)
    c[k] = {(k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z};
  return c;
}

bool box_blocks(const Box3& v, const RationalBox3& cell, std::span<const Point3> target_corners) {
  // Convexity of shadows (§5.9 lemma, any closed convex V): all corner segments meet V => all segments do.
  const std::array<Point3, 8> approx = corners_of(approximate_box(cell));
  for (const Point3& a : approx)
    for (const Point3& b : target_corners)
      if (!double_meets(a, b, v)) return false;
  for (int i = 0; i < 8; ++i) {
    const RationalPoint3 a{(i & 1) ? cell.hi.x : cell.lo.x, (i & 2) ? cell.hi.y : cell.lo.y,
                           (i & 4) ? cell.hi.z : cell.lo.z};
    for (const Point3& b : target_corners)
      if (!segment_meets_box(a, b, v)) return false;
  }
  return true;
}

VirtualOccluders::VirtualOccluders(const RationalBox3& cell, int cap)
    : cell_(cell), approx_(approximate_box(cell)), cap_(std::max(0, cap)) {
  for (int k = 0; k < 3; ++k) centre_[k] = approx_.lo[k] / 2 + approx_.hi[k] / 2;
}

void VirtualOccluders::add(const Box3& dark) {
  if (cap_ == 0) return;
  ++added_;
  double diag2 = 0;
  for (int k = 0; k < 3; ++k) diag2 += (dark.hi[k] - dark.lo[k]) * (dark.hi[k] - dark.lo[k]);
  // Larger and nearer first: a proxy of the solid angle the box covers from the cell.
  const double priority = diag2 / std::max(squared_gap(dark, centre_), 1e-300);
  const Entry e{dark, priority};
  const auto at = std::upper_bound(boxes_.begin(), boxes_.end(), e,
                                   [](const Entry& x, const Entry& y) { return x.priority > y.priority; });
  boxes_.insert(at, e);
  if (boxes_.size() > static_cast<std::size_t>(cap_)) boxes_.pop_back();
  last_ = 0;
}

bool VirtualOccluders::blocks(std::span<const Point3> target_corners) {
  if (boxes_.empty() || target_corners.empty()) return false;
  Point3 tc{0, 0, 0};
  for (const Point3& p : target_corners)
    for (int k = 0; k < 3; ++k) tc[k] += p[k] / static_cast<double>(target_corners.size());
  const std::size_t n = boxes_.size(), first = std::min(last_, n - 1);
  // Order: the box that blocked last, then the others best first.
  for (std::size_t r = 0; r < n; ++r) {
    const std::size_t i = r == 0 ? first : (r - 1 < first ? r - 1 : r);
    const Box3& v = boxes_[i].box;
    // The segment between centres is one of the segments that must meet V: a cheap first rejection.
    if (!double_meets(centre_, tc, v)) continue;
    ++exact_tests_;
    if (box_blocks(v, cell_, target_corners)) {
      last_ = i;
      return true;
    }
  }
  return false;
}

}  // namespace exactvis::region
