// Point location by horizontal ray shooting (planar/point_location_2d) against a brute force written here
// in GMP rationals with none of the structure's reasoning: the east (west) ray is replaced by an actual ray
// of direction (1, -delta) ((-1, +delta)), delta a rational small enough that no vertex lies between it and
// the horizontal, shot exactly against every edge; boundary by exact point-on-segment tests; inside by the
// crossing number over all rings. Scenes: random integer-grid scenes (collinear vertices across objects,
// parallel edges), axis-parallel boxes with flat vertices and holes (many vertices and horizontal edges at
// one height), triangles on a 7 x 7 grid, and a scene with rational (non-double) coordinates. Query points:
// every point of a half-integer grid (on vertex heights, vertical lines through vertices, edge lines,
// vertices), points on edge lines inside and outside the edges, random points.
#include "tests/planar/scene2d_test_util.hpp"
#include "planar/point_location_2d.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

using namespace exactvis;
using namespace exactvis::test2d;

namespace {

struct Q2 {
  mpq_class x, y;
};

Q2 q2(const Point2& p) { return {mpq_class(p.x.mpq()), mpq_class(p.y.mpq())}; }
mpq_class cross(const Q2& o, const Q2& a, const Q2& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool brute_on_boundary(const Scene2D& s, const Q2& q) {
  for (int e = 0; e < s.num_vertices(); ++e) {
    const Q2 a = q2(s.points[e]), b = q2(s.points[s.next[e]]);
    if (cross(a, b, q) != 0) continue;
    if (std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y && q.y <= std::max(a.y, b.y))
      return true;
  }
  return false;
}

// q off the boundary: odd number of ring crossings of the rightward horizontal ray (half-open rule).
bool brute_inside(const Scene2D& s, const Q2& q) {
  bool in = false;
  for (int e = 0; e < s.num_vertices(); ++e) {
    const Q2 a = q2(s.points[e]), b = q2(s.points[s.next[e]]);
    if ((a.y > q.y) == (b.y > q.y)) continue;
    const mpq_class x = a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y);
    if (x > q.x) in = !in;
  }
  return in;
}

// The edge first met by the ray from q of direction (dir, -dir delta), dir = +-1, for a delta below every
// positive slope to a vertex on that side: the ray turned clockwise from (dir, 0) by an infinitesimal.
int brute_first_hit(const Scene2D& s, const Q2& q, int dir) {
  mpq_class delta = 1;
  for (const Point2& p : s.points) {
    const Q2 v = q2(p);
    const mpq_class run = dir * (v.x - q.x), drop = dir * (q.y - v.y);
    if (run > 0 && drop > 0 && drop / run < delta) delta = drop / run;
  }
  delta /= 2;
  const Q2 d{mpq_class(dir), -dir * delta};
  int best = -1;
  mpq_class best_t;
  for (int e = 0; e < s.num_vertices(); ++e) {
    const Q2 a = q2(s.points[e]), b = q2(s.points[s.next[e]]);
    const Q2 ab{b.x - a.x, b.y - a.y}, qa{a.x - q.x, a.y - q.y};
    const mpq_class den = d.x * ab.y - d.y * ab.x;
    if (den == 0) continue;  // parallel: the ray passes no vertex, so it cannot run along the edge
    const mpq_class t = (qa.x * ab.y - qa.y * ab.x) / den, u = (qa.x * d.y - qa.y * d.x) / den;
    if (t <= 0 || u < 0 || u > 1) continue;
    if (best < 0 || t < best_t) best = e, best_t = t;
  }
  return best;
}

// Checks every query point against the brute force; returns how many were on the boundary / inside / free.
std::array<int, 3> check_scene(const std::string& name, const Scene2D& s, const std::vector<Point2>& queries) {
  const PointLocation2D L = point_location_2d(s);
  std::array<int, 3> counts{};
  for (const Point2& p : queries) {
    const Q2 q = q2(p);
    const LocatedPoint2D got = locate_point(L, p);
    const bool boundary = brute_on_boundary(s, q);
    EXPECT_EQ(got.on_boundary, boundary) << name << " at (" << q.x << ", " << q.y << ")";
    if (boundary || got.on_boundary) {
      ++counts[0];
      continue;
    }
    const bool inside = brute_inside(s, q);
    ++counts[inside ? 1 : 2];
    EXPECT_EQ(got.inside_object, inside) << name << " at (" << q.x << ", " << q.y << ")";
    EXPECT_EQ(got.east, brute_first_hit(s, q, 1)) << name << " east ray at (" << q.x << ", " << q.y << ")";
    EXPECT_EQ(got.west, brute_first_hit(s, q, -1)) << name << " west ray at (" << q.x << ", " << q.y << ")";
    if (::testing::Test::HasFailure()) break;
  }
  return counts;
}

// Half-integer grid points over the scene's box (grown by 1), points on the lines of edges (inside and
// outside the edges), and random points.
std::vector<Point2> query_points(const Scene2D& s, std::uint64_t seed, int random_count, double step = 0.5) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const Point2& p : s.points) x0 = std::min(x0, p.ax), y0 = std::min(y0, p.ay), x1 = std::max(x1, p.ax), y1 = std::max(y1, p.ay);
  std::vector<Point2> out;
  for (double x = std::floor(x0) - 1; x <= x1 + 1; x += step)
    for (double y = std::floor(y0) - 1; y <= y1 + 1; y += step) out.emplace_back(x, y);
  for (int e = 0; e < s.num_vertices(); ++e) {
    const Point2 &a = s.points[e], &b = s.points[s.next[e]];
    for (const Exact& w : {Exact(-1), Exact(-1, 2), Exact(1, 4), Exact(1, 2), Exact(3, 2), Exact(2)})
      out.emplace_back(a.x + w * (b.x - a.x), a.y + w * (b.y - a.y));
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(x0 - 1, x1 + 1), uy(y0 - 1, y1 + 1);
  for (int i = 0; i < random_count; ++i) out.emplace_back(ux(rng), uy(rng));
  return out;
}

