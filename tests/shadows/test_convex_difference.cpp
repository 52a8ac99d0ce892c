// convex_difference and cell_union_boundary against CGAL's regularised Boolean set operations (the oracle:
// Polygon_set_2 join and difference over lazy exact rationals, the code the backprojection used before).
// Equality of point sets is checked exactly: the same exact area, the same boundary as a set of maximal
// directed segments (region on the left; recomputed here from both outputs by an independent merge), and
// the same membership at sample points. Inputs: random convex polygons (hulls of random points) on a small
// integer grid (shared edges, collinear edges, touching vertices: degenerate) and with random rational
// coordinates (general position), with fixed seeds; hand-made pinches; the canonical form's rules.
#include "shadows/convex_difference.hpp"
#include "shadows/exact_planar_kernel.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

namespace exactvis::shadows {
namespace {

using Polygon2 = CGAL::Polygon_2<PlanarKernel>;
using PolygonWithHoles2 = CGAL::Polygon_with_holes_2<PlanarKernel>;
using PolygonSet2 = CGAL::Polygon_set_2<PlanarKernel>;
using Loop = std::vector<ChartPoint>;

Exact cross3(const ChartPoint& o, const ChartPoint& a, const ChartPoint& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Convex hull (monotone chain, exact), counterclockwise, no collinear vertices.
Loop hull(std::vector<ChartPoint> pts) {
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return {};
  Loop h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross3(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross3(h[k - 2], h[k - 1], pts[i - 1]) <= 0) --k;
    h[k++] = pts[i - 1];
  }
  h.resize(k - 1);
  if (h.size() < 3) return {};
  return h;
}

Polygon2 cgal_polygon(const Loop& l) {
  Polygon2 p;
  for (const auto& v : l) p.push_back(to_planar(v));
  return p;
}

Loop from_cgal(const Polygon2& p) {
  Loop l;
  for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it) l.push_back(from_planar(*it));
  return l;
}

struct Oracle {
  std::vector<Loop> loops;  // outer loops counterclockwise, holes clockwise: the region on the left
  Exact area = 0;
  PolygonSet2 set;
};

Oracle cgal_difference(const Loop& base, const std::vector<Loop>& subs) {
  Oracle o;
  o.set = PolygonSet2(cgal_polygon(base));
  if (!subs.empty()) {
    std::vector<Polygon2> hs;
    for (const auto& s : subs) hs.push_back(cgal_polygon(s));
    PolygonSet2 hidden;
    hidden.join(hs.begin(), hs.end());
    o.set.difference(hidden);
  }
  std::vector<PolygonWithHoles2> pwhs;
  o.set.polygons_with_holes(std::back_inserter(pwhs));
  for (const auto& pwh : pwhs) {
    o.loops.push_back(from_cgal(pwh.outer_boundary()));
    o.area += from_planar_ft(pwh.outer_boundary().area());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) {
      o.loops.push_back(from_cgal(*h));
      o.area += from_planar_ft(h->area());
    }
  }
  return o;
}

// The boundary as maximal directed segments: per (normalised line, direction) the union of the edges'
// parameter intervals. Independent of cell_union_boundary's code.
using Segments = std::map<std::pair<std::array<Exact, 3>, int>, std::vector<std::pair<Exact, Exact>>>;
Segments maximal_segments(const std::vector<Loop>& loops) {
  Segments raw;
  for (const auto& l : loops)
    for (std::size_t i = 0; i < l.size(); ++i) {
      const ChartPoint& p = l[i];
      const ChartPoint& q = l[(i + 1) % l.size()];
      const Exact dx = q[0] - p[0], dy = q[1] - p[1];
      // Line: dy x - dx y = dy px - dx py, normalised by its first nonzero coefficient.
      const Exact n = dy != 0 ? dy : -dx;
      const std::array<Exact, 3> key{dy / n, -dx / n, (dy * p[0] - dx * p[1]) / n};
      const bool by_x = dx != 0;
      const Exact tp = by_x ? p[0] : p[1], tq = by_x ? q[0] : q[1];
      raw[{key, tp < tq ? 1 : -1}].push_back({std::min(tp, tq), std::max(tp, tq)});
    }
  for (auto& [k, v] : raw) {
    std::sort(v.begin(), v.end());
    std::vector<std::pair<Exact, Exact>> m;
    for (const auto& x : v) {
      if (!m.empty() && x.first <= m.back().second) {
        m.back().second = std::max(m.back().second, x.second);
      } else {
        m.push_back(x);
      }
    }
    v = std::move(m);
  }
  return raw;
}

