// The visibility polygon answered by a walk in the visibility complex (skeleton/complex_walk_2d) against
// three references: the angular sweep visibility_polygon (a different algorithm: the same vertex sequence,
// exactly, from the same start; besides the Point2 predicates it shares with the walk only the edge order
// predicate edge_closer of skeleton/angular_sweep_2d), CGAL's Triangular_expansion_visibility_2 (the same
// region, exactly, on a subset) and the all-rational brute force of tests/oracles (the visible edges, on a
// subset). Fixed seeds; random convex, non-convex (star) and holed scenes;
// integer-grid scenes with collinear vertices across objects, parallel edges, flat vertices, concurrent
// bitangents; the same under rational rotations, scalings and translations; query points chosen to be degenerate (on
// bitangent lines, on lines through two vertices, along an edge or through a frame corner, at direction
// (1,0) / (-1,0) / (0,1) / (0,-1) from a vertex, at crossings of such lines, rational points on grid lines).
// Also: bad input is rejected, and the walk's counters show it tests only the candidates of the faces it
// visits.
#include "cgal_visibility_test_util.hpp"
#include "skeleton/complex_walk_2d.hpp"
#include "skeleton/visibility_complex_2d.hpp"
#include "skeleton/visibility_polygon_2d.hpp"

#include <CGAL/Triangular_expansion_visibility_2.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>

using namespace exactvis;
using namespace exactvis::test2d;

