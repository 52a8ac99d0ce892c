// bench_predicates: cost per call of the kernel's filtered orient3d and side_of_lines next to CGAL's
// Exact_predicates_inexact_constructions_kernel orient_3 (static filter, then interval, then exact), measured
// in the same run on the same point quadruples, interleaved (each round runs the three on the whole array,
// in rotating order; the table gives the median round). Then the share of calls each layer of
// filtered_sign decides, per input family, and the always-exact paths (filter disabled: CGAL::Mpzf; rational
// inputs: Gmpq) for scale. All three agree on every sign (checked; exit 1 otherwise).
//
// Usage: bench_predicates [N] [ROUNDS]   (N quadruples per input family, default 200000; ROUNDS default 7)
#include "kernel/filtered_predicate.hpp"
#include "kernel/predicates.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace exactvis;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

namespace {

struct Quad {
  Point3 a, b, c, d;
};
struct CgalQuad {
  Epick::Point_3 a, b, c, d;
};

struct Family {
  const char* name;
  const char* what;
  std::vector<Quad> quads;
};

std::vector<Quad> make_quads(int n, std::uint64_t seed, const std::function<Quad(std::mt19937_64&)>& one) {
  std::mt19937_64 rng(seed);
  std::vector<Quad> v;
  v.reserve(n);
  for (int i = 0; i < n; ++i) v.push_back(one(rng));
  return v;
}

Point3 uniform_point(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-1, 1);
  return {u(rng) * scale, u(rng) * scale, u(rng) * scale};
}

// d = b + c - a computed in doubles: exactly coplanar when the sums are exact (integer grids), nearly
// coplanar (one rounding) otherwise.
Quad coplanar(const Point3& a, const Point3& b, const Point3& c) {
  return {a, b, c, {b.x + c.x - a.x, b.y + c.y - a.y, b.z + c.z - a.z}};
}

std::vector<Family> families(int n) {
  std::vector<Family> f;
  f.push_back({"random", "uniform in [-1,1]^3", make_quads(n, 1, [](auto& r) {
                 return Quad{uniform_point(r, 1), uniform_point(r, 1), uniform_point(r, 1), uniform_point(r, 1)};
               })});
  f.push_back({"grid-2^40", "exactly coplanar, integers up to 2^40 (products not representable)",
               make_quads(n, 2, [](auto& r) {
                 std::uniform_int_distribution<long long> u(-(1LL << 40), 1LL << 40);
                 auto p = [&] { return Point3{double(u(r)), double(u(r)), double(u(r))}; };
                 return coplanar(p(), p(), p());
               })});
  f.push_back({"grid-small", "exactly coplanar, integers in [-8,8] (exact in doubles)", make_quads(n, 3, [](auto& r) {
                 std::uniform_int_distribution<int> u(-8, 8);
                 auto p = [&] { return Point3{double(u(r)), double(u(r)), double(u(r))}; };
                 return coplanar(p(), p(), p());
               })});
  f.push_back({"near-coplanar", "d = b + c - a rounded, in [-1,1]^3 (|det| ~ 1e-16)", make_quads(n, 4, [](auto& r) {
                 return coplanar(uniform_point(r, 1), uniform_point(r, 1), uniform_point(r, 1));
               })});
  f.push_back({"tiny", "uniform in [-1e-150,1e-150]^3 (products underflow)", make_quads(n, 5, [](auto& r) {
                 return Quad{uniform_point(r, 1e-150), uniform_point(r, 1e-150), uniform_point(r, 1e-150),
                             uniform_point(r, 1e-150)};
               })});
  f.push_back({"huge", "uniform in [-1e150,1e150]^3 (products overflow)", make_quads(n, 6, [](auto& r) {
                 return Quad{uniform_point(r, 1e150), uniform_point(r, 1e150), uniform_point(r, 1e150),
                             uniform_point(r, 1e150)};
               })});
  return f;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// One timed pass of f over the array: seconds, and the sum of the signs (also keeps the calls alive).
template <class Q, class F>
std::pair<double, long> pass(const std::vector<Q>& v, F&& f) {
  long sum = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& q : v) sum += f(q);
  return {seconds_since(t0), sum};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

PredicateCounterSnapshot counter_named(const std::string& name) {
  for (const auto& c : predicate_counters())
    if (c.name == name) return c;
  return {name};
}

}  // namespace

