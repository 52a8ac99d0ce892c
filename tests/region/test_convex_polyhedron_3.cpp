// Exact convex polyhedra by clipping a box, against the brute-force half-space oracle: the vertex set equals
// the oracle's (every feasible triple-plane point), the volume equals the divergence-theorem volume of the
// boundary triangles, the surface is a closed oriented 2-manifold (every edge used once each way, Euler
// characteristic 2), every face's vertices lie on its plane with the rest of the polyhedron inside, and point
// location agrees with evaluating every half-space. Random planes (fixed seeds) include degenerate ones:
// planes through existing vertices, edges and faces, and planes that leave only a face, an edge or a point.
#include "region/convex_polyhedron_3.hpp"

#include "oracles/halfspace_oracle.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>

using namespace exactvis;
using namespace exactvis::region;

namespace {

oracle::QVec qv(const RationalPoint3& p) { return {mpq_class(p.x.mpq()), mpq_class(p.y.mpq()), mpq_class(p.z.mpq())}; }
mpq_class qn(const Exact& x) { return mpq_class(x.mpq()); }
oracle::QHalfspace qh(const Plane3& p) { return {{qn(p.normal.x), qn(p.normal.y), qn(p.normal.z)}, qn(p.offset)}; }

std::vector<oracle::QHalfspace> box_halfspaces(const RationalPoint3& lo, const RationalPoint3& hi) {
  return {{{1, 0, 0}, qn(lo.x)},  {{-1, 0, 0}, -qn(hi.x)}, {{0, 1, 0}, qn(lo.y)},
          {{0, -1, 0}, -qn(hi.y)}, {{0, 0, 1}, qn(lo.z)},  {{0, 0, -1}, -qn(hi.z)}};
}

bool same_point_set(const std::vector<oracle::QVec>& a, const std::vector<oracle::QVec>& b) {
  if (a.size() != b.size()) return false;
  for (const auto& p : a) {
    bool found = false;
    for (const auto& q : b) found = found || p == q;
    if (!found) return false;
  }
  return true;
}

// Every structural property of a non-empty polyhedron (failures are reported by gtest).
void check_structure(const ConvexPolyhedron3& p) {
  ASSERT_FALSE(p.empty());
  std::map<std::pair<int, int>, int> directed;
  std::set<std::pair<int, int>> undirected;
  std::set<int> used;
  for (const auto& f : p.faces) {
    ASSERT_GE(f.loop.size(), 3u);
    for (std::size_t i = 0; i < f.loop.size(); ++i) {
      const int a = f.loop[i], b = f.loop[(i + 1) % f.loop.size()];
      ASSERT_NE(a, b);
      directed[{a, b}]++;
      undirected.insert({std::min(a, b), std::max(a, b)});
      used.insert(a);
    }
    const oracle::QHalfspace h = qh(f.plane);
    // Vertices on the face's plane, all others on its inner side, at least one strictly (a true facet).
    std::set<int> on(f.loop.begin(), f.loop.end());
    for (std::size_t v = 0; v < p.vertices.size(); ++v) {
      const mpq_class val = oracle::dot(h.n, qv(p.vertices[v])) - h.d;
      if (on.count(static_cast<int>(v))) EXPECT_EQ(val, 0);
      else EXPECT_GE(val, 0);
    }
    // Loop counter-clockwise seen from outside: each fan triangle's normal points against the inward normal;
    // strictly convex: no three consecutive vertices collinear.
    for (std::size_t i = 0; i < f.loop.size(); ++i) {
      const oracle::QVec a = qv(p.vertices[f.loop[i]]), b = qv(p.vertices[f.loop[(i + 1) % f.loop.size()]]),
                         c = qv(p.vertices[f.loop[(i + 2) % f.loop.size()]]);
      EXPECT_LT(oracle::sign(oracle::dot(oracle::cross(b - a, c - b), h.n)), 0);
    }
  }
  EXPECT_EQ(used.size(), p.vertices.size()) << "unused vertices";
  for (const auto& [e, n] : directed) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(directed.count({e.second, e.first}), 1u) << "edge without its opposite";
  }
  const long V = static_cast<long>(p.vertices.size()), E = static_cast<long>(undirected.size()),
             F = static_cast<long>(p.faces.size());
  EXPECT_EQ(V - E + F, 2);
}

std::vector<std::array<oracle::QVec, 3>> q_triangles(const ConvexPolyhedron3& p) {
  std::vector<std::array<oracle::QVec, 3>> out;
  for (const auto& t : boundary_triangles(p)) out.push_back({qv(t[0]), qv(t[1]), qv(t[2])});
  return out;
}