namespace {

using oracle2d::Pt;
using Tev = CGAL::Triangular_expansion_visibility_2<CgalArr, CGAL::Tag_true>;

// A scene with its frame, complex and walk index. The index points into `scene` and `complex`: built in
// place, never copied or moved.
struct WalkScene {
  std::string name;  // how to rebuild it (generator and seed), for failure messages
  Scene2D scene, framed;
  VisibilityComplex2D complex;
  ComplexWalkIndex2D index;
  std::vector<oracle2d::Polygon> oracle;  // the objects and the frame, for the brute-force oracle
  WalkScene(std::string n, const Scene2D& s, double margin, const std::vector<oracle2d::Polygon>& polys = {})
      : name(std::move(n)), scene(s), framed(with_frame(scene, margin)), complex(visibility_complex(scene)),
        index(complex_walk_index(scene, complex)), oracle(polys) {
    oracle.push_back(frame_polygon(framed));
  }
  WalkScene(const WalkScene&) = delete;
  WalkScene& operator=(const WalkScene&) = delete;
};

std::unique_ptr<WalkScene> walk_scene(const std::string& name, const std::vector<oracle2d::Polygon>& polys,
                                      double margin = 0.25) {
  const auto s = try_scene(polys);
  if (!s) return nullptr;
  return std::make_unique<WalkScene>(name, *s, margin, polys);
}

std::string str(const Point2& p) {
  const Pt q = to_pt(p);
  std::string s = "(";
  return s.append(q.x.get_str()).append(",").append(q.y.get_str()).append(")");
}

std::string str(const VisibilityPolygon2D& poly) {
  std::string s = std::to_string(poly.vertices.size()) + " vertices: ";
  for (const Point2& p : poly.vertices) s += str(p) + " ";
  return s;
}

std::string str(const Scene2D& s) {
  std::string out;
  for (const Ring2D& r : s.rings) {
    if (r.object == s.num_objects) continue;  // the frame
    out += "[object ";
    out += std::to_string(r.object);
    out += r.hole ? " hole:" : ":";
    for (int i = 0; i < r.size; ++i) out.append(" ").append(str(s.points[r.first + i]));
    out += "] ";
  }
  return out;
}

bool is_free(const WalkScene& w, const Point2& q) { return !on_boundary(w.framed, q) && !inside_obstacle(w.framed, q); }

// Counts comparisons and failures; prints the first few failures in full (scene, q, both outputs).
struct Tally {
  int checked = 0, failed = 0, cgal_checked = 0, brute_checked = 0;
  void fail(const std::string& message) {
    if (++failed <= 4) ADD_FAILURE() << message;
  }
};

// One query: the walk equals the angular sweep vertex for vertex; every other query also asks the walk for
// the visible edges, which must equal visible_edges (from the sweep).
void check_walk(const WalkScene& w, const Point2& q, const std::string& kind, Tally& tally,
                ComplexWalkStats2D* stats = nullptr, VisibilityPolygon2D* out = nullptr) {
  const bool with_edges = ++tally.checked % 2 == 0;
  const VisibilityPolygon2D want = visibility_polygon(w.framed, q);
  const std::string where = w.name + ", q " + kind + " " + str(q) + " (" + std::to_string(q.ax) + ", " +
                            std::to_string(q.ay) + ")";
  VisibilityPolygon2D got;
  std::vector<int> edges;
  try {
    got = visibility_polygon_in_complex(w.index, w.framed, q, stats, with_edges ? &edges : nullptr);
  } catch (const std::exception& e) {
    tally.fail(where + ": the walk threw: " + e.what() + "\nsweep " + str(want) + "\nscene " + str(w.scene));
    return;
  }
  if (got.vertices != want.vertices) {
    tally.fail(where + ":\nwalk  " + str(got) + "\nsweep " + str(want) + "\nscene " + str(w.scene));
  } else if (with_edges && edges != visible_edges(w.framed, q)) {
    std::string mine, theirs;
    for (int e : edges) mine += std::to_string(e) + " ";
    for (int e : visible_edges(w.framed, q)) theirs += std::to_string(e) + " ";
    tally.fail(where + ": visible edges differ:\nwalk  " + mine + "\nsweep " + theirs + "\nscene " + str(w.scene));
  }
  if (out) *out = std::move(got);
}

// The walk's polygon and CGAL's regularized triangular expansion bound the same region.
void check_cgal(const WalkScene& w, const CgalArr& arr, const Tev& tev, const Point2& q,
                const VisibilityPolygon2D& walk, Tally& tally) {
  ++tally.cgal_checked;
  const CgalK::Point_2 cq = to_cgal(q);
  CGAL::Arr_naive_point_location<CgalArr> locator(arr);
  const auto located = locator.locate(cq);
  const CgalArr::Face_const_handle* face = boost::get<CgalArr::Face_const_handle>(&located);
  ASSERT_TRUE(face) << "query point not in a face";
  CgalArr out;
  const auto f = tev.compute_visibility(cq, *face, out);
  std::vector<Pt> mine;
  for (const Point2& p : walk.vertices) mine.push_back(to_pt(p));
  const auto a = normalize(mine), b = normalize(face_polygon(f));
  if (a != b) tally.fail(w.name + ", q " + str(q) + ":\nwalk " + show(a) + "\nTEV  " + show(b));
}

// The walk's visible edges, as endpoint pairs, equal the exact brute force of tests/oracles (any q, also
// with rational coordinates).
void check_brute(const WalkScene& w, const Point2& q, Tally& tally) {
  ++tally.brute_checked;
  std::vector<int> ids;
  visibility_polygon_in_complex(w.index, w.framed, q, nullptr, &ids);
  const auto mine = edge_endpoint_pairs(w.framed, ids);
  const auto expected = oracle2d::brute_force_visible_edges(w.oracle, to_pt(q));
  bool same = mine.size() == expected.size();
  for (std::size_t i = 0; same && i < mine.size(); ++i) same = mine[i][0] == expected[i][0] && mine[i][1] == expected[i][1];
  if (!same)
    tally.fail(w.name + ", q " + str(q) + ": visible edges " + std::to_string(mine.size()) + " vs brute force " +
               std::to_string(expected.size()) + "\nscene " + str(w.scene));
}

struct Query {
  Point2 q;
  std::string kind;
};

Exact ratio(int num, int den) { return Exact(num) / Exact(den); }

Point2 on_line(const Point2& a, const Point2& b, const Exact& t) {
  return Point2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
}

// Query points for a scene: `per_kind` free points of each kind (fewer if a kind rarely gives free points).
// Kinds: random doubles; quarter-integer grid points; rational points (thirds, sevenths) on integer grid
// lines; points on the line of a free bitangent (on the bitangent itself and beyond its ends); on the
// line through two scene vertices; on the line through a scene edge (outside the edge); at direction
// (1,0), (-1,0), (0,1), (0,-1) from a scene vertex; crossings of two lines through vertex pairs or
// bitangents, and of such a line with the horizontal line through a vertex; on the line through a frame
// corner and a scene vertex.
std::vector<Query> query_points(const WalkScene& w, std::uint64_t seed, int per_kind) {
  std::mt19937_64 rng(seed);
  const Ring2D& fr = w.framed.rings[w.framed.frame_ring];
  double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
  for (int i = 0; i < fr.size; ++i) {
    const Point2& p = w.framed.points[fr.first + i];
    lo_x = std::min(lo_x, p.ax), lo_y = std::min(lo_y, p.ay), hi_x = std::max(hi_x, p.ax), hi_y = std::max(hi_y, p.ay);
  }
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  auto real = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const int n = w.scene.num_vertices();
  const auto& P = w.scene.points;
  const auto& bit = w.complex.graph.bitangents;
  const int ts[][2] = {{1, 2}, {1, 3}, {-1, 4}, {-1, 2}, {5, 4}, {3, 2}, {2, 1}, {-2, 1}, {3, 1}, {-1, 1}};
  auto some_t = [&] {
    const auto& t = ts[uni(0, static_cast<int>(std::size(ts)) - 1)];
    return ratio(t[0], t[1]);
  };
  // a line through two scene vertices: a random bitangent or a random vertex pair
  auto some_line = [&](Point2& a, Point2& b) {
    if (!bit.empty() && uni(0, 1)) {
      const Bitangent2D& t = bit[uni(0, static_cast<int>(bit.size()) - 1)];
      a = P[t.a], b = P[t.b];
      return;
    }
    const int u = uni(0, n - 1);
    int v = uni(0, n - 2);
    if (v >= u) ++v;
    a = P[u], b = P[v];
  };
  std::vector<Query> out;
  for (int kind = 0; kind < 9; ++kind) {
    if (n < 2 && kind >= 3) break;
    if (kind == 3 && bit.empty()) continue;
    int found = 0;
    for (int tries = 0; found < per_kind && tries < 30 * per_kind; ++tries) {
      Point2 q;
      std::string name;
      switch (kind) {
        case 0:
          q = Point2(real(lo_x, hi_x), real(lo_y, hi_y)), name = "random";
          break;
        case 1:
          q = Point2(std::round(4 * real(lo_x, hi_x)) / 4, std::round(4 * real(lo_y, hi_y)) / 4), name = "grid";
          break;
        case 2: {  // x an integer and y a multiple of 1/3 or 1/7, or the other way round
          const int den = uni(0, 1) ? 3 : 7;
          const bool swap = uni(0, 1);
          const double lo = swap ? lo_x : lo_y, hi = swap ? hi_x : hi_y;
          const Exact grid(std::round(swap ? real(lo_y, hi_y) : real(lo_x, hi_x)));
          const Exact frac = ratio(uni(static_cast<int>(std::ceil(den * lo)), static_cast<int>(std::floor(den * hi))), den);
          q = swap ? Point2(frac, grid) : Point2(grid, frac);
          name = "rational-on-grid-line";
          break;
        }
        case 3: {
          const Bitangent2D& t = bit[uni(0, static_cast<int>(bit.size()) - 1)];
          q = on_line(P[t.a], P[t.b], some_t()), name = "on-bitangent-line";
          break;
        }
        case 4: {
          const int u = uni(0, n - 1);
          int v = uni(0, n - 2);
          if (v >= u) ++v;
          q = on_line(P[u], P[v], some_t()), name = "collinear-with-two-vertices";
          break;
        }
        case 5: {
          const int e = uni(0, n - 1);
          const Exact t = some_t();
          if (t >= 0 && t <= 1) continue;
          q = on_line(P[e], P[w.scene.next[e]], t), name = "on-edge-line";
          break;
        }
        case 6: {
          const Point2& v = P[uni(0, n - 1)];
          const Exact d = std::array<Exact, 6>{ratio(1, 4), ratio(1, 2), Exact(1), ratio(3, 2), Exact(3), ratio(1, 3)}[uni(0, 5)];
          const int dir = uni(0, 3);
          q = dir == 0 ? Point2(v.x + d, v.y) : dir == 1 ? Point2(v.x - d, v.y)
            : dir == 2 ? Point2(v.x, v.y + d) : Point2(v.x, v.y - d);
          name = dir < 2 ? "horizontal-from-vertex" : "vertical-from-vertex";
          break;
        }
        case 8: {  // towards a frame corner: the ray from q through the vertex reaches the corner
          const Point2& corner = w.framed.points[fr.first + uni(0, 3)];
          q = on_line(corner, P[uni(0, n - 1)], std::array<Exact, 5>{ratio(1, 2), ratio(1, 3), ratio(3, 4), ratio(5, 4), ratio(3, 2)}[uni(0, 4)]);
          name = "on-line-through-frame-corner";
          break;
        }
        default: {
          Point2 a, b, c, d;
          some_line(a, b);
          if (uni(0, 2) == 0) {
            c = P[uni(0, n - 1)], d = Point2(c.x + 1, c.y);  // horizontal through a vertex
          } else {
            some_line(c, d);
          }
          if (cross_sign(a, b, c, d) == Sign::Zero) continue;
          q = line_intersection(c, c, d, a, b), name = "crossing-of-two-vertex-lines";
          break;
        }
      }
      if (!is_free(w, q)) continue;
      out.push_back({q, name});
      ++found;
    }
  }
  return out;
}

// Checks all query points of a scene against the sweep, every `cgal_every`-th (0: none) against CGAL, and
// every `brute_every`-th (0: none) against the brute force.
void check_scene(const WalkScene& w, const std::vector<Query>& qs, Tally& tally, int cgal_every, int brute_every = 0) {
  std::unique_ptr<CgalArr> arr;
  std::unique_ptr<Tev> tev;
  if (cgal_every > 0) {
    arr = std::make_unique<CgalArr>();
    insert_scene_edges(w.framed, *arr);
    tev = std::make_unique<Tev>(*arr);
  }
  int all = 0;
  for (const Query& q : qs) {
    VisibilityPolygon2D walk;
    const int failed = tally.failed;
    check_walk(w, q.q, q.kind, tally, nullptr, &walk);
    if (tally.failed != failed) continue;
    if (tev && all % cgal_every == 0) check_cgal(w, *arr, *tev, q.q, walk, tally);
    if (brute_every > 0 && all % brute_every == 0) check_brute(w, q.q, tally);
    ++all;
  }
}

// Hand-made scenes, each with the points that make it degenerate.
struct HandScene {
  std::string name;
  std::vector<oracle2d::Polygon> polys;
  std::vector<Point2> points;
};

std::vector<HandScene> hand_scenes() {
  using R = oracle2d::Ring;
  return {
      {"one box", {{{box_ring(0, 0, 1, 1)}}}, {Point2(1.5, 0.0), Point2(-0.5, 1.0), Point2(0.5, 1.5), Point2(1.5, 1.5)}},
      {"one convex hexagon",
       {{{R{{0, 0}, {2, -1}, {4, 0}, {4, 2}, {2, 3}, {0, 2}}}}},
       {Point2(6.0, 3.0), Point2(-2.0, -2.0), Point2(2.0, -3.0), Point2(5.0, 1.0), Point2(6.0, 4.0)}},
      {"one comb (non-convex, 8 collinear tips)",
       {{{R{{0, 0}, {7, 0}, {7, 4}, {6, 4}, {6, 1}, {5, 1}, {5, 4}, {4, 4}, {4, 1}, {3, 1}, {3, 4}, {2, 4},
            {2, 1}, {1, 1}, {1, 4}, {0, 4}}}}},
       {Point2(1.5, 4.0), Point2(3.5, 4.0), Point2(-1.0, 4.0), Point2(8.0, 4.0), Point2(1.5, 3.0), Point2(3.5, 5.0),
        Point2(1.5, 1.5), Point2(5.5, 2.5), Point2(-1.0, 1.0), Point2(8.0, 1.0), Point2(3.5, 8.0), Point2(0.5, 4.5)}},
      {"U shape",
       {{{R{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}}}},
       {Point2(1.5, 2.0), Point2(1.5, 3.0), Point2(1.5, 4.0), Point2(-1.0, 3.0), Point2(4.0, 1.0), Point2(1.5, 1.5)}},
      {"three boxes with collinear edges",
       {{{box_ring(0, 0, 1, 1)}}, {{box_ring(2, 0, 3, 1)}}, {{box_ring(4, 0, 5, 1)}}},
       {Point2(-1.0, 0.0), Point2(6.0, 0.0), Point2(1.5, 0.0), Point2(1.5, 1.0), Point2(-1.0, 1.0), Point2(3.5, 0.5),
        Point2(-2.0, -1.0), Point2(2.5, 2.0)}},
      {"three bitangents through the origin",
       {{{box_ring(2, 1, 3, 2)}}, {{box_ring(-3, -2, -2, -1)}}, {{box_ring(-2, 2, -1, 3)}}, {{box_ring(1, -3, 2, -2)}},
        {{box_ring(0.5, 2, 1, 3)}}, {{box_ring(-1, -3, -0.5, -2)}}},
       {Point2(0.0, 0.0), Point2(0.5, 0.25), Point2(-0.5, 0.5), Point2(0.25, 0.5), Point2(0.0, 1.0), Point2(1.0, 0.0)}},
      {"box with a hole and two islands",
       {{{box_ring(0, 0, 10, 10), box_ring(2, 2, 8, 8)}}, {{box_ring(4, 4, 5, 5)}}, {{box_ring(6, 4, 7, 5)}}},
       {Point2(3.0, 3.0), Point2(5.5, 4.5), Point2(3.0, 4.0), Point2(3.0, 5.0), Point2(7.5, 4.5), Point2(4.5, 3.0),
        Point2(2.5, 7.5), Point2(-1.0, 5.0), Point2(5.5, 2.5), Point2(11.0, 11.0), Point2(5.5, 6.5)}},
      {"ring with an empty hole",
       {{{box_ring(0, 0, 6, 6), box_ring(2, 2, 4, 4)}}},
       {Point2(3.0, 3.0), Point2(2.5, 2.5), Point2(3.5, 2.25), Point2(-1.0, 2.0), Point2(7.0, 7.0)}},
      {"octagon with flat vertices next to a box",
       {{{R{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}}}, {{box_ring(3, 0, 4, 2)}}},
       {Point2(-1.0, 1.0), Point2(2.5, 1.0), Point2(1.0, 3.0), Point2(5.0, 1.0), Point2(2.5, 0.0), Point2(2.5, 2.0),
        Point2(-1.0, 0.0), Point2(1.0, -1.0)}},
      {"diagonal chain of triangles",
       {{{R{{0, 0}, {1, 0}, {0, 1}}}}, {{R{{1, 1}, {2, 1}, {1, 2}}}}, {{R{{2, 2}, {3, 2}, {2, 3}}}}},
       {Point2(0.75, 0.75), Point2(-1.0, -1.0), Point2(4.0, 4.0), Point2(2.0, -1.0), Point2(-1.0, 2.0),
        Point2(1.5, 0.5), Point2(3.0, 1.0), Point2(1.75, 1.75)}},
  };
}

// Jittered convex polygons on an m x m grid of cells of side 10 (centres moved by up to 1, radius 1.5 to
// 4: disjoint): many small objects, doubles in general position.
std::vector<oracle2d::Polygon> jittered_convex_grid(std::uint64_t seed, int m) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<oracle2d::Polygon> polys;
  for (int i = 0; i < m * m; ++i) {
    oracle2d::Ring r;
    const int k = 3 + static_cast<int>(u(rng) * 6);
    const double cx = 10.0 * (i % m) + u(rng), cy = 10.0 * (i / m) + u(rng), rad = 1.5 + 2.5 * u(rng);
    for (int t = 0; t < k; ++t) {
      const double a = 6.283185307179586 * (t + 0.8 * u(rng)) / k;
      r.push_back({cx + rad * std::cos(a), cy + rad * std::sin(a)});
    }
    polys.push_back({{r}});
  }
  return polys;
}

