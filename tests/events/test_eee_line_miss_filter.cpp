// EeeLineMissFilter: it may only prove misses that are true. The lines are L(t) = line through P(t) = A + t U
// and Q(t) = B + t W (A, B, U, W rational; Plücker d = Q - P, m = P x Q, computed here on mpq_class with no
// exactvis geometry). Oracle: configurations built to meet (a triangle constructed around a point X of L(t*)
// for a rational t* in the range: X inside it, on an edge, at a corner, in its plane, zero-area triangles)
// must never be proved missed; triangles far from every line of the range (placed where no line of the
// family passes, by construction) must be, so the filter is not vacuous.
#include "events/eee_line_miss_filter.hpp"

#include "kernel/filtered_predicate.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>

namespace exactvis {
namespace {

using Q = mpq_class;
using QV = std::array<Q, 3>;

QV sub(const QV& a, const QV& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
QV add(const QV& a, const QV& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
QV scale(const Q& s, const QV& a) { return {s * a[0], s * a[1], s * a[2]}; }

// A family P(t) = A + t U, Q(t) = B + t W with its exact Plücker coefficients [axis][degree].
struct Family {
  QV A, U, B, W;
  std::array<std::array<Exact, 3>, 3> d, m;
  QV P(const Q& t) const { return add(A, scale(t, U)); }
  QV Qp(const Q& t) const { return add(B, scale(t, W)); }
  void coefficients() {
    auto ex = [](const Q& x) { return Exact(x.get_mpq_t()); };
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      d[k] = {ex(B[k] - A[k]), ex(W[k] - U[k]), Exact(0)};
      // (P x Q)_k = P_i Q_j - P_j Q_i with P = A + t U, Q = B + t W.
      d[k][2] = Exact(0);
      m[k] = {ex(A[i] * B[j] - A[j] * B[i]), ex(A[i] * W[j] + U[i] * B[j] - A[j] * W[i] - U[j] * B[i]),
              ex(U[i] * W[j] - U[j] * W[i])};
    }
  }
};

struct Gen {
  std::mt19937_64 rng;
  explicit Gen(std::uint64_t seed) : rng(seed) {}
  Q coord(int range) { return Q(static_cast<long>(rng() % (2 * range * 16 + 1)) - range * 16, 16); }
  QV point(int range) { return {coord(range), coord(range), coord(range)}; }
  int pick(int n) { return static_cast<int>(rng() % n); }
};

Point3 dbl(const QV& p) { return {p[0].get_d(), p[1].get_d(), p[2].get_d()}; }
bool exact_double(const QV& p) { return Q(p[0].get_d()) == p[0] && Q(p[1].get_d()) == p[1] && Q(p[2].get_d()) == p[2]; }

TEST(EeeLineMissFilter, NeverProvesAMissOfAMeetingLine) {
  Gen g(20261202);
  int cases = 0;
  for (int it = 0; it < 4000; ++it) {
    Family f{g.point(8), g.point(4), g.point(8), g.point(4), {}, {}};
    if (sub(f.A, f.B) == QV{0, 0, 0}) continue;
    f.coefficients();
    // t* in the range [lo, hi] (t* at an end every fifth case), X on L(t*) (between, beyond or at P, Q).
    const Q lo = Q(g.pick(9), 8) - 1, hi = lo + Q(1 + g.pick(16), 8);
    const Q ts = it % 5 == 0 ? (it % 10 == 0 ? lo : hi) : lo + (hi - lo) * Q(1 + g.pick(7), 8);
    const QV P = f.P(ts), D = sub(f.Qp(ts), P);
    const QV X = add(P, scale(Q(g.pick(33) - 8, 8), D));
    // A triangle holding X (X is a multiple of 1/1024 or so: exact in doubles): X inside, X a corner, X on
    // an edge, X inside a zero-area triangle, or the triangle in a plane through the line.
    QV c[3];
    const QV e1 = g.point(2), e2 = g.point(2);
    switch (it % 5) {
      case 0: c[0] = X, c[1] = add(X, e1), c[2] = add(X, e2); break;                         // corner
      case 1: c[0] = sub(X, e1), c[1] = add(X, e1), c[2] = add(X, e2); break;                // on an edge
      case 2: c[0] = sub(X, e1), c[1] = sub(X, e2), c[2] = add(X, add(e1, e2)); break;       // inside
      case 3: c[0] = sub(X, e1), c[1] = add(X, e1), c[2] = add(X, scale(Q(3), e1)); break;  // zero area
      default: c[0] = sub(X, D), c[1] = add(X, D), c[2] = add(X, e1); break;                 // line in plane
    }
    if (!exact_double(c[0]) || !exact_double(c[1]) || !exact_double(c[2])) continue;
    const EeeLineMissFilter filter(f.d, f.m);
    const int r = g.pick(3);  // corner order (both orientations)
    EXPECT_FALSE(filter.misses(dbl(c[r]), dbl(c[(r + 1 + it % 2) % 3]), dbl(c[(r + 2 - it % 2) % 3]), lo.get_d(),
                               hi.get_d()))
        << "case " << it;
    ++cases;
  }
  EXPECT_GT(cases, 3500);
}

TEST(EeeLineMissFilter, ProvesFarTrianglesMissed) {
  // Lines through P(t) in z = 0 and Q(t) in z = 1 (t in [0, 1], both in [-1, 1]^2): at height z = 1/2 each
  // line is at (P + Q) / 2, in [-1, 1]^2, so a triangle in the plane z = 1/2 with x >= 3 misses them all.
  Gen g(7);
  int proved = 0, total = 0;
  for (int it = 0; it < 500; ++it) {
    Family f;
    f.A = {g.coord(1) / 2, g.coord(1) / 2, 0};
    f.U = {g.coord(1) / 2, g.coord(1) / 2, 0};
    f.B = {g.coord(1) / 2, g.coord(1) / 2, 1};
    f.W = {g.coord(1) / 2, g.coord(1) / 2, 0};
    f.coefficients();
    const EeeLineMissFilter filter(f.d, f.m);
    ++total;
    proved += filter.misses({3, -1, 0.5}, {5, 0, 0.5}, {3, 1, 0.5}, 0.0, 1.0);
  }
  EXPECT_EQ(proved, total);
  // Filter off: nothing proved.
  Family f{{0, 0, 0}, {0, 0, 0}, {0, 0, 1}, {0, 0, 0}, {}, {}};
  f.coefficients();
  set_filter_enabled(false);
  const bool off = EeeLineMissFilter(f.d, f.m).misses({3, -1, 0.5}, {5, 0, 0.5}, {3, 1, 0.5}, 0.0, 1.0);
  set_filter_enabled(true);
  EXPECT_FALSE(off);
}

}  // namespace
}  // namespace exactvis
