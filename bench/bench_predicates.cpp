// Throughput of the filtered predicates (interval filter, exact fallback) vs always-exact evaluation
// (set_filter_enabled(false)), on random and on degenerate inputs. Prints a table (see docs/performance.md).
// Double inputs fall back to CGAL::Mpzf; the "exact Gmpq" column runs the same predicates on the same points
// converted to rationals (RationalPoint3 overloads, always exact), i.e. the GMP-rational exact path.
//
// Usage: bench_predicates [N]   (N evaluations per row, default 200000)
#include "kernel/filtered_predicate.hpp"
#include "kernel/predicates.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace exactvis;

namespace {

struct Quad {
  Point3 a, b, c, d;
};
struct RQuad {
  RationalPoint3 a, b, c, d;
};

std::vector<Quad> random_quads(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  auto p = [&]() { return Point3{u(rng), u(rng), u(rng)}; };
  std::vector<Quad> v;
  for (int i = 0; i < n; ++i) v.push_back({p(), p(), p(), p()});
  return v;
}

// Exactly degenerate: d = b + c - a on a 2^40 integer grid (exact sums, inexact products): orient3d = 0 and
// side(line(a,b), line(c,d)) = 0, and the interval filter cannot certify it.
std::vector<Quad> degenerate_quads(int n, std::uint64_t seed) {
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

struct Row {
  double seconds = 0;
  std::uint64_t exact = 0;
  long checksum = 0;
};

template <class Q, class F>
Row run(const std::vector<Q>& quads, bool filter, const char* counter_name, F&& f) {
  set_filter_enabled(filter);
  reset_predicate_counters();
  Row r;
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& q : quads) r.checksum += to_int(f(q));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const auto& c : predicate_counters())
    if (c.name == counter_name) r.exact = c.exact;
  set_filter_enabled(true);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  int n = 200000;
  if (argc > 1) {
    char* end = nullptr;
    const long v = std::strtol(argv[1], &end, 10);
    if (*end != '\0' || v <= 0 || v > 100000000) {
      std::fprintf(stderr, "bench_predicates: error: N must be a positive integer (got '%s')\n", argv[1]);
      return 2;
    }
    n = static_cast<int>(v);
  }
  const auto random = random_quads(n, 1);
  const auto degenerate = degenerate_quads(n, 2);
  auto orient = [](const auto& q) { return orient3d(q.a, q.b, q.c, q.d); };
  auto sidef = [](const auto& q) { return side_of_lines(q.a, q.b, q.c, q.d); };
  auto rational = [](const std::vector<Quad>& v) {
    std::vector<RQuad> r;
    for (const auto& q : v) r.push_back({to_rational(q.a), to_rational(q.b), to_rational(q.c), to_rational(q.d)});
    return r;
  };
  const auto random_r = rational(random), degenerate_r = rational(degenerate);

  std::printf("N = %d evaluations per row (Mop/s = million predicate calls per second)\n\n", n);
  std::printf("%-14s %-11s %13s %13s %13s %9s %9s %10s\n", "predicate", "input", "filtered", "exact Mpzf",
              "exact Gmpq", "filt/Mpzf", "filt/Gmpq", "fallbacks");
  struct Case {
    const char* pred;
    const char* counter;
    const char* input;
    const std::vector<Quad>* data;
    const std::vector<RQuad>* rdata;
    bool is_orient;
  };
  const Case cases[] = {{"orient3d", "orient3d", "random", &random, &random_r, true},
                        {"orient3d", "orient3d", "degenerate", &degenerate, &degenerate_r, true},
                        {"side_of_lines", "side_of_lines", "random", &random, &random_r, false},
                        {"side_of_lines", "side_of_lines", "degenerate", &degenerate, &degenerate_r, false}};
  for (const auto& c : cases) {
    const Row f = c.is_orient ? run(*c.data, true, c.counter, orient) : run(*c.data, true, c.counter, sidef);
    const Row e = c.is_orient ? run(*c.data, false, c.counter, orient) : run(*c.data, false, c.counter, sidef);
    const Row g = c.is_orient ? run(*c.rdata, false, c.counter, orient) : run(*c.rdata, false, c.counter, sidef);
    if (f.checksum != e.checksum || f.checksum != g.checksum) {
      std::fprintf(stderr, "bench_predicates: error: filtered and exact results differ\n");
      return 1;
    }
    char fb[64];
    std::snprintf(fb, sizeof fb, "%.2f%%", 100.0 * double(f.exact) / n);
    std::printf("%-14s %-11s %7.2f Mop/s %7.2f Mop/s %7.2f Mop/s %8.1fx %8.1fx %10s\n", c.pred, c.input,
                n / f.seconds / 1e6, n / e.seconds / 1e6, n / g.seconds / 1e6, e.seconds / f.seconds,
                g.seconds / f.seconds, fb);
  }
  return 0;
}