// Radial (star-shaped, hence simple) polygons with double coordinates on an m x m grid of cells of side
// 10: k = 6 to 17 vertices at sorted random angles and random radii in [0.5, 4.5] around the cell centre,
// so many reflex vertices, in general position.
std::vector<oracle2d::Polygon> random_star_grid(std::uint64_t seed, int m) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<oracle2d::Polygon> polys;
  for (int i = 0; i < m * m; ++i) {
    const int k = 6 + static_cast<int>(u(rng) * 12);
    std::vector<double> ang;
    for (int t = 0; t < k; ++t) ang.push_back(6.283185307179586 * u(rng));
    std::sort(ang.begin(), ang.end());
    ang.erase(std::unique(ang.begin(), ang.end()), ang.end());
    oracle2d::Ring r;
    for (double a : ang) {
      const double rad = 0.5 + 4.0 * u(rng);
      r.push_back({10.0 * (i % m) + 5 + rad * std::cos(a), 10.0 * (i / m) + 5 + rad * std::sin(a)});
    }
    polys.push_back({{r}});
  }
  return polys;
}

}  // namespace

TEST(ComplexWalk2D, HandMadeDegenerateScenesMatchSweepAndCgal) {
  Tally tally;
  for (const HandScene& h : hand_scenes()) {
    const auto w = walk_scene(h.name, h.polys, 1.0);
    ASSERT_TRUE(w) << h.name;
    auto qs = query_points(*w, 11, 12);
    for (const Point2& p : h.points) {
      ASSERT_TRUE(is_free(*w, p)) << h.name << " " << str(p);
      qs.push_back({p, "hand-picked"});
    }
    check_scene(*w, qs, tally, 1, 3);
  }
  EXPECT_EQ(tally.failed, 0) << "of " << tally.checked << " queries";
  EXPECT_GE(tally.checked, 800);
  EXPECT_GE(tally.cgal_checked, 500);
  EXPECT_GE(tally.brute_checked, 250);
}

