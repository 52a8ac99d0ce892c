// The three layers of kernel/filtered_predicate (semi-static, interval, exact) and their counters: each
// layer decides what it should (random inputs: semi-static; exact zeros of exact double arithmetic:
// semi-static or interval; zeros that doubles cannot certify: exact), every decision of every layer is the
// exact sign (independent oracle), and switching the filters off changes no result (only the counters).
#include "kernel/filtered_predicate.hpp"
#include "kernel/predicates.hpp"
#include "kernel_test_inputs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace exactvis {
namespace {

using test::PointGenerator;
using test::to_oracle;

PredicateCounterSnapshot counter_named(const std::string& name) {
  for (const auto& c : predicate_counters())
    if (c.name == name) return c;
  return {name};
}

struct Quad {
  Point3 a, b, c, d;
};

std::vector<Quad> random_quads(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Quad> v;
  for (int i = 0; i < n; ++i) v.push_back({{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)},
                                           {u(rng), u(rng), u(rng)}});
  return v;
}

// Exactly coplanar quadruples d = b + c - a on a grid of 2^40-sized integers: the sums are exact in doubles,
// the determinant's products are not, so neither filter can certify the zero.
std::vector<Quad> coplanar_quads(int n, std::uint64_t seed, double scale = 1) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long long> u(-(1LL << 40), 1LL << 40);
  auto p = [&]() { return Point3{scale * double(u(rng)), scale * double(u(rng)), scale * double(u(rng))}; };
  std::vector<Quad> v;
  for (int i = 0; i < n; ++i) {
    Quad q{p(), p(), p(), {}};
    q.d = {q.b.x + q.c.x - q.a.x, q.b.y + q.c.y - q.a.y, q.b.z + q.c.z - q.a.z};
    v.push_back(q);
  }
  return v;
}

TEST(FilteredPredicate, RandomInputsAreDecidedBySemiStaticLayer) {
  const auto quads = random_quads(20000, 5);
  orient3d(quads[0].a, quads[0].b, quads[0].c, quads[0].d);  // registers the counter
  reset_predicate_counters();
  for (const auto& q : quads) {
    orient3d(q.a, q.b, q.c, q.d);
    side_of_lines(q.a, q.b, q.c, q.d);
  }
  const auto o = counter_named("orient3d"), s = counter_named("side_of_lines");
  EXPECT_EQ(o.calls, 20000u);
  EXPECT_GE(o.semi_static, 19980u);  // ~all: no rounding-mode switch on generic inputs
  EXPECT_GE(s.semi_static, 19980u);
  EXPECT_LE(o.exact, 20u);
}

TEST(FilteredPredicate, DegenerateInputsFallBackToExact) {
  const auto quads = coplanar_quads(2000, 6);
  reset_predicate_counters();
  for (const auto& q : quads) {
    ASSERT_EQ(orient3d(q.a, q.b, q.c, q.d), Sign::Zero);
    // side(line(a,b), line(c,d)) = orient3d(a,b,c,d): the same degenerate value.
    ASSERT_EQ(side_of_lines(q.a, q.b, q.c, q.d), Sign::Zero);
  }
  const auto o = counter_named("orient3d");
  EXPECT_EQ(o.calls, 2000u);
  EXPECT_GE(o.exact, 1900u);  // (nearly) every call needed the exact path
  EXPECT_GE(counter_named("side_of_lines").exact, 1900u);
  EXPECT_GE(exact_evaluations_total(), o.exact);
}

TEST(FilteredPredicate, ExactZerosOfDoubleArithmeticNeedNoExactPath) {
  reset_predicate_counters();
  // Small integers: every operation is exact, certified by the semi-static layer.
  EXPECT_EQ(orient3d(Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{3, 4, 0}), Sign::Zero);
  EXPECT_EQ(orient3d(Point3{1, 2, 3}, Point3{4, 0, 2}, Point3{-2, 5, 1}, Point3{1, 3, 0}), Sign::Zero);
  EXPECT_EQ(counter_named("orient3d").semi_static, 2u);
  // Halves and quarters: exact in doubles, but not integers: the interval evaluation is [0, 0].
  EXPECT_EQ(orient3d(Point3{0.5, 0, 0}, Point3{0, 0.5, 0}, Point3{0, 0, 0.5}, Point3{0.25, 0.125, 0.125}),
            Sign::Zero);
  EXPECT_EQ(counter_named("orient3d").interval, 1u);
  EXPECT_EQ(counter_named("orient3d").exact, 0u);
}

