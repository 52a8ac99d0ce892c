// The real-line test of Plücker cones. Certificates are checked directly (a point of the closure with q > 0
// and one with q < 0 prove real lines by the intermediate value argument); "no real lines" answers are
// attacked by sampling real lines (through random rational points) that satisfy every constraint.
#include "region/real_line_test.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

Vec3<Exact> random_point(std::mt19937_64& rng, int range) {
  auto c = [&] { return Exact(static_cast<long>(rng() % (2 * range + 1)) - range); };
  return {c(), c(), c()};
}

IntVec6 as_vector(const PluckerLine<Exact>& l) { return to_int_vector(l); }

// Does some sampled real line satisfy every constraint strictly?
bool sampled_real_line_inside(const std::vector<IntVec6>& constraints, std::mt19937_64& rng, int tries) {
  for (int t = 0; t < tries; ++t) {
    const auto p = random_point(rng, 40), q = random_point(rng, 40);
    if (p == q) continue;
    const IntVec6 x = as_vector(line_through(p, q));
    bool ok = true;
    for (const auto& w : constraints) ok = ok && sgn(dot(w, x)) > 0;
    if (ok) return true;
  }
  return false;
}

}  // namespace

TEST(RealLineTest, CertificatesAndSamplingAgree) {
  std::mt19937_64 rng(2024);
  int with_lines = 0, without = 0, by_faces = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // Constraints from random real lines (edges), as in the visibility queries.
    std::optional<PolyhedralCone6> cone = whole_space_cone();
    std::vector<IntVec6> constraints;
    const int n = 6 + static_cast<int>(rng() % 8);
    for (int i = 0; i < n && cone; ++i) {
      const auto a = random_point(rng, 5), b = random_point(rng, 5);
      if (a == b) continue;
      const IntVec6 w = side_functional(line_through(a, b));
      constraints.push_back(w);
      cone = intersect_open_halfspace(*cone, w);
    }
    if (!cone || !cone->lineality.empty()) continue;  // lineality: see the visibility tests
    const RealLineTest t = test_real_lines(*cone);
    if (t.decided_by == 4) ++by_faces;
    if (t.has_real_lines) {
      ++with_lines;
      EXPECT_TRUE(in_closure(*cone, t.positive_point.to_gmp()));
      EXPECT_TRUE(in_closure(*cone, t.negative_point.to_gmp()));
      EXPECT_GT(sgn(plucker_form(t.positive_point.to_gmp())), 0);
      EXPECT_LT(sgn(plucker_form(t.negative_point.to_gmp())), 0);
    } else {
      ++without;
      EXPECT_FALSE(sampled_real_line_inside(constraints, rng, 3000)) << "trial " << trial;
    }
  }
  EXPECT_GT(with_lines, 20);
  EXPECT_GT(without, 20);
  RecordProperty("decided_by_faces", by_faces);
}

TEST(RealLineTest, ConicCaseThreeLinesOfARegulus) {
  // Lines passing three skew lines of one regulus of the hyperboloid x^2 + y^2 - z^2 = 1 on prescribed
  // sides, and a fourth constraint: the answer must match sampling in both directions.
  std::mt19937_64 rng(99);
  // Rulings (cos t - sin t * s, sin t + cos t * s, s) for t = 0, 2pi/3, 4pi/3 approximated by rational points:
  const Vec3<Exact> a0{Exact(1), Exact(0), Exact(0)}, a1{Exact(1), Exact(1), Exact(1)};
  const Vec3<Exact> b0{Exact(0), Exact(1), Exact(0)}, b1{Exact(-1), Exact(1), Exact(1)};
  const Vec3<Exact> c0{Exact(-1), Exact(0), Exact(0)}, c1{Exact(-1), Exact(-1), Exact(1)};
  const std::vector<PluckerLine<Exact>> ruling{line_through(a0, a1), line_through(b0, b1), line_through(c0, c1)};
  int checked = 0;
  for (int signs = 0; signs < 16; ++signs) {
    std::optional<PolyhedralCone6> cone = whole_space_cone();
    std::vector<IntVec6> constraints;
    for (int i = 0; i < 3 && cone; ++i) {
      IntVec6 w = side_functional(ruling[i]);
      if (signs & (1 << i))
        for (auto& c : w) c = -c;
      constraints.push_back(w);
      cone = intersect_open_halfspace(*cone, w);
    }
    // Three more edges (a triangle the lines must cross) make the cone pointed.
    const Vec3<Exact> p0{Exact(0), Exact(0), Exact(5)}, p1{Exact(3), Exact(0), Exact(5)}, p2{Exact(0), Exact(3), Exact(5)};
    for (const auto& e : {line_through(p0, p1), line_through(p1, p2), line_through(p2, p0)}) {
      if (!cone) break;
      IntVec6 w = side_functional(e);
      if (signs & 8)
        for (auto& c : w) c = -c;
      constraints.push_back(w);
      cone = intersect_open_halfspace(*cone, w);
    }
    if (!cone) continue;
    const RealLineTest t = test_real_lines(*cone);
    ++checked;
    if (t.has_real_lines) {
      EXPECT_GT(sgn(plucker_form(t.positive_point.to_gmp())), 0);
      EXPECT_LT(sgn(plucker_form(t.negative_point.to_gmp())), 0);
    } else {
      EXPECT_FALSE(sampled_real_line_inside(constraints, rng, 20000));
    }
  }
  EXPECT_GT(checked, 0);
}