// Compares the clipped polyhedron with the oracle for the box and the planes.
void check_against_oracle(const ConvexPolyhedron3& p, const RationalPoint3& lo, const RationalPoint3& hi,
                          const std::vector<Plane3>& planes) {
  std::vector<oracle::QHalfspace> h = box_halfspaces(lo, hi);
  for (const auto& pl : planes) h.push_back(qh(pl));
  const std::vector<oracle::QVec> expected = oracle::halfspace_vertices(h);
  if (!oracle::spans_3d(expected)) {
    EXPECT_TRUE(p.empty()) << "oracle: no interior, got " << p.vertices.size() << " vertices";
    return;
  }
  ASSERT_FALSE(p.empty()) << "oracle: " << expected.size() << " vertices spanning 3D";
  std::vector<oracle::QVec> got;
  for (const auto& v : p.vertices) got.push_back(qv(v));
  EXPECT_TRUE(same_point_set(got, expected)) << got.size() << " vs " << expected.size();
  check_structure(p);
  EXPECT_EQ(qn(volume(p)), oracle::enclosed_volume(q_triangles(p)));
  EXPECT_GT(qn(volume(p)), 0);
}

}  // namespace

TEST(ConvexPolyhedron3, Box) {
  const RationalPoint3 lo{Exact(-1), Exact(0), Exact(2)}, hi{Exact(3), Exact(1, 2), Exact(5)};
  const ConvexPolyhedron3 box = box_polyhedron(lo, hi);
  EXPECT_EQ(box.vertices.size(), 8u);
  EXPECT_EQ(box.faces.size(), 6u);
  check_structure(box);
  EXPECT_EQ(volume(box), Exact(4) * Exact(1, 2) * Exact(3));
  EXPECT_EQ(oracle::enclosed_volume(q_triangles(box)), mpq_class(6));
  EXPECT_TRUE(box_polyhedron(lo, {Exact(3), Exact(0), Exact(5)}).empty());  // flat box
  EXPECT_EQ(volume(ConvexPolyhedron3{}), Exact(0));
}

TEST(ConvexPolyhedron3, RandomClipsAgainstOracle) {
  std::mt19937_64 rng(11);
  auto small = [&](int r) { return Exact(static_cast<long>(rng() % (2 * r + 1)) - r); };
  int nonempty = 0, empty = 0, degenerate_planes = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const RationalPoint3 lo{Exact(-4), Exact(-4), Exact(-4)}, hi{Exact(4), Exact(4), Exact(4)};
    ConvexPolyhedron3 p = box_polyhedron(lo, hi);
    std::vector<Plane3> planes;
    const int k = 1 + static_cast<int>(rng() % 5);
    for (int i = 0; i < k; ++i) {
      Plane3 pl;
      if (!p.empty() && rng() % 3 == 0) {
        // A plane through one to three current vertices: degenerate contacts.
        const auto& vs = p.vertices;
        const RationalPoint3 a = vs[rng() % vs.size()], b = vs[rng() % vs.size()];
        const RationalPoint3 c = rng() % 2 ? vs[rng() % vs.size()] : RationalPoint3{small(4), small(4), small(4)};
        pl = plane_through(a, b, c);
        ++degenerate_planes;
      } else {
        pl = Plane3{{small(3), small(3), small(3)}, small(6)};
      }
      if (pl.normal == Vec3<Exact>(Exact(0), Exact(0), Exact(0))) continue;
      planes.push_back(pl);
      p = clip_polyhedron(p, pl);
    }
    check_against_oracle(p, lo, hi, planes);
    (p.empty() ? empty : nonempty)++;
  }
  EXPECT_GT(nonempty, 100);
  EXPECT_GT(empty, 10);
  EXPECT_GT(degenerate_planes, 50);
}

TEST(ConvexPolyhedron3, SplitPartitionsVolume) {
  std::mt19937_64 rng(3);
  auto small = [&](int r) { return Exact(static_cast<long>(rng() % (2 * r + 1)) - r); };
  for (int trial = 0; trial < 200; ++trial) {
    ConvexPolyhedron3 p = box_polyhedron({small(2) - 3, small(2) - 3, small(2) - 3}, {small(2) + 3, small(2) + 3, small(2) + 3});
    for (int i = 0; i < 3; ++i) {
      const Plane3 cut{{small(2), small(2), small(2)}, small(3)};
      if (cut.normal == Vec3<Exact>(Exact(0), Exact(0), Exact(0))) continue;
      const ConvexPolyhedron3 front = clip_polyhedron(p, cut), back = clip_polyhedron(p, cut.flipped());
      EXPECT_EQ(volume(front) + volume(back), volume(p));
      p = rng() % 2 ? front : back;
      if (p.empty()) break;
    }
  }
}

