// Visibility polygons against CGAL's Triangular_expansion_visibility_2 and Rotational_sweep_visibility_2
// (regularized) at thousands of random points, compared exactly; visible edge sets against the brute force.
#include "cgal_visibility_test_util.hpp"
#include "skeleton/visibility_polygon_2d.hpp"

#include <CGAL/Rotational_sweep_visibility_2.h>
#include <CGAL/Triangular_expansion_visibility_2.h>
#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::test2d;

namespace {

using K = CgalK;
using Arr = CgalArr;
using Pt = oracle2d::Pt;

struct Fixture {
  std::vector<oracle2d::Polygon> polys;  // scene + frame, for the oracle
  Scene2D framed;
  Arr arr;
};

bool make_fixture(std::uint64_t seed, int cells, Fixture& fx) {
  const auto polys = oracle2d::random_grid_scene(seed, cells);
  const auto s = try_scene(polys);
  if (!s) return false;
  fx.framed = with_frame(*s, 0.1);
  fx.polys = polys;
  fx.polys.push_back(frame_polygon(fx.framed));
  insert_scene_edges(fx.framed, fx.arr);
  return true;
}

// Random query points: half uniform doubles, half on a half-integer grid (collinear with many vertices).
std::vector<Point2> query_points(const Fixture& fx, std::mt19937_64& rng, int count) {
  const Ring2D& fr = fx.framed.rings[fx.framed.frame_ring];
  double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
  for (int i = 0; i < fr.size; ++i) {
    const Point2& p = fx.framed.points[fr.first + i];
    lo_x = std::min(lo_x, p.ax), lo_y = std::min(lo_y, p.ay), hi_x = std::max(hi_x, p.ax), hi_y = std::max(hi_y, p.ay);
  }
  std::vector<Point2> out;
  while (static_cast<int>(out.size()) < count) {
    double x = std::uniform_real_distribution<double>(lo_x, hi_x)(rng);
    double y = std::uniform_real_distribution<double>(lo_y, hi_y)(rng);
    if (out.size() % 2) x = std::round(2 * x) / 2, y = std::round(2 * y) / 2;
    const Pt q{mpq_class(x), mpq_class(y)};
    if (oracle2d::on_boundary(fx.polys, q) || oracle2d::inside_object(fx.polys, q)) continue;
    out.emplace_back(x, y);
  }
  return out;
}

}  // namespace

TEST(VisibilityPolygon2D, MatchesCgalTriangularExpansionAndRotationalSweepExactly) {
  std::mt19937_64 rng(2024);
  int queries = 0, scenes = 0;
  for (std::uint64_t seed = 100; scenes < 12 && seed < 400; ++seed) {
    Fixture fx;
    if (!make_fixture(seed, 2 + seed % 2, fx)) continue;
    ++scenes;
    CGAL::Triangular_expansion_visibility_2<Arr, CGAL::Tag_true> tev(fx.arr);
    CGAL::Rotational_sweep_visibility_2<Arr, CGAL::Tag_true> rsv(fx.arr);
    CGAL::Arr_naive_point_location<Arr> locator(fx.arr);
    for (const Point2& q : query_points(fx, rng, 200)) {
      const K::Point_2 cq(q.ax, q.ay);
      const auto located = locator.locate(cq);
      const Arr::Face_const_handle* face = boost::get<Arr::Face_const_handle>(&located);
      ASSERT_TRUE(face) << "query point not in a face";
      Arr out_tev, out_rsv;
      const auto f_tev = tev.compute_visibility(cq, *face, out_tev);
      const auto f_rsv = rsv.compute_visibility(cq, *face, out_rsv);
      std::vector<Pt> mine;
      for (const Point2& p : visibility_polygon(fx.framed, q).vertices) mine.push_back(to_pt(p));
      const auto a = normalize(mine), b = normalize(face_polygon(f_tev)), c = normalize(face_polygon(f_rsv));
      ASSERT_GE(a.size(), 3u);
      ASSERT_TRUE(a == b) << "seed " << seed << " q=(" << q.ax << "," << q.ay << ")\nmine " << show(a) << "\nTEV  "
                          << show(b);
      ASSERT_TRUE(a == c) << "seed " << seed << " q=(" << q.ax << "," << q.ay << ")\nmine " << show(a) << "\nRSV  "
                          << show(c);
      ++queries;
    }
  }
  EXPECT_GE(queries, 2000);
}

TEST(VisibilityPolygon2D, VisibleEdgesMatchBruteForce) {
  std::mt19937_64 rng(7);
  int queries = 0, scenes = 0;
  for (std::uint64_t seed = 500; scenes < 6 && seed < 800; ++seed) {
    Fixture fx;
    if (!make_fixture(seed, 2, fx)) continue;
    ++scenes;
    for (const Point2& q : query_points(fx, rng, 40)) {
      const auto mine = edge_endpoint_pairs(fx.framed, visible_edges(fx.framed, q));
      const auto expected = oracle2d::brute_force_visible_edges(fx.polys, to_pt(q));
      ASSERT_EQ(mine.size(), expected.size()) << "seed " << seed << " q=(" << q.ax << "," << q.ay << ")";
      for (std::size_t i = 0; i < mine.size(); ++i) EXPECT_TRUE(mine[i][0] == expected[i][0] && mine[i][1] == expected[i][1]);
      ++queries;
    }
  }
  EXPECT_GE(queries, 200);
}