TEST(ComplexWalk2D, SceneWithoutObjects) {
  // make_scene2d accepts an empty list; the frame alone bounds the free space
  const Scene2D empty = make_scene2d({});
  ASSERT_EQ(empty.num_objects, 0);
  const WalkScene w("empty scene", empty, 0.5);
  Tally tally;
  for (const Point2& q : {Point2(0.5, 0.5), Point2(0.0, 0.0), Point2(-0.25, 1.0), Point2(1.0, 1.0 / 3)}) {
    ASSERT_TRUE(is_free(w, q));
    VisibilityPolygon2D poly;
    check_walk(w, q, "hand-picked", tally, nullptr, &poly);
    EXPECT_EQ(poly.vertices.size(), 4u);  // the frame box
  }
  EXPECT_EQ(tally.failed, 0);
}

TEST(ComplexWalk2D, RandomConvexScenesMatchSweep) {
  Tally tally;
  int scenes = 0;
  for (std::uint64_t seed = 1; scenes < 30 && seed < 300; ++seed) {
    const auto w = walk_scene("random_grid_scene(seed " + std::to_string(seed) + ", convex only)",
                              oracle2d::random_grid_scene(seed, 2 + seed % 2, true), 0.1 + 0.1 * (seed % 3));
    if (!w || w->scene.num_objects == 0) continue;
    ++scenes;
    check_scene(*w, query_points(*w, seed, 20), tally, seed % 5 == 0 ? 4 : 0);
  }
  EXPECT_EQ(tally.failed, 0) << "of " << tally.checked << " queries";
  EXPECT_GE(tally.checked, 3000);
  EXPECT_GE(tally.cgal_checked, 100);
}

