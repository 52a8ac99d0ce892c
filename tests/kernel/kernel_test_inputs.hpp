#pragma once
// Deterministic random and adversarial inputs for the kernel property tests, and conversions to the
// independent oracle's types (tests/oracles/rational_geometry.hpp).
#include "kernel/line_through_point_meeting_two_lines.hpp"
#include "kernel/plucker_line.hpp"
#include "kernel/predicates.hpp"
#include "oracles/rational_geometry.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

namespace exactvis::test {

inline oracle::QVec to_oracle(const Point3& p) { return oracle::qvec(p.x, p.y, p.z); }
inline mpq_class to_mpq(const Exact& x) { return mpq_class(x.mpq()); }
inline oracle::QVec to_oracle(const RationalPoint3& p) { return {to_mpq(p.x), to_mpq(p.y), to_mpq(p.z)}; }
inline oracle::QLine to_oracle(const PluckerLine<Exact>& l) {
  return {{to_mpq(l.d.x), to_mpq(l.d.y), to_mpq(l.d.z)}, {to_mpq(l.m.x), to_mpq(l.m.y), to_mpq(l.m.z)}};
}

// Number families: one per test case, so that points of a case share magnitudes (or deliberately not).
enum class Family { Unit, SmallInt, BigInt, Huge, Tiny, Mixed, Count };

inline const char* family_name(Family f) {
  switch (f) {
    case Family::Unit: return "unit";
    case Family::SmallInt: return "small-int";
    case Family::BigInt: return "big-int";
    case Family::Huge: return "huge";
    case Family::Tiny: return "tiny";
    case Family::Mixed: return "mixed";
    default: return "?";
  }
}

// Generates the points of one case: fresh points of the family, or degenerate ones built from earlier points
// of the case (shared vertices, last-bit perturbations, points on lines and planes through earlier points).
struct PointGenerator {
  std::mt19937_64 rng;
  Family family = Family::Unit;
  std::vector<Point3> pool;
  double degenerate_probability = 0.6;

  explicit PointGenerator(std::uint64_t seed) : rng(seed) {}

  void start_case(Family f) {
    family = f;
    pool.clear();
  }
  void start_case() { start_case(static_cast<Family>(uniform_int(0, static_cast<int>(Family::Count) - 1))); }

  int uniform_int(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

  double fresh_coordinate() {
    switch (family) {
      case Family::Unit: return uniform(-1, 1);
      case Family::SmallInt: return uniform_int(-3, 3);
      case Family::BigInt: return std::ldexp(static_cast<double>(uniform_int(-(1 << 30), 1 << 30)), 20);
      case Family::Huge: return uniform(-1, 1) * 1e150;
      case Family::Tiny: return uniform(-1, 1) * 1e-150;
      case Family::Mixed: return std::ldexp(uniform(-1, 1), uniform_int(-600, 600));
      default: return 0;
    }
  }
  Point3 fresh() { return {fresh_coordinate(), fresh_coordinate(), fresh_coordinate()}; }
  const Point3& pick() { return pool[uniform_int(0, static_cast<int>(pool.size()) - 1)]; }

  // Affine weights that are exact in binary (so results are exact for dyadic-friendly inputs).
  double weight() {
    static const double w[] = {-1.0, -0.5, 0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0};
    return w[uniform_int(0, 8)];
  }

  Point3 degenerate() {
    const int n = static_cast<int>(pool.size());
    switch (uniform_int(0, 4)) {
      case 0: return pick();  // shared vertex
      case 1: {               // last-bit perturbation of one coordinate
        Point3 p = pick();
        const int k = uniform_int(0, 2);
        const double toward = uniform_int(0, 1) ? INFINITY : -INFINITY;
        for (int i = uniform_int(1, 2); i > 0; --i) p[k] = std::nextafter(p[k], toward);
        return p;
      }
      case 2: {  // on the line through two earlier points (exact when the arithmetic is)
        const Point3 a = pick(), b = pick();
        const double w = weight();
        return {a.x + w * (b.x - a.x), a.y + w * (b.y - a.y), a.z + w * (b.z - a.z)};
      }
      case 3: {  // on the plane through three earlier points
        if (n < 3) return pick();
        const Point3 a = pick(), b = pick(), c = pick();
        const double u = weight(), v = weight();
        return {a.x + u * (b.x - a.x) + v * (c.x - a.x), a.y + u * (b.y - a.y) + v * (c.y - a.y),
                a.z + u * (b.z - a.z) + v * (c.z - a.z)};
      }
      default: {  // coordinates copied from earlier points (axis-aligned coincidences)
        Point3 p = fresh();
        p[uniform_int(0, 2)] = pick()[uniform_int(0, 2)];
        return p;
      }
    }
  }

  Point3 next() {
    Point3 p = (pool.empty() || uniform(0, 1) >= degenerate_probability) ? fresh() : degenerate();
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(p[k])) p[k] = 0;  // weights can overflow huge inputs
    pool.push_back(p);
    return p;
  }
};

// N exact lines, each through the generator's next two points; std::nullopt when a pair coincides (the
// caller skips the case; the points are drawn either way, so later cases stay the same).
template <std::size_t N>
std::optional<std::array<PluckerLine<Exact>, N>> next_lines(PointGenerator& gen) {
  std::array<PluckerLine<Exact>, N> lines;
  bool ok = true;
  for (auto& l : lines) {
    const Point3 p = gen.next(), q = gen.next();
    ok &= !(p == q);
    l = exact_line_through(p, q);
  }
  if (!ok) return std::nullopt;
  return lines;
}

}  // namespace exactvis::test
