// EvPencilRange: it may only prove misses that are true. Oracle (mpq_class, no exactvis geometry): the lines
// L(t) = line(V, A + t (B - A)), t in [t0, t1], meet a closed triangle iff at t0, t1 or at a parameter in
// between where L(t) passes through a point of the triangle's section by the plane of V, A, B, the section's
// points are not strictly on one side of L(t) (the lines through V meeting a compact convex set form a closed
// set whose boundary parameters are such passing points). Small integer coordinates make coplanar, collinear
// and touching configurations frequent; the filter must also prove a good share of the true misses.
#include "events/ev_pencil_filter.hpp"

#include "kernel/filtered_predicate.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace exactvis {
namespace {

using Q = mpq_class;
using QV = std::array<Q, 3>;

QV sub(const QV& a, const QV& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
QV cross(const QV& a, const QV& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Q dot(const QV& a, const QV& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
int sgn(const Q& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

// Oracle: does some L(t), t in [t0, t1], meet the closed triangle c?
bool range_meets(const QV& v, const QV& a, const QV& b, const Q& t0, const Q& t1, const std::array<QV, 3>& c) {
  const QV av = sub(a, v), bv = sub(b, v), n = cross(av, bv);
  Q f[3];
  for (int k = 0; k < 3; ++k) f[k] = dot(sub(c[k], v), n);
  std::vector<QV> sec;  // the section's extreme points
  const bool coplanar = f[0] == 0 && f[1] == 0 && f[2] == 0;
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    if (coplanar || f[k] == 0) sec.push_back(c[k]);
    if (!coplanar && sgn(f[k]) * sgn(f[j]) < 0) {
      const Q den = f[k] - f[j];
      QV x;
      for (int i = 0; i < 3; ++i) x[i] = (f[k] * c[j][i] - f[j] * c[k][i]) / den;
      sec.push_back(x);
    }
  }
  if (sec.empty()) return false;
  // s_t(X) = det(d(t), X - V, n) = s0(X) + t s1(X), d(t) = av + t (bv - av).
  auto side = [&](const QV& x, const Q& t) {
    QV d;
    for (int i = 0; i < 3; ++i) d[i] = av[i] + t * (bv[i] - av[i]);
    return sgn(dot(cross(d, sub(x, v)), n));
  };
  auto meets_at = [&](const Q& t) {
    bool pos = false, neg = false;
    for (const QV& x : sec) {
      const int s = side(x, t);
      if (s == 0) return true;
      (s > 0 ? pos : neg) = true;
    }
    return pos && neg;
  };
  std::vector<Q> ts{t0, t1};
  for (const QV& x : sec) {
    const Q s0 = dot(cross(av, sub(x, v)), n), s1 = dot(cross(sub(bv, av), sub(x, v)), n);
    if (s1 != 0) {
      const Q r = -s0 / s1;
      if (r > t0 && r < t1) ts.push_back(r);
    }
  }
  for (const Q& t : ts)
    if (meets_at(t)) return true;
  return false;
}

struct Gen {
  std::mt19937_64 rng;
  explicit Gen(std::uint64_t seed) : rng(seed) {}
  Q coord(int range) { return Q(static_cast<long>(rng() % (2 * range + 1)) - range); }
  QV point(int range) { return {coord(range), coord(range), coord(range)}; }
  Q param() {  // a rational in [0, 1] with denominator 8
    return Q(static_cast<long>(rng() % 9), 8);
  }
};

Point3 dbl(const QV& p) { return {p[0].get_d(), p[1].get_d(), p[2].get_d()}; }

TEST(EvPencilFilter, ProvesOnlyTrueMissesOfTriangles) {
  Gen g(20261203);
  int misses = 0, proved = 0, cases = 0;
  for (int it = 0; it < 20000; ++it) {
    const QV v = g.point(4), a = g.point(4), b = g.point(4);
    if (cross(sub(a, v), sub(b, v)) == QV{0, 0, 0}) continue;  // no pencil
    Q t0 = g.param(), t1 = g.param();
    if (t1 < t0) std::swap(t0, t1);
    const std::array<QV, 3> c{g.point(4), g.point(4), g.point(4)};
    ++cases;
    const EvPencilRange range(dbl(v), dbl(a), dbl(b), t0.get_d(), t0.get_d(), t1.get_d(), t1.get_d());
    const bool proof = range.misses_triangle(dbl(c[0]), dbl(c[1]), dbl(c[2]));
    const bool meets = range_meets(v, a, b, t0, t1, c);
    ASSERT_FALSE(proof && meets) << "iteration " << it;
    misses += meets ? 0 : 1;
    proved += proof ? 1 : 0;
  }
  EXPECT_GT(cases, 15000);
  EXPECT_GT(misses, 2000);
  EXPECT_GT(proved, misses / 2) << "misses " << misses << ", proved " << proved;
}

TEST(EvPencilFilter, ProvesOnlyTrueMissesOfBoxes) {
  Gen g(77);
  int proved = 0;
  for (int it = 0; it < 4000; ++it) {
    const QV v = g.point(4), a = g.point(4), b = g.point(4);
    if (cross(sub(a, v), sub(b, v)) == QV{0, 0, 0}) continue;
    Q t0 = g.param(), t1 = g.param();
    if (t1 < t0) std::swap(t0, t1);
    QV lo = g.point(6), hi = lo;
    for (int k = 0; k < 3; ++k) hi[k] += Q(static_cast<long>(g.rng() % 4));
    const EvPencilRange range(dbl(v), dbl(a), dbl(b), t0.get_d(), t0.get_d(), t1.get_d(), t1.get_d());
    if (!range.misses_box({dbl(lo), dbl(hi)})) continue;
    ++proved;
    // Every triangle of three points of the box (its corners and random points inside) is missed.
    auto inside = [&] {
      QV p;
      for (int k = 0; k < 3; ++k) p[k] = lo[k] + (hi[k] - lo[k]) * Q(static_cast<long>(g.rng() % 5), 4);
      return p;
    };
    for (int r = 0; r < 6; ++r) ASSERT_FALSE(range_meets(v, a, b, t0, t1, {inside(), inside(), inside()})) << it;
    for (int m = 0; m < 8; ++m) {
      const QV c{(m & 1) ? hi[0] : lo[0], (m & 2) ? hi[1] : lo[1], (m & 4) ? hi[2] : lo[2]};
      ASSERT_FALSE(range_meets(v, a, b, t0, t1, {c, c, c})) << it;
    }
  }
  EXPECT_GT(proved, 500);
}

TEST(EvPencilFilter, OutwardEnclosuresAndTheSwitch) {
  // V at the origin, E from (1, 0, 0) to (0, 1, 0): L(t) has direction (1 - t, t, 0). The triangle around
  // (1, 1, 0) (t = 1/2) is met for ranges containing 1/2 and missed by [0, 1/4].
  const Point3 v{0, 0, 0}, a{1, 0, 0}, b{0, 1, 0};
  const Point3 p{0.9, 1.0, -1}, q{1.1, 1.0, -1}, r{1.0, 1.0, 1};
  EXPECT_FALSE(EvPencilRange(v, a, b, 0, 0, 1, 1).misses_triangle(p, q, r));
  EXPECT_TRUE(EvPencilRange(v, a, b, 0, 0, 0.25, 0.25).misses_triangle(p, q, r));
  // A wide enclosure of t1 reaching 1/2 keeps it.
  EXPECT_FALSE(EvPencilRange(v, a, b, 0, 0, 0.25, 0.5).misses_triangle(p, q, r));
  // Strictly above the plane: missed by every range; also its box.
  EXPECT_TRUE(EvPencilRange(v, a, b, 0, 0, 1, 1).misses_triangle({0, 0, 1}, {1, 0, 1}, {0, 1, 2}));
  EXPECT_TRUE(EvPencilRange(v, a, b, 0, 0, 1, 1).misses_box({{0, 0, 1}, {1, 1, 2}}));
  // A triangle through V is met by every line.
  EXPECT_FALSE(EvPencilRange(v, a, b, 0, 0, 0.25, 0.25).misses_triangle(v, {5, -1, 0}, {5, 1, 1}));
  set_filter_enabled(false);
  EXPECT_FALSE(EvPencilRange(v, a, b, 0, 0, 0.25, 0.25).misses_triangle(p, q, r));
  EXPECT_FALSE(EvPencilRange(v, a, b, 0, 0, 1, 1).misses_box({{0, 0, 1}, {1, 1, 2}}));
  set_filter_enabled(true);
}

}  // namespace
}  // namespace exactvis