TEST(ComplexWalk2D, RandomStarAndHoledScenesMatchSweep) {
  // random_grid_scene mixes convex polygons, star-shaped (non-convex) polygons on the grid, and squares
  // with square holes holding islands
  Tally tally;
  int scenes = 0;
  for (std::uint64_t seed = 1; scenes < 40 && seed < 600; ++seed) {
    const auto w = walk_scene("random_grid_scene(seed " + std::to_string(seed) + ")",
                              oracle2d::random_grid_scene(seed, 2 + seed % 2), 0.1 + 0.1 * (seed % 3));
    if (!w || w->scene.num_objects == 0) continue;
    ++scenes;
    check_scene(*w, query_points(*w, seed, 20), tally, seed % 5 == 0 ? 4 : 0);
  }
  EXPECT_EQ(tally.failed, 0) << "of " << tally.checked << " queries";
  EXPECT_GE(tally.checked, 4000);
  EXPECT_GE(tally.cgal_checked, 100);
}

TEST(ComplexWalk2D, BoxScenesWithFlatVerticesHolesAndCollinearEdgesMatchSweep) {
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const auto w = walk_scene("random_box_scene(seed " + std::to_string(seed) + ", " + std::to_string(3 + seed % 6) + ")",
                              random_box_scene(seed, 3 + seed % 6), 0.2);
    ASSERT_TRUE(w) << seed;
    check_scene(*w, query_points(*w, seed, 15), tally, seed % 4 == 0 ? 3 : 0);
  }
  EXPECT_EQ(tally.failed, 0) << "of " << tally.checked << " queries";
  EXPECT_GE(tally.checked, 4000);
  EXPECT_GE(tally.cgal_checked, 150);
}