std::vector<Loop> loops_of(const ChartRegion& r) {
  std::vector<Loop> out;
  for (const auto& p : r.pieces) {
    out.push_back(p.outer);
    for (const auto& h : p.holes) out.push_back(h);
  }
  return out;
}

// Membership by crossing parity over one piece's loops; nullopt on a boundary.
std::optional<bool> in_piece(const ChartPolygonWithHoles& pc, const ChartPoint& q) {
  int crossings = 0;
  auto loop = [&](const Loop& l) {
    for (std::size_t k = 0; k < l.size(); ++k) {
      const ChartPoint& a = l[k];
      const ChartPoint& b = l[(k + 1) % l.size()];
      if (cross3(a, b, q) == 0 && std::min(a[0], b[0]) <= q[0] && q[0] <= std::max(a[0], b[0]) &&
          std::min(a[1], b[1]) <= q[1] && q[1] <= std::max(a[1], b[1]))
        return false;
      if ((a[1] > q[1]) != (b[1] > q[1]) && a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]) > q[0]) ++crossings;
    }
    return true;
  };
  if (!loop(pc.outer)) return std::nullopt;
  for (const auto& h : pc.holes)
    if (!loop(h)) return std::nullopt;
  return crossings % 2 == 1;
}

// Every property of the canonical form, and equality with the oracle.
void expect_matches_oracle(const Loop& base, const std::vector<Loop>& subs, std::mt19937_64& rng, const std::string& name) {
  const ConvexDifference mine = convex_difference(base, subs);
  const Oracle o = cgal_difference(base, subs);
  ASSERT_EQ(mine.region.area, o.area) << name;
  EXPECT_EQ(maximal_segments(loops_of(mine.region)), maximal_segments(o.loops)) << name;
  for (std::size_t i = 0; i < mine.region.pieces.size(); ++i) {
    const auto& pc = mine.region.pieces[i];
    auto check_loop = [&](const Loop& l, bool outer) {
      ASSERT_GE(l.size(), 3u) << name;
      Exact a2 = 0;
      for (std::size_t k = 0; k < l.size(); ++k) {
        const ChartPoint& p = l[k];
        const ChartPoint& q = l[(k + 1) % l.size()];
        const ChartPoint& r = l[(k + 2) % l.size()];
        a2 += p[0] * q[1] - p[1] * q[0];
        EXPECT_NE(p, q) << name;
        EXPECT_NE(cross3(p, q, r), 0) << name << ": collinear vertex";
        EXPECT_FALSE(l[k] < l[0]) << name << ": not starting at its smallest vertex";
      }
      EXPECT_EQ(a2 > 0, outer) << name;
    };
    check_loop(pc.outer, true);
    for (const auto& h : pc.holes) check_loop(h, false);
    if (i > 0) {
      const auto& prev = mine.region.pieces[i - 1].outer;
      EXPECT_TRUE(prev[0] < pc.outer[0] || (prev[0] == pc.outer[0] && prev[1] < pc.outer[1])) << name;
    }
  }
  // Membership at random points of the base's box: in exactly one piece iff in CGAL's set.
  Exact lo[2] = {base[0][0], base[0][1]}, hi[2] = {base[0][0], base[0][1]};
  for (const auto& v : base)
    for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], v[d]), hi[d] = std::max(hi[d], v[d]);
  std::uniform_int_distribution<int> w(0, 1 << 20);
  for (int k = 0; k < 200; ++k) {
    const ChartPoint q{lo[0] + (hi[0] - lo[0]) * Exact(w(rng), 1 << 20), lo[1] + (hi[1] - lo[1]) * Exact(w(rng), 1 << 20)};
    int inside = 0;
    bool boundary = false;
    for (const auto& pc : mine.region.pieces) {
      const auto in = in_piece(pc, q);
      if (!in) boundary = true;
      else inside += *in;
    }
    const auto side = o.set.oriented_side(to_planar(q));
    if (boundary || side == CGAL::ON_ORIENTED_BOUNDARY) continue;
    EXPECT_LE(inside, 1) << name;
    EXPECT_EQ(inside == 1, side == CGAL::ON_POSITIVE_SIDE) << name << " at " << q[0] << ", " << q[1];
  }
  // Canonical: the subtrahends in another order give the same loops.
  std::vector<Loop> shuffled = subs;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  const ConvexDifference again = convex_difference(base, shuffled);
  ASSERT_EQ(again.region.pieces.size(), mine.region.pieces.size()) << name;
  for (std::size_t i = 0; i < again.region.pieces.size(); ++i) {
    EXPECT_EQ(again.region.pieces[i].outer, mine.region.pieces[i].outer) << name;
    EXPECT_EQ(again.region.pieces[i].holes, mine.region.pieces[i].holes) << name;
  }
}

