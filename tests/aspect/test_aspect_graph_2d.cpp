// The 2D aspect graph checked by sampling viewpoints with the brute-force oracle: the same aspect everywhere
// inside a region, a different aspect across every region boundary.
#include "tests/planar/scene2d_test_util.hpp"
#include "aspect/aspect_graph_2d.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::test2d;

namespace {

using Edge = std::array<oracle2d::Pt, 2>;

std::vector<Edge> as_edges(const Scene2D& s, const std::vector<int>& ids) {
  std::vector<Edge> out;
  for (int e : ids) {
    oracle2d::Pt a = to_pt(s.points[e]), b = to_pt(s.points[s.next[e]]);
    if (b < a) std::swap(a, b);
    out.push_back({a, b});
  }
  std::sort(out.begin(), out.end(), [](const Edge& x, const Edge& y) { return x[0] < y[0] || (x[0] == y[0] && x[1] < y[1]); });
  return out;
}

bool same(const std::vector<Edge>& x, const std::vector<Edge>& y) {
  if (x.size() != y.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!(x[i][0] == y[i][0] && x[i][1] == y[i][1])) return false;
  return true;
}

// Oracle aspect: visible edges of the scene with its frame, frame edges dropped.
std::vector<Edge> oracle_aspect(const std::vector<oracle2d::Polygon>& with_frame_polys, std::size_t n_objects,
                                const oracle2d::Pt& p) {
  const auto all = oracle2d::brute_force_visible_edges(with_frame_polys, p);
  std::vector<Edge> out;
  // frame vertices are exactly the frame polygon's hole ring; drop edges with a frame endpoint
  const auto& hole = with_frame_polys.back().rings[1];
  auto is_frame = [&](const oracle2d::Pt& q) {
    for (const auto& h : hole)
      if (q.x == h[0] && q.y == h[1]) return true;
    return false;
  };
  for (const auto& e : all)
    if (!is_frame(e[0]) && !is_frame(e[1])) out.push_back(e);
  (void)n_objects;
  return out;
}

void check_scene(const std::vector<oracle2d::Polygon>& polys, std::mt19937_64& rng, int random_points) {
  const Scene2D s = make_scene2d(to_input(polys));
  const AspectGraph2D g = aspect_graph(s, 0.25);
  auto framed_polys = polys;
  framed_polys.push_back(frame_polygon(g.framed));
  ASSERT_GE(g.regions.size(), 2u);
  // 1. every face sample has its region's aspect (also checks our sweep against the oracle)
  for (const auto& f : g.faces) {
    if (f.region < 0) continue;
    EXPECT_TRUE(same(oracle_aspect(framed_polys, polys.size(), to_pt(f.sample)),
                     as_edges(g.framed, g.regions[f.region].aspect)))
        << "face sample (" << f.sample.ax << "," << f.sample.ay << ")";
  }
  // 2. different aspects across every boundary: the two sides' samples differ under the oracle
  for (const auto& [a, b] : g.adjacency) {
    const auto& fa = g.faces[g.regions[a].faces.front()];
    const auto& fb = g.faces[g.regions[b].faces.front()];
    EXPECT_FALSE(same(oracle_aspect(framed_polys, polys.size(), to_pt(fa.sample)),
                      oracle_aspect(framed_polys, polys.size(), to_pt(fb.sample))))
        << "regions " << a << " and " << b << " have the same aspect";
  }
  // 3. random viewpoints: the oracle's aspect is the aspect of the region they fall in
  const Ring2D& fr = g.framed.rings[g.framed.frame_ring];
  const Point2 &lo = g.framed.points[fr.first], &hi = g.framed.points[fr.first + 2];
  std::uniform_real_distribution<double> ux(lo.ax, hi.ax), uy(lo.ay, hi.ay);
  int located = 0;
  for (int t = 0; t < random_points; ++t) {
    const Point2 p(ux(rng), uy(rng));
    const int r = region_of(g, p);
    if (r < 0) continue;
    ++located;
    EXPECT_TRUE(same(oracle_aspect(framed_polys, polys.size(), to_pt(p)), as_edges(g.framed, g.regions[r].aspect)))
        << "viewpoint (" << p.ax << "," << p.ay << ") region " << r;
  }
  EXPECT_GE(located, random_points / 3);
}

oracle2d::Ring box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

}  // namespace