TEST(ComplexWalk2D, TriangleScenesOnASmallGridMatchSweep) {
  // vertices on a 7 x 7 grid: collinear vertices across objects, parallel edges, several bitangents on
  // one line and through one point
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const auto w = walk_scene("random_triangle_scene(seed " + std::to_string(seed) + ", " + std::to_string(2 + seed % 5) + ")",
                              random_triangle_scene(seed, 2 + seed % 5), 0.2);
    ASSERT_TRUE(w) << seed;
    check_scene(*w, query_points(*w, seed, 15), tally, seed % 4 == 0 ? 3 : 0, seed % 4 == 2 ? 4 : 0);
  }
  EXPECT_EQ(tally.failed, 0) << "of " << tally.checked << " queries";
  EXPECT_GE(tally.checked, 4000);
  EXPECT_GE(tally.cgal_checked, 150);
  EXPECT_GE(tally.brute_checked, 200);
}

TEST(ComplexWalk2D, StarPolygonsInGeneralPositionMatchSweepAndCgal) {
  // many reflex vertices, double coordinates without exact degeneracies
  Tally tally;
  int scenes = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const auto w = walk_scene("random_star_grid(seed " + std::to_string(seed) + ", 3)", random_star_grid(seed, 3), 0.1);
    if (!w) continue;
    ++scenes;
    check_scene(*w, query_points(*w, seed, 10), tally, 4);
  }
  EXPECT_GE(scenes, 10);
  EXPECT_EQ(tally.failed, 0) << "of " << tally.checked << " queries";
  EXPECT_GE(tally.checked, 900);
  EXPECT_GE(tally.cgal_checked, 200);
}

