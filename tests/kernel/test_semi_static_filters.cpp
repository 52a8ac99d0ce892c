// The hand-written semi-static filters (kernel/semi_static_filters): whenever they decide, the sign is the
// exact one (independent oracle: GMP rationals, homogeneous cofactor determinants), over random, nearly and
// exactly degenerate inputs at every scale from subnormals to near overflow, and inputs built so that the
// determinant lies around the error bound (where a too small constant gives wrong signs). They must also
// decide what they are meant to decide (generic inputs, rescaled magnitudes, small-integer zeros).
#include "kernel/semi_static_filters.hpp"
#include "kernel_test_inputs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace exactvis {
namespace {

using test::to_oracle;

int oracle_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  // det of the homogeneous rows (a, 1), (b, 1), (c, 1), expanded along the last column.
  const mpq_class Ax(ax), Ay(ay), Bx(bx), By(by), Cx(cx), Cy(cy);
  return oracle::sign(Bx * Cy - By * Cx - (Ax * Cy - Ay * Cx) + (Ax * By - Ay * Bx));
}

struct Rng {
  std::mt19937_64 g;
  explicit Rng(std::uint64_t seed) : g(seed) {}
  double uniform(double lo = -1, double hi = 1) { return std::uniform_real_distribution<double>(lo, hi)(g); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(g); }
  // A random scale 2^e, e in [lo, hi].
  double scale(int lo, int hi) { return std::ldexp(1.0, integer(lo, hi)); }
  double ulps(double x, int k) {  // x moved by k ulps (k may be negative)
    for (; k > 0; --k) x = std::nextafter(x, INFINITY);
    for (; k < 0; ++k) x = std::nextafter(x, -INFINITY);
    return x;
  }
};

// Input families for the 3D tests; each returns 4 points.
enum class Kind { Random, Scaled, AxisScaled, NearCoplanar, AroundBound, Collinear, SmallInt, NearInteger,
                  BigIntCoplanar, NearOverflow, Subnormal, Count };

std::array<Point3, 4> make_quad(Rng& r, Kind kind) {
  auto unit = [&] { return Point3{r.uniform(), r.uniform(), r.uniform()}; };
  switch (kind) {
    case Kind::Random: return {unit(), unit(), unit(), unit()};
    case Kind::Scaled: {  // one scale for the case, from subnormal to near overflow
      const double s = r.scale(-1070, 1020);
      auto p = [&] { return Point3{r.uniform() * s, r.uniform() * s, r.uniform() * s}; };
      return {p(), p(), p(), p()};
    }
    case Kind::AxisScaled: {  // one scale per axis
      const double sx = r.scale(-1000, 1000), sy = r.scale(-1000, 1000), sz = r.scale(-1000, 1000);
      auto p = [&] { return Point3{r.uniform() * sx, r.uniform() * sy, r.uniform() * sz}; };
      return {p(), p(), p(), p()};
    }
    case Kind::NearCoplanar: {  // d = b + c - a rounded, then a few ulps off, at any scale
      const double s = r.scale(-900, 900);
      auto p = [&] { return Point3{r.uniform() * s, r.uniform() * s, r.uniform() * s}; };
      const Point3 a = p(), b = p(), c = p();
      Point3 d{b.x + c.x - a.x, b.y + c.y - a.y, b.z + c.z - a.z};
      const int axis = r.integer(0, 2);
      d[axis] = r.ulps(d[axis], r.integer(-3, 3));
      return {a, b, c, d};
    }
    case Kind::AroundBound: {  // |det| spread around the filter's bound (48u mx my mz ~ 1e-14)
      const Point3 a = unit(), b = unit(), c = unit();
      const double t = std::ldexp(r.uniform(), -r.integer(38, 56));
      return {a, b, c, {b.x + c.x - a.x + t, b.y + c.y - a.y, b.z + c.z - a.z}};
    }
    case Kind::Collinear: {  // three points on a line (rounded), any fourth point
      const Point3 a = unit(), b = unit();
      const double w = r.uniform(-2, 2);
      return {a, b, {a.x + w * (b.x - a.x), a.y + w * (b.y - a.y), a.z + w * (b.z - a.z)}, unit()};
    }
    case Kind::SmallInt: {
      auto p = [&] { return Point3{double(r.integer(-4, 4)), double(r.integer(-4, 4)), double(r.integer(-4, 4))}; };
      return {p(), p(), p(), p()};
    }
    case Kind::NearInteger: {  // small integers, some moved by one ulp (their differences may round back)
      auto c = [&] {
        const double x = r.integer(-4, 4);
        return r.integer(0, 3) == 0 ? r.ulps(x, r.integer(0, 1) ? 1 : -1) : x;
      };
      auto p = [&] { return Point3{c(), c(), c()}; };
      return {p(), p(), p(), p()};
    }
    case Kind::BigIntCoplanar: {  // exactly coplanar, 2^40-sized integers: products not representable
      auto i = [&] { return std::ldexp(double(r.integer(-(1 << 30), 1 << 30)), 10); };
      auto p = [&] { return Point3{i(), i(), i()}; };
      const Point3 a = p(), b = p(), c = p();
      return {a, b, c, {b.x + c.x - a.x, b.y + c.y - a.y, b.z + c.z - a.z}};
    }
    case Kind::NearOverflow: {  // coordinates near +-DBL_MAX (differences may overflow)
      const double big = std::ldexp(1.0, 1023);
      const bool same_sign = r.integer(0, 1);
      auto c = [&] { return same_sign ? big * (1 + r.uniform(0, 0.99)) : big * r.uniform() * 1.99; };
      auto p = [&] { return Point3{c(), c(), c()}; };
      return {p(), p(), p(), p()};
    }
    case Kind::Subnormal: {  // multiples of the smallest subnormal, some of them zero
      auto c = [&] { return std::ldexp(double(r.integer(-1000, 1000)), -1074); };
      auto p = [&] { return Point3{c(), c(), c()}; };
      return {p(), p(), p(), p()};
    }
    default: return {};
  }
}