TEST(ConvexPolyhedron3, DegenerateContacts) {
  const RationalPoint3 lo{Exact(0), Exact(0), Exact(0)}, hi{Exact(2), Exact(2), Exact(2)};
  const ConvexPolyhedron3 box = box_polyhedron(lo, hi);
  const Exact zero(0), one(1);
  // x >= 0 touches a face: unchanged. x >= 2 leaves the face x = 2 only: empty. x <= 0 (keep -x >= 0): empty.
  EXPECT_EQ(clip_polyhedron(box, Plane3{{one, zero, zero}, zero}).vertices.size(), 8u);
  EXPECT_TRUE(clip_polyhedron(box, Plane3{{one, zero, zero}, Exact(2)}).empty());
  EXPECT_TRUE(clip_polyhedron(box, Plane3{{-one, zero, zero}, zero}).empty());
  // x + y >= 4 leaves only the edge x = y = 2; x + y + z >= 6 only the corner: empty.
  EXPECT_TRUE(clip_polyhedron(box, Plane3{{one, one, zero}, Exact(4)}).empty());
  EXPECT_TRUE(clip_polyhedron(box, Plane3{{one, one, one}, Exact(6)}).empty());
  // x + y >= 2 through a diagonal of two faces: a prism with 6 vertices, half the volume.
  const ConvexPolyhedron3 prism = clip_polyhedron(box, Plane3{{one, one, zero}, Exact(2)});
  EXPECT_EQ(prism.vertices.size(), 6u);
  EXPECT_EQ(prism.faces.size(), 5u);
  EXPECT_EQ(volume(prism), Exact(4));
  check_structure(prism);
  // x + y + z >= 1 cuts a corner: 10 vertices (7 kept + 3 new), 7 faces.
  const ConvexPolyhedron3 cut = clip_polyhedron(box, Plane3{{one, one, one}, one});
  EXPECT_EQ(cut.vertices.size(), 10u);
  EXPECT_EQ(cut.faces.size(), 7u);
  EXPECT_EQ(volume(cut), Exact(8) - Exact(1, 6));
  check_structure(cut);
  // x + y + z >= 2 passes through three corners: the corner tetrahedron goes, 7 vertices, 7 faces.
  const ConvexPolyhedron3 corner = clip_polyhedron(box, Plane3{{one, one, one}, Exact(2)});
  EXPECT_EQ(corner.vertices.size(), 7u);
  EXPECT_EQ(corner.faces.size(), 7u);
  EXPECT_EQ(volume(corner), Exact(8) - Exact(8, 6));
  check_structure(corner);
}

TEST(ConvexPolyhedron3, IntersectHalfspacesAndLocate) {
  std::mt19937_64 rng(7);
  auto small = [&](int r) { return Exact(static_cast<long>(rng() % (2 * r + 1)) - r); };
  const RationalPoint3 lo{Exact(-3), Exact(-3), Exact(-3)}, hi{Exact(3), Exact(3), Exact(3)};
  int interior = 0, boundary = 0, outside = 0;
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<Plane3> planes;
    while (planes.size() < 4) {
      const Plane3 pl{{small(2), small(2), small(2)}, Exact(-static_cast<int>(rng() % 4))};  // mostly around 0
      if (!(pl.normal == Vec3<Exact>(Exact(0), Exact(0), Exact(0)))) planes.push_back(pl);
    }
    const ConvexPolyhedron3 p = intersect_halfspaces(lo, hi, planes);
    check_against_oracle(p, lo, hi, planes);
    std::vector<oracle::QHalfspace> h = box_halfspaces(lo, hi);
    for (const auto& pl : planes) h.push_back(qh(pl));
    for (int s = 0; s < 30; ++s) {
      const RationalPoint3 x{small(3), small(3), Exact(static_cast<int>(rng() % 13) - 6, 2)};
      int worst = 1;  // 1 strictly inside all, 0 on some, -1 outside some
      for (const auto& hs : h) worst = std::min(worst, oracle::sign(oracle::dot(hs.n, qv(x)) - hs.d));
      const Containment want = p.empty() ? Containment::Outside
                               : worst > 0 ? Containment::Interior
                               : worst == 0 ? Containment::Boundary
                                            : Containment::Outside;
      // A polyhedron with no interior contains nothing, even where the (flat) half-space set has points.
      EXPECT_EQ(locate(p, x), want);
      (want == Containment::Interior ? interior : want == Containment::Boundary ? boundary : outside)++;
    }
  }
  EXPECT_GT(interior, 50);
  EXPECT_GT(boundary, 50);
  EXPECT_GT(outside, 50);
}