TEST(ComplexWalk2D, ScenesWithRationalCoordinatesMatchSweep) {
  // box and triangle scenes under exact rational maps that keep every collinearity: a rotation with
  // cos = 3/5, sin = 4/5 (axis-parallel edges become slanted, other vertex lines become horizontal), a
  // scaling by 1/3 (coordinates no longer doubles), a shrinking by 1/1000003 moved to (10^6, -10^6) (the
  // scene in a tiny corner of its frame) and a blow-up by 10^9 moved by (1/7, -2/7)
  static const char* const maps[] = {"rotated by (3/5, 4/5)", "scaled by 1/3", "shrunk by 1/1000003 at (1e6, -1e6)",
                                     "blown up by 1e9 and moved by (1/7, -2/7)"};
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    const auto polys = seed % 2 ? random_box_scene(seed, 3 + seed % 5) : random_triangle_scene(seed, 3 + seed % 5);
    auto input = to_input(polys);
    const int map = (seed / 2) % 4;
    for (auto& poly : input)
      for (auto& ring : poly.rings)
        for (Point2& p : ring)
          p = map == 0   ? Point2((Exact(3) * p.x - Exact(4) * p.y) / 5, (Exact(4) * p.x + Exact(3) * p.y) / 5)
              : map == 1 ? Point2(p.x / 3, p.y / 3)
              : map == 2 ? Point2(p.x / 1000003 + Exact(1000000), p.y / 1000003 - Exact(1000000))
                         : Point2(p.x * Exact(1e9) + Exact(1) / 7, p.y * Exact(1e9) - Exact(2) / 7);
    const WalkScene w(std::string(seed % 2 ? "random_box_scene" : "random_triangle_scene") + "(seed " +
                          std::to_string(seed) + ", " + std::to_string(3 + seed % 5) + ") " + maps[map],
                      make_scene2d(input), 0.2);
    check_scene(w, query_points(w, seed, 12), tally, seed % 3 == 0 ? 3 : 0);
  }
  EXPECT_EQ(tally.failed, 0) << "of " << tally.checked << " queries";
  EXPECT_GE(tally.checked, 2000);
  EXPECT_GE(tally.cgal_checked, 200);
}

TEST(ComplexWalk2D, OneIndexServesFramesOfAnyMargin) {
  // the index is built on the scene without frame; queries may use with_frame(scene, m) for any m
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const auto w = walk_scene("random_grid_scene(seed " + std::to_string(seed) + ")", oracle2d::random_grid_scene(seed, 2));
    if (!w) continue;
    for (double margin : {0.0, 0.05, 2.0}) {
      const Scene2D framed = with_frame(w->scene, margin);
      std::mt19937_64 rng(seed);
      const Ring2D& fr = framed.rings[framed.frame_ring];
      const Point2 &lo = framed.points[fr.first], &hi = framed.points[fr.first + 2];
      for (int found = 0, tries = 0; found < 30 && tries < 300; ++tries) {
        const Point2 q(std::round(4 * std::uniform_real_distribution<double>(lo.ax, hi.ax)(rng)) / 4,
                       std::round(4 * std::uniform_real_distribution<double>(lo.ay, hi.ay)(rng)) / 4);
        if (on_boundary(framed, q) || inside_obstacle(framed, q)) continue;
        ++found, ++tally.checked;
        const auto got = visibility_polygon_in_complex(w->index, framed, q).vertices;
        if (got != visibility_polygon(framed, q).vertices)
          tally.fail(w->name + ", margin " + std::to_string(margin) + ", q " + str(q));
      }
    }
  }
  EXPECT_EQ(tally.failed, 0) << "of " << tally.checked << " queries";
  EXPECT_GE(tally.checked, 400);
}

TEST(ComplexWalk2D, ManyPointsOnAllCoresEqualSingleWalks) {
  // visibility_polygons_in_complex (parallel over the points) against the angular sweep per point, on
  // degenerate scenes with adversarial points; a repeated point; an empty list; a bad point among good ones
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const auto w = seed % 2 ? walk_scene("random_box_scene(seed " + std::to_string(seed) + ", 6)", random_box_scene(seed, 6))
                            : walk_scene("random_triangle_scene(seed " + std::to_string(seed) + ", 6)", random_triangle_scene(seed, 6));
    ASSERT_TRUE(w);
    std::vector<Point2> points;
    for (const Query& q : query_points(*w, seed, 8)) points.push_back(q.q);
    points.push_back(points.front());
    const auto batch = visibility_polygons_in_complex(w->index, w->framed, points);
    ASSERT_EQ(batch.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i, ++checked)
      ASSERT_TRUE(batch[i].vertices == visibility_polygon(w->framed, points[i]).vertices)
          << w->name << " q " << str(points[i]);
    EXPECT_TRUE(visibility_polygons_in_complex(w->index, w->framed, {}).empty());
    const Point2 bad = w->scene.points[0];  // a vertex: on a boundary
    points.insert(points.begin() + points.size() / 2, bad);
    EXPECT_THROW(visibility_polygons_in_complex(w->index, w->framed, points), std::invalid_argument) << w->name;
  }
  EXPECT_GE(checked, 600);
}