TEST(ConvexDifference, RandomGridPolygonsMatchCgal) {
  std::mt19937_64 rng(11);
  // Small polygons (hulls of points within 2 of a centre) on the grid: holes, pinches and shared edges.
  std::uniform_int_distribution<int> g(0, 12), off(-2, 2), cnt(3, 6), nsub(0, 12);
  const Loop base = normalized_convex_polygon({{Exact(0), Exact(0)}, {Exact(12), Exact(0)}, {Exact(0), Exact(12)}});
  int with_holes = 0, several = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<Loop> subs;
    const int n = nsub(rng);
    for (int s = 0; s < n; ++s) {
      std::vector<ChartPoint> pts;
      const int m = cnt(rng);
      const int cx = g(rng), cy = g(rng);
      for (int k = 0; k < m; ++k) pts.push_back({Exact(cx + off(rng)), Exact(cy + off(rng))});
      Loop h = hull(pts);
      if (!h.empty()) subs.push_back(std::move(h));
    }
    expect_matches_oracle(base, subs, rng, "grid trial " + std::to_string(trial));
    const ConvexDifference d = convex_difference(base, subs);
    for (const auto& p : d.region.pieces) with_holes += !p.holes.empty();
    several += d.region.pieces.size() > 1;
  }
  EXPECT_GT(with_holes, 5);  // the inputs exercise holes and several pieces
  EXPECT_GT(several, 20);
}

TEST(ConvexDifference, RandomRationalPolygonsMatchCgal) {
  std::mt19937_64 rng(12);
  std::uniform_int_distribution<int> g(-300000, 1300000), nsub(1, 12);
  const Loop base = normalized_convex_polygon({{Exact(0), Exact(0)}, {Exact(1), Exact(1, 3)}, {Exact(1, 5), Exact(1)}});
  for (int trial = 0; trial < 150; ++trial) {
    std::vector<Loop> subs;
    const int n = nsub(rng);
    for (int s = 0; s < n; ++s) {
      std::vector<ChartPoint> pts;
      for (int k = 0; k < 4; ++k) pts.push_back({Exact(g(rng), 1000003), Exact(g(rng), 999983)});
      Loop h = hull(pts);
      if (!h.empty()) subs.push_back(std::move(h));
    }
    expect_matches_oracle(base, subs, rng, "rational trial " + std::to_string(trial));
  }
}