// polygon_outside against point classification by the oracle: random solids (a box clipped by random planes)
// and random convex polygons in planes z = c, c often a plane of the solid's box (the polygon then lies in
// a face's plane, partly on the solid's boundary). At random rational points of the polygon: a point in the
// closed solid lies in no piece's relative interior; a point strictly outside lies in some closed piece; no
// point lies in two pieces' relative interiors. Every piece's centroid is strictly outside the solid.
TEST(ConvexPolyhedron3, PolygonOutsideAgainstOracle) {
  std::mt19937_64 rng(29);
  auto small = [&](int r) { return Exact(static_cast<long>(rng() % (2 * r + 1)) - r); };
  // In a piece in the plane z = c (x, y orientation): +1 relint, 0 on its boundary, -1 outside.
  auto where_in = [](const Polygon3& piece, const oracle::QVec& x) {
    int turn = 0, worst = 1;
    for (std::size_t i = 0; i < piece.size() && turn == 0; ++i) {
      const oracle::QVec a = qv(piece[i]), b = qv(piece[(i + 1) % piece.size()]), c = qv(piece[(i + 2) % piece.size()]);
      turn = oracle::sign((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    }
    for (std::size_t i = 0; i < piece.size(); ++i) {
      const oracle::QVec a = qv(piece[i]), b = qv(piece[(i + 1) % piece.size()]);
      worst = std::min(worst, turn * oracle::sign((b.x - a.x) * (x.y - a.y) - (b.y - a.y) * (x.x - a.x)));
    }
    return worst;
  };
  int inside = 0, outside = 0, coplanar = 0, split = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const RationalPoint3 lo{small(2) - 2, small(2) - 2, small(2) - 2}, hi{small(2) + 2, small(2) + 2, small(2) + 2};
    std::vector<Plane3> planes;
    for (int i = 0; i < static_cast<int>(rng() % 3); ++i) {
      const Plane3 pl{{small(2), small(2), small(2)}, small(2)};
      if (!(pl.normal == Vec3<Exact>(Exact(0), Exact(0), Exact(0)))) planes.push_back(pl);
    }
    const ConvexPolyhedron3 solid = intersect_halfspaces(lo, hi, planes);
    if (solid.empty()) continue;
    std::vector<oracle::QHalfspace> h = box_halfspaces(lo, hi);
    for (const auto& pl : planes) h.push_back(qh(pl));
    const Exact c = rng() % 2 ? (rng() % 2 ? lo.z : hi.z) : Exact(static_cast<int>(rng() % 17) - 8, 2);
    coplanar += c == lo.z || c == hi.z;
    // A convex polygon: a square clipped by a random line of the plane.
    Polygon3 poly{{small(3) - 1, small(3) - 1, c}, {}, {}, {}};
    const Exact side = Exact(1 + static_cast<int>(rng() % 6));
    poly[1] = {poly[0].x + side, poly[0].y, c};
    poly[2] = {poly[0].x + side, poly[0].y + side, c};
    poly[3] = {poly[0].x, poly[0].y + side, c};
    if (rng() % 2) {
      const Polygon3 cut = clip_polygon(poly, Plane3{{small(2), small(2), Exact(0)}, poly[0].x + poly[0].y + side / 2});
      if (!is_degenerate(cut)) poly = cut;
    }
    const std::vector<Polygon3> pieces = polygon_outside(poly, solid);
    split += pieces.size() > 1;
    for (const auto& piece : pieces) {
      ASSERT_FALSE(is_degenerate(piece));
      const oracle::QVec g = qv(centroid(piece));
      int worst = 1;
      for (const auto& hs : h) worst = std::min(worst, oracle::sign(oracle::dot(hs.n, g) - hs.d));
      EXPECT_LT(worst, 0) << "a piece's centroid in the closed solid";
      for (const auto& v : piece) EXPECT_EQ(v.z, c);
    }
    for (int s = 0; s < 40; ++s) {
      const RationalPoint3 x = random_interior_point(poly, rng);
      int worst = 1;
      for (const auto& hs : h) worst = std::min(worst, oracle::sign(oracle::dot(hs.n, qv(x)) - hs.d));
      int relint = 0, closed = 0;
      for (const auto& piece : pieces) {
        const int w = where_in(piece, qv(x));
        relint += w > 0;
        closed += w >= 0;
      }
      EXPECT_LE(relint, 1);
      if (worst >= 0) {
        EXPECT_EQ(relint, 0) << "a point of the closed solid inside a piece";
        ++inside;
      } else {
        EXPECT_GE(closed, 1) << "a point outside the solid in no piece";
        ++outside;
      }
    }
  }
  EXPECT_GT(inside, 300);
  EXPECT_GT(outside, 300);
  EXPECT_GT(coplanar, 30);
  EXPECT_GT(split, 30);
}