TEST(ComplexWalk2D, RejectsBadInput) {
  const std::vector<oracle2d::Polygon> polys{{{box_ring(0, 0, 10, 10), box_ring(2, 2, 8, 8)}}, {{box_ring(4, 4, 5, 5)}}};
  const auto w = walk_scene("box with a hole and an island", polys, 0.5);
  ASSERT_TRUE(w);
  auto walk = [&](const Point2& q) { return visibility_polygon_in_complex(w->index, w->framed, q); };
  EXPECT_THROW(walk(Point2(1.0, 5.0)), std::invalid_argument);    // inside the ring
  EXPECT_THROW(walk(Point2(4.5, 4.5)), std::invalid_argument);    // inside the island
  EXPECT_THROW(walk(Point2(0.0, 5.0)), std::invalid_argument);    // on an edge
  EXPECT_THROW(walk(Point2(2.0, 5.0)), std::invalid_argument);    // on a hole edge
  EXPECT_THROW(walk(Point2(10.0, 10.0)), std::invalid_argument);  // at a vertex
  EXPECT_THROW(walk(Point2(5.0, 4.0)), std::invalid_argument);    // on the island's edge
  EXPECT_THROW(walk(Point2(100.0, 5.0)), std::invalid_argument);  // outside the frame
  const Ring2D& fr = w->framed.rings[w->framed.frame_ring];
  EXPECT_THROW(walk(w->framed.points[fr.first]), std::invalid_argument);  // frame corner
  const Point2 &f0 = w->framed.points[fr.first], &f1 = w->framed.points[fr.first + 1];
  EXPECT_THROW(walk(Point2((f0.x + f1.x) / 2, (f0.y + f1.y) / 2)), std::invalid_argument);  // frame edge
  // a scene without frame in place of the framed scene
  EXPECT_THROW(visibility_polygon_in_complex(w->index, w->scene, Point2(3.0, 3.0)), std::invalid_argument);
  // good points in the hole, outside the ring
  Tally tally;
  for (const Point2& q : {Point2(3.0, 3.0), Point2(11.0, 5.0), Point2(-1.0, -1.0), Point2(4.5, 3.0)}) {
    EXPECT_NO_THROW(walk(q));
    check_walk(*w, q, "hand-picked", tally);
  }
  EXPECT_EQ(tally.failed, 0);
}

TEST(ComplexWalk2D, CountersShowTheWalkTestsOnlyTheCandidatesOfItsFaces) {
  // Per step the walk tests the candidate pivots of the face it is in (the pivots of the complex edges
  // whose segments have the face's end objects), so candidates <= faces * (largest candidate list). A
  // walk scanning all n vertices at each of its events would test n * events; on a grid of 100 small
  // objects a face's candidates are the pivots of the few objects between its two end objects, so the
  // walk must stay far below that (asserted: 8 times below, summed over the queries).
  const auto w = walk_scene("jittered_convex_grid(seed 3, 10 x 10)", jittered_convex_grid(3, 10), 0.1);
  ASSERT_TRUE(w);
  const std::size_t n = w->scene.num_vertices();
  std::size_t largest = 0, entries = 0;
  for (const auto& [pair, pivots] : w->index.candidates) largest = std::max(largest, pivots.size()), entries += pivots.size();
  ASSERT_GT(entries, 0u);
  Tally tally;
  std::size_t events = 0, faces = 0, candidates = 0;
  for (const Query& q : query_points(*w, 5, 8)) {
    ComplexWalkStats2D st;
    check_walk(*w, q.q, q.kind, tally, &st);
    EXPECT_GT(st.events, 0u) << str(q.q);
    EXPECT_GT(st.faces, 0u) << str(q.q);
    EXPECT_LE(st.candidates, st.faces * largest) << str(q.q);
    events += st.events, faces += st.faces, candidates += st.candidates;
  }
  EXPECT_EQ(tally.failed, 0) << "of " << tally.checked << " queries";
  EXPECT_GE(tally.checked, 40);
  RecordProperty("n", static_cast<int>(n));
  RecordProperty("events", static_cast<int>(events));
  RecordProperty("faces", static_cast<int>(faces));
  RecordProperty("candidates", static_cast<int>(candidates));
  RecordProperty("largest_candidate_list", static_cast<int>(largest));
  EXPECT_LT(8 * candidates, n * events) << "n " << n << ", events " << events << ", faces " << faces
                                         << ", candidates " << candidates << ", largest list " << largest;
  // the same counters on small random scenes: events > 0 whenever there is an object
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto s = walk_scene("random_box_scene(seed " + std::to_string(seed) + ", 4)", random_box_scene(seed, 4));
    ASSERT_TRUE(s);
    std::size_t big = 0;
    for (const auto& [pair, pivots] : s->index.candidates) big = std::max(big, pivots.size());
    for (const Query& q : query_points(*s, seed, 2)) {
      ComplexWalkStats2D st;
      check_walk(*s, q.q, q.kind, tally, &st);
      EXPECT_GT(st.events, 0u) << s->name << " " << str(q.q);
      EXPECT_LE(st.candidates, st.faces * big) << s->name << " " << str(q.q);
    }
  }
  EXPECT_EQ(tally.failed, 0);
}