TEST(FilteredPredicate, HugeAndTinyMagnitudes) {
  // Beyond the semi-static layer's safe range the columns are rescaled by powers of two (sign-preserving,
  // exact): huge and tiny generic inputs stay in layer 1, though their products overflow or underflow.
  reset_predicate_counters();
  const double h = 1e150, t = 1e-150;
  EXPECT_EQ(orient3d(Point3{0, 0, 0}, Point3{h, 0, 0}, Point3{0, h, 0}, Point3{0, 0, h}), Sign::Positive);
  EXPECT_EQ(orient3d(Point3{h, h, h}, Point3{-h, h, h}, Point3{h, -h, h}, Point3{h, h, -h}), Sign::Negative);
  EXPECT_EQ(orient3d(Point3{0, 0, 0}, Point3{t, 0, 0}, Point3{0, t, 0}, Point3{0, 0, -t}), Sign::Negative);
  EXPECT_EQ(counter_named("orient3d").semi_static, 3u);
  // An exact zero at a tiny scale cannot be certified in doubles: the exact layer decides.
  for (const auto& q : coplanar_quads(10, 9, std::ldexp(1.0, -600)))
    EXPECT_EQ(orient3d(q.a, q.b, q.c, q.d), Sign::Zero);
  EXPECT_EQ(counter_named("orient3d").exact, 10u);
  // Scaling by a power of two changes no sign, however small the result.
  const double s = std::ldexp(1.0, -520), third = 1.0 / 3;
  EXPECT_EQ(orient3d(Point3{s, 0, 0}, Point3{0, s, 0}, Point3{0, 0, s}, Point3{s * third, s * third, s * third}),
            orient3d(Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}, Point3{third, third, third}));
}

// Which layer decided one call of `f` (from the counter deltas of `name`).
template <class F>
FilterLayer layer_of_call(const std::string& name, F&& f, Sign* result) {
  const auto before = counter_named(name);
  *result = f();
  const auto after = counter_named(name);
  if (after.semi_static > before.semi_static) return FilterLayer::SemiStatic;
  if (after.interval > before.interval) return FilterLayer::Interval;
  return FilterLayer::Exact;
}

TEST(FilteredPredicate, EveryLayerAgreesWithTheExactSign) {
  // The adversarial generator (shared vertices, last-bit perturbations, points on lines and planes through
  // earlier points, huge/tiny/mixed magnitudes) reaches all three layers of orient3d on double and on
  // rational inputs (the generic BoundedDouble layer); each decision is checked against the oracle.
  PointGenerator gen(31);
  int by_layer[2][3] = {};
  for (int i = 0; i < 6000; ++i) {
    gen.start_case();
    const Point3 a = gen.next(), b = gen.next(), c = gen.next(), d = gen.next();
    const int expected = oracle::orient3d(to_oracle(a), to_oracle(b), to_oracle(c), to_oracle(d));
    Sign s;
    const FilterLayer l = layer_of_call("orient3d", [&] { return orient3d(a, b, c, d); }, &s);
    ASSERT_EQ(to_int(s), expected) << "double inputs, layer " << static_cast<int>(l) << ", case " << i;
    ++by_layer[0][static_cast<int>(l)];
    const FilterLayer lr = layer_of_call(
        "orient3d", [&] { return orient3d(to_rational(a), to_rational(b), to_rational(c), to_rational(d)); }, &s);
    ASSERT_EQ(to_int(s), expected) << "rational inputs, layer " << static_cast<int>(lr) << ", case " << i;
    ++by_layer[1][static_cast<int>(lr)];
  }
  for (int input = 0; input < 2; ++input)
    for (int l = 0; l < 3; ++l) EXPECT_GE(by_layer[input][l], 30) << "input " << input << " layer " << l;
}

TEST(FilteredPredicate, DisablingTheFilterChangesNoResult) {
  auto quads = random_quads(2000, 7);
  const auto cop = coplanar_quads(500, 8);
  quads.insert(quads.end(), cop.begin(), cop.end());
  PointGenerator gen(34);
  for (int i = 0; i < 2000; ++i) {
    gen.start_case();
    quads.push_back({gen.next(), gen.next(), gen.next(), gen.next()});
  }
  auto signs = [&] {
    std::vector<Sign> out;
    for (const auto& q : quads) {
      out.push_back(orient3d(q.a, q.b, q.c, q.d));
      out.push_back(side_of_lines(q.a, q.b, q.c, q.d));
      out.push_back(orient2d_projected(q.a, q.b, q.c, 2));
      out.push_back(collinear(q.a, q.b, q.d) ? Sign::Zero : Sign::Positive);
      out.push_back(orient3d(to_rational(q.a), to_rational(q.b), to_rational(q.c), to_rational(q.d)));
    }
    return out;
  };
  const std::vector<Sign> with_filter = signs();
  set_filter_enabled(false);
  reset_predicate_counters();
  const std::vector<Sign> without = signs();
  const auto o = counter_named("orient3d");
  set_filter_enabled(true);
  EXPECT_EQ(with_filter, without);
  EXPECT_EQ(o.exact, o.calls);  // always exact when disabled
  EXPECT_EQ(o.calls, 2 * quads.size());
}

}  // namespace
}  // namespace exactvis
