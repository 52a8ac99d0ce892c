// The output-sensitive rotational sweep (skeleton/rotational_visibility_2d) against two references that
// share none of its code: the per-vertex angular sweep (the previous construction) and exact brute
// forces with gmpxx rationals (strict pairs here, bitangents with their maximal free segments in
// tests/oracles). Random and degenerate scenes with fixed seeds: integer grids (collinear vertices across
// objects, parallel edges), flat vertices, holes, non-convex polygons, concurrent bitangents, frames.
#include "tests/planar/scene2d_test_util.hpp"
#include "skeleton/rotational_visibility_2d.hpp"
#include "skeleton/visibility_complex_2d.hpp"
#include "skeleton/visibility_polygon_2d.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <tuple>

using namespace exactvis;
using namespace exactvis::test2d;

namespace {

using oracle2d::Pt;

// Exact brute force: the open segment (p, q) meets no closed edge and its midpoint is outside the objects.
bool brute_strict(const std::vector<oracle2d::Polygon>& polys, const Pt& p, const Pt& q) {
  const mpq_class dx = q.x - p.x, dy = q.y - p.y;
  for (const auto& poly : polys)
    for (const auto& ring : poly.rings)
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const auto &ra = ring[i], &rb = ring[(i + 1) % ring.size()];
        // bounding boxes apart (exact: input coordinates are doubles, compared as rationals)
        if (std::max(mpq_class(ra[0]), mpq_class(rb[0])) < std::min(p.x, q.x) ||
            std::min(mpq_class(ra[0]), mpq_class(rb[0])) > std::max(p.x, q.x) ||
            std::max(mpq_class(ra[1]), mpq_class(rb[1])) < std::min(p.y, q.y) ||
            std::min(mpq_class(ra[1]), mpq_class(rb[1])) > std::max(p.y, q.y))
          continue;
        const Pt a{ra[0], ra[1]}, b{rb[0], rb[1]};
        const mpq_class ex = b.x - a.x, ey = b.y - a.y;
        const mpq_class den = dx * ey - dy * ex;
        if (den != 0) {  // t on (p, q), s on [a, b]
          const mpq_class t = ((a.x - p.x) * ey - (a.y - p.y) * ex) / den;
          const mpq_class s = ((a.x - p.x) * dy - (a.y - p.y) * dx) / den;
          if (t > 0 && t < 1 && s >= 0 && s <= 1) return false;
          continue;
        }
        if ((a.x - p.x) * dy - (a.y - p.y) * dx != 0) continue;  // parallel, not collinear
        const mpq_class len = dx * dx + dy * dy;
        const mpq_class ta = ((a.x - p.x) * dx + (a.y - p.y) * dy) / len;
        const mpq_class tb = ((b.x - p.x) * dx + (b.y - p.y) * dy) / len;
        if (std::max(ta, tb) > 0 && std::min(ta, tb) < 1) return false;
      }
  const Pt mid{(p.x + q.x) / 2, (p.y + q.y) / 2};
  return !oracle2d::inside_object(polys, mid);
}

std::set<std::pair<int, int>> brute_pairs(const std::vector<oracle2d::Polygon>& polys, const Scene2D& s) {
  std::set<std::pair<int, int>> out;
  for (int p = 0; p < s.num_vertices(); ++p)
    for (int q = p + 1; q < s.num_vertices(); ++q)
      if (brute_strict(polys, to_pt(s.points[p]), to_pt(s.points[q]))) out.emplace(p, q);
  return out;
}

std::string describe(const Scene2D& s, const Bitangent2D& b) {
  auto pt = [](const Point2& p) { const Pt q = to_pt(p); return "(" + q.x.get_str() + "," + q.y.get_str() + ")"; };
  auto end = [&](const SegmentEnd2D& e) {
    return e.kind == SegmentEnd2D::Infinity ? std::string("inf")
                                            : std::to_string(e.kind) + ":" + std::to_string(e.id) + pt(e.point);
  };
  return std::to_string(b.a) + "-" + std::to_string(b.b) + " " + b.kind() + " " + end(b.end_a) + " " + end(b.end_b);
}