// Hand-made pinches: two holes touching at a vertex (one hole loop through it twice), a hole touching the
// outer boundary (one outer loop), two pieces touching at a vertex (two outer loops), an island inside a
// hole (nesting), a subtrahend sharing an edge with the base.
TEST(ConvexDifference, PinchesAndNestingFollowTheFaceRule) {
  std::mt19937_64 rng(13);
  auto sq = [](int x0, int y0, int x1, int y1) {
    return Loop{{Exact(x0), Exact(y0)}, {Exact(x1), Exact(y0)}, {Exact(x1), Exact(y1)}, {Exact(x0), Exact(y1)}};
  };
  const Loop big = sq(0, 0, 12, 12);
  {
    const std::vector<Loop> subs{sq(2, 2, 4, 4), sq(4, 4, 6, 6)};
    expect_matches_oracle(big, subs, rng, "holes touching");
    const ConvexDifference d = convex_difference(big, subs);
    ASSERT_EQ(d.region.pieces.size(), 1u);
    ASSERT_EQ(d.region.pieces[0].holes.size(), 1u);
    EXPECT_EQ(d.region.pieces[0].holes[0].size(), 8u);  // through (4, 4) twice
  }
  {
    const std::vector<Loop> subs{Loop{{Exact(6), Exact(0)}, {Exact(8), Exact(4)}, {Exact(4), Exact(4)}}};
    expect_matches_oracle(big, subs, rng, "hole touching the outer boundary");
    const ConvexDifference d = convex_difference(big, subs);
    ASSERT_EQ(d.region.pieces.size(), 1u);
    EXPECT_TRUE(d.region.pieces[0].holes.empty());
    EXPECT_EQ(d.region.pieces[0].outer.size(), 8u);  // through (6, 0) twice
  }
  {
    const std::vector<Loop> subs{sq(0, 6, 6, 12), sq(6, 0, 12, 6)};
    expect_matches_oracle(big, subs, rng, "pieces touching");
    EXPECT_EQ(convex_difference(big, subs).region.pieces.size(), 2u);
  }
  {
    // A ring of four rectangles around the island [5, 7]^2, inside the hole [3, 9]^2 minus the island.
    const std::vector<Loop> subs{sq(3, 3, 9, 5), sq(3, 7, 9, 9), sq(3, 5, 5, 7), sq(7, 5, 9, 7)};
    expect_matches_oracle(big, subs, rng, "island in a hole");
    const ConvexDifference d = convex_difference(big, subs);
    ASSERT_EQ(d.region.pieces.size(), 2u);
    EXPECT_EQ(d.region.pieces[0].holes.size(), 1u);  // the big square (first vertex (0, 0)) has the hole
    EXPECT_TRUE(d.region.pieces[1].holes.empty());
    EXPECT_EQ(d.region.area, Exact(144 - 36 + 4));
  }
  {
    const std::vector<Loop> subs{sq(0, 0, 12, 3), sq(0, 0, 12, 12)};
    expect_matches_oracle(big, subs, rng, "everything hidden");
    EXPECT_TRUE(convex_difference(big, subs).region.pieces.empty());
  }
}

TEST(ConvexDifference, NormalizedPolygonDropsRepeatsAndCollinearVertices) {
  const Loop p = normalized_convex_polygon({{Exact(0), Exact(0)}, {Exact(0), Exact(2)}, {Exact(0), Exact(2)},
                                            {Exact(2), Exact(2)}, {Exact(2), Exact(1)}, {Exact(2), Exact(0)},
                                            {Exact(1), Exact(0)}, {Exact(0), Exact(0)}});
  ASSERT_EQ(p.size(), 4u);
  EXPECT_GT(cross3(p[0], p[1], p[2]), 0);  // counterclockwise
  EXPECT_TRUE(normalized_convex_polygon({{Exact(0), Exact(0)}, {Exact(1), Exact(1)}, {Exact(3), Exact(3)}}).empty());
}

}  // namespace
}  // namespace exactvis::shadows
