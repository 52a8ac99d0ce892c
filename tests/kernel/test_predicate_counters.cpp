// The counters of kernel/predicate_counters: per predicate name, calls and the layer deciding each call;
// the counts add up, are listed per name (instantiations summed), survive their threads and reset.
#include "kernel/predicate_counters.hpp"
#include "kernel/predicates.hpp"
#include "kernel_test_inputs.hpp"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <random>
#include <thread>

namespace exactvis {
namespace {

using test::PointGenerator;

PredicateCounterSnapshot counter_named(const std::string& name) {
  for (const auto& c : predicate_counters())
    if (c.name == name) return c;
  return {name};
}

TEST(PredicateCounters, LayerCountsAddUpToCalls) {
  PointGenerator gen(32);
  reset_predicate_counters();
  for (int i = 0; i < 3000; ++i) {
    gen.start_case();
    const Point3 a = gen.next(), b = gen.next(), c = gen.next(), d = gen.next();
    orient3d(a, b, c, d);
    orient3d(to_rational(a), to_rational(b), to_rational(c), to_rational(d));  // same name: summed
    side_of_lines(a, b, c, d);
    orient2d_projected(a, b, c, i % 3);
    collinear(a, b, c);
    side_of_lines(line_through(to_rational(a), to_rational(b)), line_through(to_rational(c), to_rational(d)));
  }
  int checked = 0;
  for (const auto& c : predicate_counters()) {
    EXPECT_EQ(c.semi_static + c.interval + c.exact, c.calls) << c.name;
    checked += c.calls > 0;
  }
  EXPECT_GE(checked, 5);
  EXPECT_EQ(counter_named("orient3d").calls, 6000u);
  EXPECT_EQ(counter_named("side_of_lines").calls, 3000u);
  EXPECT_EQ(counter_named("side_of_plucker_lines").calls, 3000u);
}

TEST(PredicateCounters, CountsFromManyThreads) {
  // Thread-local counts: visible while the threads live, kept after they exit, reset everywhere.
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<std::array<Point3, 4>> quads(2000);
  for (auto& q : quads)
    for (auto& p : q) p = {u(rng), u(rng), u(rng)};
  reset_predicate_counters();
  std::atomic<int> done{0};
  std::atomic<bool> release{false};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      for (const auto& q : quads) orient3d(q[0], q[1], q[2], q[3]);
      done.fetch_add(1);
      while (!release.load()) std::this_thread::yield();
      for (const auto& q : quads) orient3d(q[0], q[1], q[2], q[3]);
    });
  while (done.load() < 4) std::this_thread::yield();
  EXPECT_EQ(counter_named("orient3d").calls, 8000u);  // live threads' blocks
  reset_predicate_counters();
  EXPECT_EQ(counter_named("orient3d").calls, 0u);
  release = true;
  for (auto& th : threads) th.join();
  const auto o = counter_named("orient3d");  // exited threads' totals
  EXPECT_EQ(o.calls, 8000u);
  EXPECT_EQ(o.semi_static + o.interval + o.exact, o.calls);
}

TEST(PredicateCounters, CountersAreListedAndReset) {
  orient3d(Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1});
  bool found = false;
  for (const auto& c : predicate_counters()) found |= c.name == "orient3d" && c.calls > 0;
  EXPECT_TRUE(found);
  reset_predicate_counters();
  for (const auto& c : predicate_counters()) {
    EXPECT_EQ(c.calls, 0u) << c.name;
    EXPECT_EQ(c.semi_static + c.interval + c.exact, 0u) << c.name;
  }
  EXPECT_EQ(exact_evaluations_total(), 0u);
}

}  // namespace
}  // namespace exactvis