// New sweep == per-vertex sweep: pairs, bitangents, kinds, both ends.
void expect_same_as_per_vertex_sweep(const Scene2D& s, const VisibilityGraph2D& fast) {
  const auto ref = visibility_graph(s, nullptr, VisibilityGraphMethod::PerVertexSweep);
  EXPECT_EQ(fast.strict_pairs, ref.strict_pairs);
  ASSERT_EQ(fast.bitangents.size(), ref.bitangents.size());
  for (std::size_t i = 0; i < fast.bitangents.size(); ++i)
    EXPECT_EQ(describe(s, fast.bitangents[i]), describe(s, ref.bitangents[i]));
}

// New sweep == per-vertex sweep, and == brute force (pairs, and bitangents with their free segments when
// `bitangent_oracle`).
void expect_same(const std::vector<oracle2d::Polygon>& polys, const Scene2D& s, bool bitangent_oracle) {
  const auto fast = visibility_graph(s, nullptr, VisibilityGraphMethod::RotationalSweep);
  expect_same_as_per_vertex_sweep(s, fast);
  const std::set<std::pair<int, int>> mine(fast.strict_pairs.begin(), fast.strict_pairs.end());
  EXPECT_EQ(mine, brute_pairs(polys, s));
  if (!bitangent_oracle) return;
  std::set<std::string> expected, got;
  for (const auto& b : oracle2d::brute_force_bitangents(polys))
    expected.insert(b.a.x.get_str() + "," + b.a.y.get_str() + "|" + b.b.x.get_str() + "," + b.b.y.get_str() + "|" +
                    b.kind + "|" + (b.end_a_infinite ? "inf" : b.end_a.x.get_str() + "," + b.end_a.y.get_str()) +
                    "|" + (b.end_b_infinite ? "inf" : b.end_b.x.get_str() + "," + b.end_b.y.get_str()));
  for (const auto& b : fast.bitangents) {
    Pt a = to_pt(s.points[b.a]), c = to_pt(s.points[b.b]);
    std::string kind = b.kind();
    SegmentEnd2D ea = b.end_a, eb = b.end_b;
    if (c < a) {
      std::swap(a, c);
      std::swap(ea, eb);
      auto flip = [](char x) { return x == 'L' ? 'R' : 'L'; };
      kind = {flip(kind[1]), flip(kind[0])};
    }
    auto end = [](const SegmentEnd2D& e) {
      if (e.kind == SegmentEnd2D::Infinity) return std::string("inf");
      const Pt p = to_pt(e.point);
      return p.x.get_str() + "," + p.y.get_str();
    };
    got.insert(a.x.get_str() + "," + a.y.get_str() + "|" + c.x.get_str() + "," + c.y.get_str() + "|" + kind + "|" +
               end(ea) + "|" + end(eb));
  }
  EXPECT_EQ(got, expected);
}

oracle2d::Ring box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

}  // namespace

TEST(RotationalVisibility2D, HandPickedDegenerateScenes) {
  const std::vector<std::vector<oracle2d::Polygon>> scenes{
      {{{box(0, 0, 1, 1)}}, {{box(3, 0.5, 4, 2)}}},
      {{{box(0, 0, 1, 1)}}, {{box(2, 0, 3, 1)}}, {{box(4, 0, 5, 1)}}},  // collinear edges
      {{{box(2, 1, 3, 2)}}, {{box(-3, -2, -2, -1)}}, {{box(-2, 2, -1, 3)}}, {{box(1, -3, 2, -2)}},
       {{box(0.5, 2, 1, 3)}}, {{box(-1, -3, -0.5, -2)}}},  // three bitangents through the origin
      {{{{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}}}},  // U shape
      {{{box(0, 0, 10, 10), box(2, 2, 8, 8)}}, {{box(4, 4, 5, 5)}}, {{box(6, 4, 7, 5)}}},  // hole, islands
      {{{{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}}}, {{box(3, 0, 4, 2)}}},  // flat
      {{{box(0, 0, 1, 1)}}},  // one object: only its own edges
      {{{{{0, 0}, {1, 0}, {0, 1}}}}, {{{{1, 1}, {2, 1}, {1, 2}}}}, {{{{2, 2}, {3, 2}, {2, 3}}}}},  // diagonal chain
  };
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    SCOPED_TRACE("scene " + std::to_string(i));
    const Scene2D s = make_scene2d(to_input(scenes[i]));
    expect_same(scenes[i], s, true);
  }
}