const char* kind_name(Kind k) {
  static const char* names[] = {"random", "scaled", "axis-scaled", "near-coplanar", "around-bound", "collinear",
                                "small-int", "near-integer", "bigint-coplanar", "near-overflow", "subnormal"};
  return names[static_cast<int>(k)];
}

TEST(SemiStaticFilters, Orient3dIsExactWheneverItDecides) {
  Rng r(101);
  const int per_kind = 6000;
  for (int k = 0; k < static_cast<int>(Kind::Count); ++k) {
    const Kind kind = static_cast<Kind>(k);
    int decided = 0;
    for (int i = 0; i < per_kind; ++i) {
      const auto q = make_quad(r, kind);
      const auto s = orient3d_semi_static(q[0], q[1], q[2], q[3]);
      if (!s) continue;
      ++decided;
      const int expected = oracle::orient3d(to_oracle(q[0]), to_oracle(q[1]), to_oracle(q[2]), to_oracle(q[3]));
      ASSERT_EQ(to_int(*s), expected) << kind_name(kind) << " case " << i << ": " << q[0].x << " " << q[3].z;
    }
    // What the layer must decide on its own: generic inputs at any magnitude, small-integer configurations.
    if (kind == Kind::Random || kind == Kind::Scaled || kind == Kind::AxisScaled || kind == Kind::SmallInt ||
        kind == Kind::Subnormal)
      EXPECT_GE(decided, per_kind * 99 / 100) << kind_name(kind);
    if (kind == Kind::BigIntCoplanar) EXPECT_EQ(decided, 0);  // exactly 0 and not certifiable in doubles
    if (kind == Kind::NearOverflow) EXPECT_GT(decided, per_kind / 3);  // rescaled unless a difference overflows
    if (kind == Kind::AroundBound) {  // both sides of the bound occur
      EXPECT_GT(decided, per_kind / 10);
      EXPECT_LT(decided, per_kind * 9 / 10);
    }
  }
}

