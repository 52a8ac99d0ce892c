// The interval filter of kernel/filtered_predicate: it decides random inputs on its own, falls back to the
// exact path on degenerate inputs, and switching it off changes no result (only the counters).
#include "kernel/filtered_predicate.hpp"
#include "kernel/predicates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace exactvis {
namespace {

PredicateCounterSnapshot counter_named(const std::string& name) {
  for (const auto& c : predicate_counters())
    if (c.name == name) return c;
  return {name, 0, 0};
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
// the determinant's products are not, so the interval straddles 0 without being [0,0].
std::vector<Quad> coplanar_quads(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long long> u(-(1LL << 40), 1LL << 40);
  auto p = [&]() { return Point3{double(u(rng)), double(u(rng)), double(u(rng))}; };
  std::vector<Quad> v;
  for (int i = 0; i < n; ++i) {
    Quad q{p(), p(), p(), {}};
    q.d = {q.b.x + q.c.x - q.a.x, q.b.y + q.c.y - q.a.y, q.b.z + q.c.z - q.a.z};
    v.push_back(q);
  }
  return v;
}

TEST(FilteredPredicate, RandomInputsStayInTheFilter) {
  const auto quads = random_quads(20000, 5);
  orient3d(quads[0].a, quads[0].b, quads[0].c, quads[0].d);  // registers the counter
  reset_predicate_counters();
  for (const auto& q : quads) {
    orient3d(q.a, q.b, q.c, q.d);
    side_of_lines(q.a, q.b, q.c, q.d);
  }
  EXPECT_EQ(counter_named("orient3d").calls, 20000u);
  EXPECT_LE(counter_named("orient3d").exact, 20u);  // ~0: random inputs are decided by intervals
  EXPECT_LE(counter_named("side_of_lines").exact, 20u);
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

TEST(FilteredPredicate, ZeroIntervalIsDecidedWithoutExactPath) {
  // Small integer inputs evaluate exactly in intervals: [0,0] is a certified zero.
  reset_predicate_counters();
  EXPECT_EQ(orient3d(Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{3, 4, 0}), Sign::Zero);
  EXPECT_EQ(counter_named("orient3d").exact, 0u);
}

TEST(FilteredPredicate, DisablingTheFilterChangesNoResult) {
  auto quads = random_quads(3000, 7);
  const auto cop = coplanar_quads(1000, 8);
  quads.insert(quads.end(), cop.begin(), cop.end());
  std::vector<Sign> with_filter;
  for (const auto& q : quads) with_filter.push_back(orient3d(q.a, q.b, q.c, q.d));
  set_filter_enabled(false);
  reset_predicate_counters();
  std::vector<Sign> without;
  for (const auto& q : quads) without.push_back(orient3d(q.a, q.b, q.c, q.d));
  const auto o = counter_named("orient3d");
  set_filter_enabled(true);
  EXPECT_EQ(with_filter, without);
  EXPECT_EQ(o.exact, o.calls);  // always exact when disabled
  EXPECT_EQ(o.calls, quads.size());
}

TEST(FilteredPredicate, OverflowAndUnderflowFallBack) {
  // Huge coordinates overflow the interval products (a one-sided overflow [DBL_MAX, inf] still certifies the
  // sign); tiny ones underflow to [-denorm_min, 0], which cannot: the exact path must decide.
  reset_predicate_counters();
  const double h = 1e150, t = 1e-150;
  EXPECT_EQ(orient3d(Point3{0, 0, 0}, Point3{h, 0, 0}, Point3{0, h, 0}, Point3{0, 0, h}), Sign::Positive);
  EXPECT_EQ(orient3d(Point3{h, h, h}, Point3{-h, h, h}, Point3{h, -h, h}, Point3{h, h, -h}), Sign::Negative);
  EXPECT_EQ(counter_named("orient3d").exact, 0u);
  EXPECT_EQ(orient3d(Point3{0, 0, 0}, Point3{t, 0, 0}, Point3{0, t, 0}, Point3{0, 0, -t}), Sign::Negative);
  EXPECT_EQ(counter_named("orient3d").exact, 1u);
  // Scaling by a power of two changes no sign, however small the result.
  const double s = std::ldexp(1.0, -520), third = 1.0 / 3;
  EXPECT_EQ(orient3d(Point3{s, 0, 0}, Point3{0, s, 0}, Point3{0, 0, s}, Point3{s * third, s * third, s * third}),
            orient3d(Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}, Point3{third, third, third}));
}

TEST(FilteredPredicate, CountersAreListedAndReset) {
  orient3d(Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1});
  bool found = false;
  for (const auto& c : predicate_counters()) found |= c.name == "orient3d" && c.calls > 0;
  EXPECT_TRUE(found);
  reset_predicate_counters();
  for (const auto& c : predicate_counters()) {
    EXPECT_EQ(c.calls, 0u) << c.name;
    EXPECT_EQ(c.exact, 0u) << c.name;
  }
  EXPECT_EQ(exact_evaluations_total(), 0u);
}

}  // namespace
}  // namespace exactvis