TEST(RotationalVisibility2D, RandomGridScenesMatchPerVertexSweepAndBruteForce) {
  int tested = 0;
  std::size_t pairs = 0;
  for (std::uint64_t seed = 1; tested < 60 && seed < 600; ++seed) {
    const auto polys = oracle2d::random_grid_scene(seed, seed % 3 == 0 ? 3 : 2, seed % 4 == 0);
    const auto s = try_scene(polys);
    if (!s || s->num_vertices() > 70) continue;
    ++tested;
    SCOPED_TRACE("grid seed " + std::to_string(seed));
    expect_same(polys, *s, true);
    pairs += visibility_graph(*s).strict_pairs.size();
  }
  EXPECT_GE(tested, 50);
  EXPECT_GE(pairs, 3000u);  // not vacuous
}

TEST(RotationalVisibility2D, RandomBoxScenesWithFlatVerticesHolesAndCollinearEdges) {
  std::size_t pairs = 0;
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    const auto polys = random_box_scene(seed, 3 + seed % 6);
    const auto s = try_scene(polys);
    ASSERT_TRUE(s.has_value()) << "seed " << seed;
    SCOPED_TRACE("box seed " + std::to_string(seed));
    expect_same(polys, *s, seed <= 60);
    pairs += visibility_graph(*s).strict_pairs.size();
  }
  EXPECT_GE(pairs, 5000u);
}

TEST(RotationalVisibility2D, RandomTriangleScenesOnASmallGrid) {
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    const auto polys = random_triangle_scene(seed, 2 + seed % 5);
    const auto s = try_scene(polys);
    ASSERT_TRUE(s.has_value());
    SCOPED_TRACE("triangle seed " + std::to_string(seed));
    expect_same(polys, *s, true);
  }
}

TEST(RotationalVisibility2D, FramedScenesMatchPerVertexSweep) {
  // with a frame (no ray reaches infinity); the same scenes without one are in the tests above
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto polys = seed % 2 ? random_box_scene(seed, 5) : oracle2d::random_grid_scene(seed, 2);
    const auto s = try_scene(polys);
    if (!s) continue;
    const Scene2D framed = with_frame(*s, 0.25);
    SCOPED_TRACE("framed seed " + std::to_string(seed));
    expect_same_as_per_vertex_sweep(framed, visibility_graph(framed, nullptr, VisibilityGraphMethod::RotationalSweep));
  }
}

TEST(RotationalVisibility2D, ComplexIsTheSameWithEitherConstruction) {
  for (std::uint64_t seed = 3; seed <= 60; ++seed) {
    const auto s = try_scene(seed % 2 ? oracle2d::random_grid_scene(seed, 2) : random_box_scene(seed, 5));
    if (!s) continue;
    SCOPED_TRACE("seed " + std::to_string(seed));
    const auto a = visibility_complex(*s, nullptr, VisibilityGraphMethod::RotationalSweep);
    const auto b = visibility_complex(*s, nullptr, VisibilityGraphMethod::PerVertexSweep);
    EXPECT_EQ(a.edges.size(), b.edges.size());
    EXPECT_EQ(a.faces.size(), b.faces.size());
    EXPECT_EQ(a.gluing_consistent, b.gluing_consistent);
    for (std::size_t i = 0; i < std::min(a.vertices.size(), b.vertices.size()); ++i) {
      EXPECT_EQ(a.vertices[i].edges, b.vertices[i].edges);
      EXPECT_EQ(a.vertices[i].faces, b.vertices[i].faces);
    }
    // end objects of the edges: one sweep with ray queries vs two O(n) ray shots per edge
    for (std::size_t j = 0; j < std::min(a.edges.size(), b.edges.size()); ++j)
      EXPECT_EQ(a.edges[j].end_objects, b.edges[j].end_objects) << "edge " << j;
  }
}

