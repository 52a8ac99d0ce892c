// The 2D occluder grid (region/footprint_grid.hpp) is complete: on random boxes (points, thin segments,
// large boxes, boxes sharing coordinates with the query) and random convex query hulls (point clouds,
// segments, single points), every box that meets the hull, decided by an independent exact separating-axis
// test in GMP rationals, is reported, and none is reported twice; a callback returning true stops the walk.
#include "region/footprint_grid.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

// Exact: does the closed box [lo, hi] (xy) meet the convex hull of the points? Separating axis test over the
// box's axes and the normals of every pair of points (a superset of the hull's edge normals).
bool box_meets_hull(const Box3& b, const std::vector<XyPoint>& pts) {
  const mpq_class bx0(b.lo.x), bx1(b.hi.x), by0(b.lo.y), by1(b.hi.y);
  mpq_class px0(pts[0].x), px1(pts[0].x), py0(pts[0].y), py1(pts[0].y);
  for (const auto& p : pts) {
    px0 = std::min(px0, mpq_class(p.x)), px1 = std::max(px1, mpq_class(p.x));
    py0 = std::min(py0, mpq_class(p.y)), py1 = std::max(py1, mpq_class(p.y));
  }
  if (px1 < bx0 || px0 > bx1 || py1 < by0 || py0 > by1) return false;
  const mpq_class cx[4] = {bx0, bx1, bx0, bx1}, cy[4] = {by0, by0, by1, by1};
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      const mpq_class nx = mpq_class(pts[j].y) - mpq_class(pts[i].y), ny = mpq_class(pts[i].x) - mpq_class(pts[j].x);
      if (nx == 0 && ny == 0) continue;
      mpq_class h0 = nx * mpq_class(pts[0].x) + ny * mpq_class(pts[0].y), h1 = h0;
      for (const auto& p : pts) {
        const mpq_class v = nx * mpq_class(p.x) + ny * mpq_class(p.y);
        h0 = std::min(h0, v), h1 = std::max(h1, v);
      }
      mpq_class b0 = nx * cx[0] + ny * cy[0], b1 = b0;
      for (int k = 1; k < 4; ++k) {
        const mpq_class v = nx * cx[k] + ny * cy[k];
        b0 = std::min(b0, v), b1 = std::max(b1, v);
      }
      if (h1 < b0 || h0 > b1) return false;
    }
  return true;
}

}  // namespace

TEST(FootprintGrid, ReportsEveryBoxMeetingTheHullOnce) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  // Coordinates on a coarse grid half the time, so boxes touch the hull exactly at edges and corners.
  auto coord = [&](double scale) { return u(rng) < 0.5 ? std::round(u(rng) * 16) / 16 * scale : u(rng) * scale; };
  std::int64_t met = 0, reported_extra = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const double scale = trial % 3 == 0 ? 1e4 : 10;
    std::vector<Box3> boxes;
    const int n = 1 + static_cast<int>(u(rng) * 150);
    for (int i = 0; i < n; ++i) {
      const double x = coord(scale), y = coord(scale);
      const int kind = static_cast<int>(u(rng) * 4);
      const double w = kind == 0 ? 0 : (kind == 3 ? coord(scale) : coord(scale / 20)),
                   h = kind == 1 ? 0 : (kind == 3 ? coord(scale) : coord(scale / 20));
      boxes.push_back({{x, y, 0}, {x + w, y + h, 1}});
    }
    if (trial % 7 == 0)  // all on one line: a degenerate grid axis
      for (auto& b : boxes) b.lo.y = b.hi.y = 3;
    const FootprintGrid grid(boxes);
    for (int q = 0; q < 15; ++q) {
      std::vector<XyPoint> pts;
      const int k = 1 + static_cast<int>(u(rng) * 8);
      for (int i = 0; i < k; ++i) pts.push_back({coord(scale * 1.2) - 0.1 * scale, coord(scale * 1.2) - 0.1 * scale});
      if (q % 5 == 0) pts = {pts[0], pts[0]};  // a single point
      if (q % 5 == 1 && boxes.size() > 1)      // a segment between two box corners
        pts = {{boxes[0].lo.x, boxes[0].lo.y}, {boxes[1].hi.x, boxes[1].hi.y}};
      std::vector<int> count(boxes.size(), 0);
      grid.visit_hull(pts, pts[0], [&](std::size_t i) {
        ++count[i];
        return false;
      });
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        EXPECT_LE(count[i], 1) << "trial " << trial << " box " << i << " reported twice";
        if (box_meets_hull(boxes[i], pts)) {
          ++met;
          EXPECT_EQ(count[i], 1) << "trial " << trial << " query " << q << ": box " << i << " meets the hull, not reported";
        } else {
          reported_extra += count[i];
        }
      }
    }
  }
  EXPECT_GT(met, 500);
  std::cout << met << " boxes met their query hull (all reported), " << reported_extra << " reported beyond\n";
}

TEST(FootprintGrid, StopsWhenTheCallbackSaysSo) {
  std::vector<Box3> boxes;
  for (int i = 0; i < 100; ++i) boxes.push_back({{double(i), 0, 0}, {i + 0.5, 1, 1}});
  const FootprintGrid grid(boxes);
  int calls = 0;
  EXPECT_TRUE(grid.visit_hull({{0, 0}, {100, 1}}, {50, 0.5}, [&](std::size_t) { return ++calls == 3; }));
  EXPECT_EQ(calls, 3);
  EXPECT_FALSE(FootprintGrid().visit_hull({{0, 0}}, {0, 0}, [](std::size_t) { return true; }));
  // Nothing near a hull far from every box beyond the grid's border rows (clamped, so a superset is fine,
  // but the walk must terminate and report each box at most once).
  std::vector<int> seen(boxes.size(), 0);
  grid.visit_hull({{-1e6, -1e6}, {-1e6 + 1, -1e6}}, {0, 0}, [&](std::size_t i) { return ++seen[i] > 1; });
  for (int s : seen) EXPECT_LE(s, 1);
}