TEST(VisibilityPolygon2D, RejectsPointsOnBoundaryOrInsideObjects) {
  const Scene2D s = with_frame(make_scene2d({{{{Point2(0.0, 0.0), Point2(1.0, 0.0), Point2(1.0, 1.0), Point2(0.0, 1.0)}}}}));
  EXPECT_THROW(visibility_polygon(s, Point2(0.5, 0.5)), std::invalid_argument);
  EXPECT_THROW(visibility_polygon(s, Point2(1.0, 0.5)), std::invalid_argument);
  EXPECT_THROW(visibility_polygon(make_scene2d({{{{Point2(0.0, 0.0), Point2(1.0, 0.0), Point2(1.0, 1.0)}}}}),
                                  Point2(3.0, 3.0)),
               std::invalid_argument);
  EXPECT_NO_THROW(visibility_polygon(s, Point2(1.5, 0.5)));
}

TEST(VisibilityPolygon2D, BatchFromOneRotationalSweepEqualsSingleQueriesAndCgal) {
  // visibility_polygons (all points in one rotational sweep) against visibility_polygon (one angular
  // sweep per point: same vertex sequence exactly) and CGAL's triangular expansion (same region)
  std::mt19937_64 rng(99);
  int queries = 0, scenes = 0;
  for (std::uint64_t seed = 200; scenes < 10 && seed < 500; ++seed) {
    Fixture fx;
    if (!make_fixture(seed, 2 + seed % 2, fx)) continue;
    ++scenes;
    auto qs = query_points(fx, rng, 150);
    qs.push_back(qs.front());  // a repeated point
    const auto batch = visibility_polygons(fx.framed, qs);
    ASSERT_EQ(batch.size(), qs.size());
    CGAL::Triangular_expansion_visibility_2<Arr, CGAL::Tag_true> tev(fx.arr);
    CGAL::Arr_naive_point_location<Arr> locator(fx.arr);
    for (std::size_t i = 0; i < qs.size(); ++i) {
      const Point2& q = qs[i];
      const auto single = visibility_polygon(fx.framed, q).vertices;
      ASSERT_TRUE(single == batch[i].vertices) << "seed " << seed << " q=(" << q.ax << "," << q.ay << ")";
      const K::Point_2 cq(q.ax, q.ay);
      const auto located = locator.locate(cq);
      const Arr::Face_const_handle* face = boost::get<Arr::Face_const_handle>(&located);
      ASSERT_TRUE(face);
      Arr out_tev;
      const auto f_tev = tev.compute_visibility(cq, *face, out_tev);
      std::vector<Pt> mine;
      for (const Point2& p : batch[i].vertices) mine.push_back(to_pt(p));
      ASSERT_TRUE(normalize(mine) == normalize(face_polygon(f_tev))) << "seed " << seed;
      ++queries;
    }
  }
  EXPECT_GE(queries, 1500);
}

TEST(VisibilityPolygon2D, BatchRejectsPointsOnBoundaryOrInsideObjects) {
  const Scene2D s = with_frame(make_scene2d({{{{Point2(0.0, 0.0), Point2(1.0, 0.0), Point2(1.0, 1.0), Point2(0.0, 1.0)}}}}));
  EXPECT_THROW(visibility_polygons(s, {Point2(1.5, 0.5), Point2(0.5, 0.5)}), std::invalid_argument);  // inside
  EXPECT_THROW(visibility_polygons(s, {Point2(1.0, 0.5)}), std::invalid_argument);                     // on an edge
  EXPECT_THROW(visibility_polygons(s, {Point2(0.5, 0.0)}), std::invalid_argument);                     // horizontal edge
  EXPECT_THROW(visibility_polygons(s, {Point2(1.0, 1.0)}), std::invalid_argument);                     // a vertex
  EXPECT_THROW(visibility_polygons(s, {Point2(100.0, 0.5)}), std::invalid_argument);                   // outside frame
  EXPECT_THROW(visibility_polygons(make_scene2d({{{{Point2(0.0, 0.0), Point2(1.0, 0.0), Point2(1.0, 1.0)}}}}),
                                   {Point2(3.0, 3.0)}),
               std::invalid_argument);  // no frame
  const auto ok = visibility_polygons(s, {Point2(1.5, 0.5), Point2(-0.25, 1.0)});
  EXPECT_TRUE(ok[0].vertices == visibility_polygon(s, Point2(1.5, 0.5)).vertices);
  EXPECT_TRUE(ok[1].vertices == visibility_polygon(s, Point2(-0.25, 1.0)).vertices);
}
