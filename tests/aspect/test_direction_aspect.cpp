// The exact per-direction aspect of general models (aspect/direction_aspect) against the independent exact
// slab oracle (tests/oracles/aspect_oracle: oracle::direction_aspect, vertical-slab decomposition of the
// projection and exact depth comparisons, no CGAL): hand models inside and outside the class of §10.5
// (three boxes in a row, an open heightfield), random pairs of convex polytopes, random heightfields, at
// random integer directions and at degenerate ones (axes, edge directions, directions in face planes).
// Every witness is re-checked by the oracle's own segment/triangle test.
#include "aspect/direction_aspect.hpp"

#include "kernel/triangle_index.hpp"
#include "tests/aspect/aspect_test_models.hpp"
#include "tests/exact_to_mpq.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using namespace exactvis;
using namespace exactvis::aspect_test;
using exact_to_mpq::qv;

// An open heightfield: an (m+1) x (m+1) grid of integer heights in [0, h], two triangles per square.
Scene heightfield(unsigned seed, int m, int h) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> height(0, h);
  std::vector<Point3> v;
  for (int y = 0; y <= m; ++y)
    for (int x = 0; x <= m; ++x) v.push_back({double(x), double(y), double(height(rng))});
  std::vector<std::array<int, 3>> t;
  for (int y = 0; y < m; ++y)
    for (int x = 0; x < m; ++x) {
      const int a = y * (m + 1) + x, b = a + 1, c = a + m + 1, d = c + 1;
      t.push_back({a, b, d});
      t.push_back({a, d, c});
    }
  return make_scene(v, t);
}

std::vector<std::int64_t> oracle_ids(const Scene& s, const Vec3<Exact>& d) {
  std::vector<std::int64_t> ids;
  for (int i : oracle::direction_aspect(oracle_model(s), qv(d))) ids.push_back(s.triangles[i].id);
  return ids;
}

// The witness is strictly inside its triangle and a long segment from it towards the viewer, beyond every
// scene point, meets no triangle (oracle geometry only).
void check_witnesses(const Scene& s, const Vec3<Exact>& d, const DirectionAspect& a) {
  ASSERT_EQ(a.witnesses.size(), a.aspect.size());
  const auto model = oracle_model(s);
  mpq_class reach = 1;
  for (const auto& p : s.vertices) reach += abs(mpq_class(p.x)) + abs(mpq_class(p.y)) + abs(mpq_class(p.z));
  const oracle::QVec qd = qv(d);
  mpq_class dn = abs(qd.x) + abs(qd.y) + abs(qd.z);
  for (std::size_t k = 0; k < a.aspect.size(); ++k) {
    ASSERT_EQ(a.witnesses[k].triangle, a.aspect[k]);
    const std::int64_t idx = s.index_of_id(a.aspect[k]);
    ASSERT_GE(idx, 0);
    const oracle::QVec x = qv(a.witnesses[k].point);
    const auto& tri = model[idx];
    EXPECT_TRUE(oracle::oracle_point_in_triangle_relative_interior(x, tri[0], tri[1], tri[2]));
    const oracle::QVec far = x + (2 * reach / dn) * qd;
    for (std::size_t u = 0; u < model.size(); ++u) {
      if (static_cast<std::int64_t>(u) == idx) continue;
      EXPECT_FALSE(oracle::oracle_open_segment_meets_closed_triangle(x, far, model[u][0], model[u][1], model[u][2]))
          << "witness of " << a.aspect[k] << " blocked by " << u;
    }
  }
}

void check_directions(const Scene& s, const std::vector<Vec3<Exact>>& dirs) {
  const TriangleIndex index(s);
  for (const auto& d : dirs) {
    const DirectionAspect a = direction_aspect(s, d, &index);
    EXPECT_EQ(a.aspect, oracle_ids(s, d)) << "d = " << d.x << " " << d.y << " " << d.z;
    check_witnesses(s, d, a);
  }
}

std::vector<Vec3<Exact>> random_directions(unsigned seed, int count, int range) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> c(-range, range);
  std::vector<Vec3<Exact>> out;
  while (static_cast<int>(out.size()) < count) {
    Vec3<Exact> d(Exact(c(rng)), Exact(c(rng)), Exact(c(rng)));
    if (d.x != 0 || d.y != 0 || d.z != 0) out.push_back(d);
  }
  return out;
}

// Axis directions, the directions of the scene's edges and of the sums / differences of two edge vectors of
// a triangle (in its plane): where faces are edge-on and edges collapse to points.
std::vector<Vec3<Exact>> degenerate_directions(const Scene& s, int limit) {
  std::vector<Vec3<Exact>> out;
  for (int k = 0; k < 3; ++k)
    for (int sg : {-1, 1}) {
      Vec3<Exact> d;
      d[k] = Exact(sg);
      out.push_back(d);
    }
  for (const auto& t : s.triangles) {
    if (static_cast<int>(out.size()) >= limit) break;
    const Vec3<Exact> a = Vec3<Exact>::from(s.corner(t, 0)), b = Vec3<Exact>::from(s.corner(t, 1)),
                      c = Vec3<Exact>::from(s.corner(t, 2));
    out.push_back(b - a);
    out.push_back(a - c);
    out.push_back((b - a) + (c - a));
  }
  return out;
}

TEST(DirectionAspect, HandModelsMatchOracle) {
  for (const Scene& s : {cube(), tetrahedron(), l_prism(), two_boxes(), notched_box(), three_boxes()}) {
    check_directions(s, random_directions(7, 24, 4));
    check_directions(s, degenerate_directions(s, 40));
  }
}

TEST(DirectionAspect, ThreeBoxesAlongTheRow) {
  // From +x only the last cube's +x face (triangles 34, 35); from a direction slightly off the row the
  // middle and first cubes' +x faces show in part.
  const Scene s = three_boxes();
  EXPECT_EQ(direction_aspect(s, {Exact(1), Exact(0), Exact(0)}).aspect, (std::vector<std::int64_t>{34, 35}));
  const Vec3<Exact> off(Exact(4), Exact(1), Exact(1));
  const auto a = direction_aspect(s, off).aspect;
  EXPECT_EQ(a, oracle_ids(s, off));
  EXPECT_TRUE(std::find(a.begin(), a.end(), 10) != a.end() || std::find(a.begin(), a.end(), 11) != a.end());
}

TEST(DirectionAspect, RandomPairsOfConvexPolytopesMatchOracle) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const Scene s = combined(random_convex(seed, 7, 4), translated(random_convex(100 + seed, 7, 4), 9, 1, 0));
    check_directions(s, random_directions(seed, 10, 3));
  }
}

TEST(DirectionAspect, RandomHeightfieldsMatchOracle) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const Scene s = heightfield(seed, 3, 3);
    check_directions(s, random_directions(50 + seed, 12, 3));
    check_directions(s, degenerate_directions(s, 16));
  }
}

TEST(DirectionAspect, ZeroDirectionIsRejected) {
  EXPECT_THROW(direction_aspect(cube(), {Exact(0), Exact(0), Exact(0)}), std::invalid_argument);
}

}  // namespace