TEST(SemiStaticFilters, Orient2dIsExactWheneverItDecides) {
  Rng r(102);
  const int per_kind = 8000;
  for (int kind = 0; kind < 8; ++kind) {
    int decided = 0;
    for (int i = 0; i < per_kind; ++i) {
      double p[6];
      switch (kind) {
        case 0:  // random
          for (double& x : p) x = r.uniform();
          break;
        case 1: {  // one scale, subnormal to near overflow
          const double s = r.scale(-1070, 1020);
          for (double& x : p) x = r.uniform() * s;
          break;
        }
        case 2: {  // nearly collinear: c = a + w (b - a) rounded, a few ulps off
          const double s = r.scale(-900, 900), w = r.uniform(-3, 3);
          for (int j = 0; j < 4; ++j) p[j] = r.uniform() * s;
          p[4] = r.ulps(p[0] + w * (p[2] - p[0]), r.integer(-2, 2));
          p[5] = r.ulps(p[1] + w * (p[3] - p[1]), r.integer(-2, 2));
          break;
        }
        case 3: {  // around the bound (8u mx my ~ 1e-15)
          for (int j = 0; j < 4; ++j) p[j] = r.uniform();
          p[4] = 2 * p[2] - p[0] + std::ldexp(r.uniform(), -r.integer(45, 60));
          p[5] = 2 * p[3] - p[1];
          break;
        }
        case 4:  // small integers (many exact zeros)
          for (double& x : p) x = r.integer(-5, 5);
          break;
        case 5: {  // near overflow
          const double big = std::ldexp(1.0, 1023);
          for (double& x : p) x = big * r.uniform() * 1.99;
          break;
        }
        case 6:  // subnormal grid
          for (double& x : p) x = std::ldexp(double(r.integer(-50, 50)), -1074);
          break;
        default:  // small integers, some moved by one ulp
          for (double& x : p) {
            x = r.integer(-5, 5);
            if (r.integer(0, 3) == 0) x = r.ulps(x, r.integer(0, 1) ? 1 : -1);
          }
          break;
      }
      const auto s = orient2d_semi_static(p[0], p[1], p[2], p[3], p[4], p[5]);
      if (!s) continue;
      ++decided;
      ASSERT_EQ(to_int(*s), oracle_orient2d(p[0], p[1], p[2], p[3], p[4], p[5])) << "kind " << kind << " case " << i;
    }
    if (kind == 0 || kind == 1 || kind == 4 || kind == 6) EXPECT_GE(decided, per_kind * 99 / 100) << "kind " << kind;
    if (kind == 3) {
      EXPECT_GT(decided, per_kind / 10);
      EXPECT_LT(decided, per_kind * 9 / 10);
    }
  }
}

TEST(SemiStaticFilters, Cross2dIsExactWheneverItDecides) {
  // The general form cross(u1 - u0, v1 - v0): independent start points, parallel and nearly parallel
  // vectors, shared points, integers, all scales.
  Rng r(103);
  int decided = 0;
  const int n = 30000;
  for (int i = 0; i < n; ++i) {
    double p[8];
    const double s = r.scale(-1000, 1000);
    for (double& x : p) x = r.integer(0, 4) == 0 ? double(r.integer(-6, 6)) : r.uniform() * s;
    switch (r.integer(0, 3)) {
      case 0: p[4] = p[0], p[5] = p[1]; break;                    // v0 = u0
      case 1: p[6] = p[4] + (p[2] - p[0]), p[7] = p[5] + (p[3] - p[1]); break;  // parallel (rounded)
      case 2: p[6] = p[2], p[7] = p[3]; break;                    // v1 = u1
      default: break;
    }
    const auto got = cross2d_semi_static(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]);
    if (!got) continue;
    ++decided;
    const mpq_class ux = mpq_class(p[2]) - p[0], uy = mpq_class(p[3]) - p[1];
    const mpq_class vx = mpq_class(p[6]) - p[4], vy = mpq_class(p[7]) - p[5];
    ASSERT_EQ(to_int(*got), oracle::sign(ux * vy - uy * vx)) << "case " << i;
  }
  EXPECT_GT(decided, n * 3 / 4);
  EXPECT_EQ(difference_sign(0.1, 0.1), Sign::Zero);
  EXPECT_EQ(difference_sign(1e-320, 2e-320), Sign::Positive);
  EXPECT_EQ(difference_sign(-1e308, 1e308), Sign::Positive);  // overflowing difference: sign still right
  EXPECT_EQ(difference_sign(1.0, std::nextafter(1.0, 0.0)), Sign::Negative);
}

TEST(SemiStaticFilters, DecidesZeroColumnsAndOverflowedDifferencesSafely) {
  // A zero column makes the determinant exactly 0 whatever the other entries.
  EXPECT_EQ(orient3d_semi_static({1, 2, 0}, {1e300, -3, 0}, {-1e-300, 5, 0}, {7, 1e-320, 0}), Sign::Zero);
  EXPECT_EQ(orient2d_semi_static(1e308, 5, -1e308, 5, 3, 5), Sign::Zero);  // x differences overflow, y are 0
  // Overflowed differences (inf) never certify a sign.
  const double m = 1.7e308;
  EXPECT_FALSE(orient3d_semi_static({-m, -m, -m}, {m, -m, -m}, {-m, m, -m}, {-m, -m, m}).has_value());
  EXPECT_FALSE(orient2d_semi_static(-m, -m, m, -m, -m, m).has_value());
}

}  // namespace
}  // namespace exactvis