TEST(PointLocation2D, RandomGridScenesMatchBruteForce) {
  int scenes = 0;
  std::array<int, 3> total{};
  for (std::uint64_t seed = 1; scenes < 6 && seed < 40; ++seed) {
    const auto s = try_scene(oracle2d::random_grid_scene(seed, 2, seed % 3 == 0));
    if (!s || s->num_vertices() == 0) continue;
    ++scenes;
    const auto c = check_scene("grid seed " + std::to_string(seed), *s, query_points(*s, seed, 200, 1.0));
    for (int k = 0; k < 3; ++k) total[k] += c[k];
    if (HasFailure()) return;
  }
  EXPECT_EQ(scenes, 6);
  for (int k = 0; k < 3; ++k) EXPECT_GT(total[k], 100) << k;  // boundary, inside and free points all occur
}

TEST(PointLocation2D, BoxScenesWithFlatVerticesAndHolesMatchBruteForce) {
  std::array<int, 3> total{};
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto s = try_scene(random_box_scene(seed, 6));
    ASSERT_TRUE(s);
    const auto c = check_scene("boxes seed " + std::to_string(seed), *s, query_points(*s, seed, 100, 1.0));
    for (int k = 0; k < 3; ++k) total[k] += c[k];
    if (HasFailure()) return;
  }
  for (int k = 0; k < 3; ++k) EXPECT_GT(total[k], 100) << k;
}

TEST(PointLocation2D, TrianglesOnASmallGridMatchBruteForce) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const auto s = try_scene(random_triangle_scene(seed, 5));
    ASSERT_TRUE(s);
    check_scene("triangles seed " + std::to_string(seed), *s, query_points(*s, seed, 50, 0.5));
    if (HasFailure()) return;
  }
}

TEST(PointLocation2D, RationalCoordinatesAndEmptyScene) {
  // Boxes scaled by 1/3 (coordinates that are no doubles), queried at thirds and sixths.
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    std::vector<PolygonInput2D> in;
    for (const auto& poly : random_box_scene(seed, 5)) {
      PolygonInput2D p;
      for (const auto& ring : poly.rings) {
        std::vector<Point2> r;
        for (const auto& v : ring) r.emplace_back(Exact(v[0]) / 3, Exact(v[1]) / 3);
        p.rings.push_back(std::move(r));
      }
      in.push_back(std::move(p));
    }
    const Scene2D s = make_scene2d(in);
    std::vector<Point2> qs;
    for (int i = -2; i <= 50; i += 2)
      for (int j = -2; j <= 50; ++j) qs.emplace_back(Exact(i, 6), Exact(j, 6));
    check_scene("rational boxes seed " + std::to_string(seed), s, qs);
    if (HasFailure()) return;
  }
  const Scene2D empty = make_scene2d({});
  const LocatedPoint2D at = locate_point(point_location_2d(empty), Point2(1, 2));
  EXPECT_FALSE(at.on_boundary || at.inside_object);
  EXPECT_EQ(at.east, -1);
  EXPECT_EQ(at.west, -1);
}

}  // namespace