TEST(AspectGraph2D, TwoSquaresSampledViewpoints) {
  std::mt19937_64 rng(1);
  check_scene({{{box(0, 0, 1, 1)}}, {{box(3, 0.5, 4, 2)}}}, rng, 300);
}

TEST(AspectGraph2D, DegenerateCollinearSquares) {
  std::mt19937_64 rng(2);
  check_scene({{{box(0, 0, 1, 1)}}, {{box(2, 0, 3, 1)}}, {{box(4, 0, 5, 1)}}}, rng, 300);
}

TEST(AspectGraph2D, NonConvexPolygonAndHole) {
  std::mt19937_64 rng(3);
  check_scene({{{{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}}},
               {{box(5, 0, 9, 4), box(6, 1, 8, 3)}}},
              rng, 300);
}

TEST(AspectGraph2D, RandomGridScenes) {
  std::mt19937_64 rng(4);
  int tested = 0;
  for (std::uint64_t seed = 2000; tested < 4 && seed < 2300; ++seed) {
    auto polys = oracle2d::random_grid_scene(seed, 2);
    const auto s = try_scene(polys);
    if (!s || s->num_vertices() > 24 || s->num_objects < 2) continue;
    ++tested;
    SCOPED_TRACE("seed " + std::to_string(seed));
    check_scene(polys, rng, 150);
  }
  EXPECT_GE(tested, 3);
}

// Coordinates whose squares or cubes overflow doubles (the interval approximations CGAL's lazy kernel made of
// the arrangement's line intersections overflowed there: aspect2d crashed from ~1e102 on). Exact inputs are
// handled exactly: the oracle agrees, and scaling a scene by a power of two (exact) changes nothing but the
// coordinates.
TEST(AspectGraph2D, HugeCoordinates) {
  std::mt19937_64 rng(5);
  const double k = std::ldexp(1.0, 500);  // about 3.3e150
  check_scene({{{box(0, 0, k, k)}}, {{box(3 * k, 0.5 * k, 4 * k, 2 * k)}}}, rng, 200);
  check_scene({{{{{0, 0}, {1e308, 0}, {0, 1}}}}, {{box(-4, 2, -2, 3)}}}, rng, 200);
  // Scaling by 2^k: the frame (margin 1/4 of 8 = 2, integer corners) scales too, so the partition must be
  // the same up to the scale, region by region.
  for (int e : {400, 1000}) {
    const double f = std::ldexp(1.0, e);
    const Scene2D small = make_scene2d(to_input({{{box(0, 0, 2, 2)}}, {{box(4, 1, 8, 8)}}, {{box(0, 5, 2, 6)}}}));
    const Scene2D big =
        make_scene2d(to_input({{{box(0, 0, 2 * f, 2 * f)}}, {{box(4 * f, f, 8 * f, 8 * f)}}, {{box(0, 5 * f, 2 * f, 6 * f)}}}));
    const AspectGraph2D a = aspect_graph(small, 0.25), b = aspect_graph(big, 0.25);
    ASSERT_EQ(a.faces.size(), b.faces.size()) << e;
    ASSERT_EQ(a.regions.size(), b.regions.size()) << e;
    EXPECT_EQ(a.adjacency, b.adjacency) << e;
    for (std::size_t r = 0; r < a.regions.size(); ++r) EXPECT_EQ(a.regions[r].aspect, b.regions[r].aspect) << e;
    const Exact scale(f);
    for (std::size_t i = 0; i < a.faces.size(); ++i) {
      ASSERT_EQ(a.faces[i].outer.size(), b.faces[i].outer.size());
      for (std::size_t j = 0; j < a.faces[i].outer.size(); ++j) {
        EXPECT_EQ(a.faces[i].outer[j].x * scale, b.faces[i].outer[j].x);
        EXPECT_EQ(a.faces[i].outer[j].y * scale, b.faces[i].outer[j].y);
      }
    }
  }
}