TEST(RotationalVisibility2D, RayQueriesMatchRayShots) {
  // rays from every vertex towards every other vertex and towards points between them, on degenerate
  // grid scenes: the sweep's first contact equals first_contact's (vertex or edge, same id)
  std::size_t checked = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto polys = seed % 2 ? random_box_scene(seed, 4) : random_triangle_scene(seed, 4);
    const auto s = try_scene(polys);
    if (!s) continue;
    const auto& P = s->points;
    std::vector<Point2> targets;
    targets.reserve(P.size() * P.size() * 2);
    std::vector<RayQuery2D> qs;
    for (int v = 0; v < s->num_vertices(); ++v)
      for (int u = 0; u < s->num_vertices(); ++u) {
        if (u == v) continue;
        for (int half = 0; half < 2; ++half) {
          // towards u, and towards the midpoint of u and next(u)
          const Point2& t = half ? Point2((P[u].x + P[s->next[u]].x) / 2, (P[u].y + P[s->next[u]].y) / 2) : P[u];
          if (!in_free_wedge(*s, v, P[v], t)) continue;
          targets.push_back(t);
          qs.push_back({v, &P[v], &targets.back()});
        }
      }
    const auto got = rotational_first_contacts(*s, qs);
    for (std::size_t i = 0; i < qs.size(); ++i) {
      const SegmentEnd2D want = first_contact(*s, qs[i].vertex, *qs[i].from, *qs[i].to);
      ASSERT_EQ(got[i].kind, want.kind) << "seed " << seed << " query " << i;
      ASSERT_EQ(got[i].id, want.id) << "seed " << seed << " query " << i;
      ASSERT_EQ(got[i].object, want.object);
      ++checked;
    }
  }
  EXPECT_GE(checked, 5000u);
}

TEST(RotationalVisibility2D, LargerScenesInGeneralPositionMatchPerVertexSweep) {
  // jittered convex polygons with double coordinates (no exact degeneracy), up to a few hundred vertices
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<PolygonInput2D> polys;
    const int m = 3 + static_cast<int>(seed);
    for (int i = 0; i < m * m; ++i) {
      PolygonInput2D p;
      p.rings.emplace_back();
      const int k = 3 + static_cast<int>(u(rng) * 6);
      const double cx = 10.0 * (i % m) + u(rng), cy = 10.0 * (i / m) + u(rng), r = 2.0 + 2.5 * u(rng);
      for (int t = 0; t < k; ++t) {
        const double a = 6.283185307179586 * (t + 0.8 * u(rng)) / k;
        p.rings[0].emplace_back(cx + r * std::cos(a), cy + r * std::sin(a));
      }
      polys.push_back(std::move(p));
    }
    const Scene2D s = make_scene2d(polys);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", n = " + std::to_string(s.num_vertices()));
    expect_same_as_per_vertex_sweep(s, visibility_graph(s, nullptr, VisibilityGraphMethod::RotationalSweep));
  }
}

TEST(RotationalVisibility2D, BatchPolygonsOnDegenerateScenesEqualSingleQueries) {
  // boxes with flat vertices and holes, triangles on a small grid, and query points on a quarter-integer
  // grid: many rays through several vertices, through (1, 0) and (-1, 0) directions (the half-turn seams)
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 80; ++seed) {
    const auto polys = seed % 2 ? random_box_scene(seed, 3 + seed % 6) : random_triangle_scene(seed, 3 + seed % 4);
    const auto s = try_scene(polys);
    ASSERT_TRUE(s.has_value());
    const Scene2D framed = with_frame(*s, 0.2);
    std::vector<Point2> qs;
    std::mt19937_64 rng(seed);
    for (int t = 0; t < 400 && qs.size() < 40; ++t) {
      const Point2 q(std::uniform_int_distribution<int>(-8, 80)(rng) / 4.0,
                     std::uniform_int_distribution<int>(-8, 80)(rng) / 4.0);
      if (on_boundary(framed, q) || inside_obstacle(framed, q)) continue;
      qs.push_back(q);
    }
    const auto batch = visibility_polygons(framed, qs);
    for (std::size_t i = 0; i < qs.size(); ++i) {
      ASSERT_TRUE(batch[i].vertices == visibility_polygon(framed, qs[i]).vertices)
          << "seed " << seed << " q " << qs[i].ax << "," << qs[i].ay;
      ++checked;
    }
  }
  EXPECT_GE(checked, 2500);
}