int main(int argc, char** argv) {
  int n = 200000, rounds = 7;
  for (int i = 1; i < argc && i <= 2; ++i) {
    char* end = nullptr;
    const long v = std::strtol(argv[i], &end, 10);
    if (*end != '\0' || v <= 0 || v > 100000000) {
      std::fprintf(stderr, "bench_predicates: error: %s must be a positive integer (got '%s')\n",
                   i == 1 ? "N" : "ROUNDS", argv[i]);
      return 2;
    }
    (i == 1 ? n : rounds) = static_cast<int>(v);
  }
  const auto fams = families(n);
  const Epick::Orientation_3 cgal_orient = Epick().orientation_3_object();
  auto ours_orient = [](const Quad& q) { return to_int(orient3d(q.a, q.b, q.c, q.d)); };
  auto ours_side = [](const Quad& q) { return to_int(side_of_lines(q.a, q.b, q.c, q.d)); };
  auto cgal = [&](const CgalQuad& q) { return static_cast<int>(cgal_orient(q.a, q.b, q.c, q.d)); };

  std::printf("N = %d quadruples per family, %d interleaved rounds (median round; ns per call)\n\n", n, rounds);
  std::printf("%-14s %10s %10s %10s %12s %12s   %-20s %-20s\n", "input", "CGAL ns", "orient ns", "side ns",
              "orient/CGAL", "side/CGAL", "orient3d S/I/E %", "side_of_lines S/I/E %");
  for (const Family& f : fams) {
    std::vector<CgalQuad> cq;
    cq.reserve(f.quads.size());
    auto cp = [](const Point3& p) { return Epick::Point_3(p.x, p.y, p.z); };
    for (const Quad& q : f.quads) cq.push_back({cp(q.a), cp(q.b), cp(q.c), cp(q.d)});
    // Layer shares: one counted pass each (not timed).
    reset_predicate_counters();
    long so = 0, ss = 0, sc = 0;
    for (const Quad& q : f.quads) so += ours_orient(q), ss += ours_side(q);
    for (const CgalQuad& q : cq) sc += cgal(q);
    std::vector<int> mismatches;
    for (std::size_t i = 0; i < f.quads.size(); ++i)
      if (ours_orient(f.quads[i]) != cgal(cq[i]) || ours_side(f.quads[i]) != ours_orient(f.quads[i]))
        mismatches.push_back(static_cast<int>(i));
    if (!mismatches.empty() || so != sc || ss != so) {
      std::fprintf(stderr, "bench_predicates: error: signs differ from CGAL on %zu %s quadruples\n",
                   mismatches.size(), f.name);
      return 1;
    }
    const auto o = counter_named("orient3d"), s = counter_named("side_of_lines");
    auto shares = [&](const PredicateCounterSnapshot& c) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.1f/%.1f/%.1f", 100.0 * c.semi_static / c.calls, 100.0 * c.interval / c.calls,
                    100.0 * c.exact / c.calls);
      return std::string(buf);
    };
    const std::string os = shares(o), sshare = shares(s);
    std::vector<double> tc, to, ts;
    for (int r = 0; r < rounds; ++r) {
      for (int k = 0; k < 3; ++k) {
        switch ((r + k) % 3) {
          case 0: tc.push_back(pass(cq, cgal).first); break;
          case 1: to.push_back(pass(f.quads, ours_orient).first); break;
          default: ts.push_back(pass(f.quads, ours_side).first); break;
        }
      }
    }
    const double c_ns = 1e9 * median(tc) / n, o_ns = 1e9 * median(to) / n, s_ns = 1e9 * median(ts) / n;
    std::printf("%-14s %10.1f %10.1f %10.1f %12.2f %12.2f   %-20s %-20s\n", f.name, c_ns, o_ns, s_ns, o_ns / c_ns,
                s_ns / c_ns, os.c_str(), sshare.c_str());
    std::fflush(stdout);
  }
  std::printf("\n(S/I/E = share of calls decided by the semi-static filter / the interval filter / exact evaluation)\n");
  for (const Family& f : fams) std::printf("  %-14s %s\n", f.name, f.what);

  // The exact paths alone, for scale: filter disabled (double inputs: CGAL::Mpzf), rational inputs (Gmpq).
  std::printf("\nalways exact (ns per call): orient3d Mpzf / Gmpq, side_of_lines Mpzf / Gmpq\n");
  for (const Family& f : fams) {
    if (std::string(f.name) != "random" && std::string(f.name) != "grid-2^40") continue;
    std::vector<Quad> sub(f.quads.begin(), f.quads.begin() + std::min<std::size_t>(f.quads.size(), 20000));
    struct RQuad {
      RationalPoint3 a, b, c, d;
    };
    std::vector<RQuad> rq;
    for (const Quad& q : sub) rq.push_back({to_rational(q.a), to_rational(q.b), to_rational(q.c), to_rational(q.d)});
    set_filter_enabled(false);
    const double om = pass(sub, ours_orient).first, sm = pass(sub, ours_side).first;
    const double og = pass(rq, [](const RQuad& q) { return to_int(orient3d(q.a, q.b, q.c, q.d)); }).first;
    const double sg = pass(rq, [](const RQuad& q) { return to_int(side_of_lines(q.a, q.b, q.c, q.d)); }).first;
    set_filter_enabled(true);
    const double m = static_cast<double>(sub.size());
    std::printf("  %-14s %8.0f %8.0f %8.0f %8.0f\n", f.name, 1e9 * om / m, 1e9 * og / m, 1e9 * sm / m, 1e9 * sg / m);
  }
  return 0;
}
