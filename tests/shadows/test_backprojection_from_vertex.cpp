// The 3D skeleton issue's point-to-polygon query (docs/theory.md section 9, "Queries"): the visible part of a
// triangle seen from a scene *vertex* is shadows::backproject at that vertex's position (the vertex's own
// triangles pass through it and hide nothing of positive area). Checked against the independent oracle
// (tests/oracles/rational_geometry: open segment vs closed triangle) on random rational points, and exact
// areas.
#include "kernel/triangle_index.hpp"
#include "oracles/rational_geometry.hpp"
#include "shadows/backprojection.hpp"

#include <gtest/gtest.h>

#include <random>

namespace exactvis::shadows {
namespace {

using oracle::QVec;

QVec qv(const Point3& p) { return oracle::qvec(p.x, p.y, p.z); }
QVec qv(const Vec3<Exact>& p) { return {mpq_class(p.x.mpq()), mpq_class(p.y.mpq()), mpq_class(p.z.mpq())}; }

Scene soup(const std::vector<std::array<Point3, 3>>& tris) {
  Scene s;
  for (const auto& t : tris) {
    const int b = static_cast<int>(s.vertices.size());
    s.vertices.insert(s.vertices.end(), t.begin(), t.end());
    s.objects.push_back({"o" + std::to_string(s.objects.size())});
    s.triangles.push_back({s.faces_read++, {b, b + 1, b + 2}, static_cast<int>(s.objects.size()) - 1});
  }
  return s;
}

// 2D coordinates dropping axis `drop`; point-in-ring by crossings; -1 when on the ring (boundary).
int in_ring(const QVec& p, const std::vector<QVec>& ring, int drop) {
  auto c = [&](const QVec& q, int k) { const int a = (drop + 1 + k) % 3; return a == 0 ? q.x : (a == 1 ? q.y : q.z); };
  const mpq_class px = c(p, 0), py = c(p, 1);
  bool inside = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const QVec& a = ring[i];
    const QVec& b = ring[(i + 1) % ring.size()];
    const mpq_class ax = c(a, 0), ay = c(a, 1), bx = c(b, 0), by = c(b, 1);
    const mpq_class cr = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    if (cr == 0 && std::min(ax, bx) <= px && px <= std::max(ax, bx) && std::min(ay, by) <= py && py <= std::max(ay, by))
      return -1;
    if ((ay > py) != (by > py)) {
      const mpq_class x = ax + (py - ay) * (bx - ax) / (by - ay);
      if (x > px) inside = !inside;
    }
  }
  return inside ? 1 : 0;
}

Backprojection view_from_vertex(const Scene& s, const TriangleIndex& index, int vertex, int triangle) {
  const Point3& v = s.vertices[vertex];
  return backproject(s, index, {triangle}, RationalPoint3{Exact(v.x), Exact(v.y), Exact(v.z)});
}

// 1 seen, 0 not, -1 on a boundary.
int in_view(const Backprojection& view, const QVec& p, int drop) {
  for (const auto& vp : view.parts.at(0).pieces) {
    std::vector<QVec> outer;
    for (const auto& q : vp.outer) outer.push_back(qv(q));
    const int o = in_ring(p, outer, drop);
    if (o != 1) {
      if (o < 0) return -1;
      continue;
    }
    bool in_hole = false;
    for (const auto& h : vp.holes) {
      std::vector<QVec> ring;
      for (const auto& q : h) ring.push_back(qv(q));
      const int r = in_ring(p, ring, drop);
      if (r < 0) return -1;
      in_hole = in_hole || r == 1;
    }
    if (!in_hole) return 1;
  }
  return 0;
}

void check_by_sampling(const Scene& s, int vertex, int triangle, unsigned seed, int* seen_count, int* hidden_count) {
  const TriangleIndex index(s);
  const Backprojection view = view_from_vertex(s, index, vertex, triangle);
  const auto& t = s.triangles[triangle];
  const QVec a = qv(s.corner(t, 0)), b = qv(s.corner(t, 1)), c = qv(s.corner(t, 2));
  const QVec n = oracle::cross(b - a, c - a);
  int drop = 0;
  for (int k = 1; k < 3; ++k) {
    const mpq_class nk = k == 1 ? n.y : n.z, nd = drop == 0 ? n.x : (drop == 1 ? n.y : n.z);
    if (abs(nk) > abs(nd)) drop = k;
  }
  const QVec v = qv(s.vertices[vertex]);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> w(1, 1000);
  for (int i = 0; i < 300; ++i) {
    const mpq_class u1 = w(rng), u2 = w(rng), u3 = w(rng), sum = u1 + u2 + u3;
    const QVec p = (u1 / sum) * a + (u2 / sum) * b + (u3 / sum) * c;
    const int got = in_view(view, p, drop);
    if (got < 0) continue;
    bool blocked = false;
    for (std::size_t o = 0; o < s.triangles.size() && !blocked; ++o) {
      if (static_cast<int>(o) == triangle) continue;
      const auto& ot = s.triangles[o];
      if (ot.v[0] == vertex || ot.v[1] == vertex || ot.v[2] == vertex) continue;
      blocked = oracle::oracle_open_segment_meets_closed_triangle(v, p, qv(s.corner(ot, 0)), qv(s.corner(ot, 1)),
                                                                  qv(s.corner(ot, 2)));
    }
    EXPECT_EQ(got == 1, !blocked) << "sample " << i;
    (got == 1 ? *seen_count : *hidden_count) += 1;
  }
}

TEST(BackprojectionFromVertex, UnblockedTriangleIsSeenWhole) {
  const Scene s = soup({{Point3{0, 0, 5}, Point3{1, 0, 5}, Point3{0, 1, 5}}, {Point3{-3, -3, 0}, Point3{4, -2, 0}, Point3{0, 5, 0}}});
  const TriangleIndex index(s);
  const auto view = view_from_vertex(s, index, 0, 1);
  ASSERT_EQ(view.parts.at(0).pieces.size(), 1u);
  EXPECT_TRUE(view.parts[0].pieces[0].holes.empty());
  EXPECT_EQ(view.parts[0].visible_area_2d, view.parts[0].area_2d);
  EXPECT_TRUE(view.blockers.empty());
}

TEST(BackprojectionFromVertex, OccluderCastsAnExactHole) {
  // V = (0, 0, 10); a small square-ish triangle at z = 5 casts a shadow scaled by 2 on the floor z = 0.
  const Scene s = soup({{Point3{0, 0, 10}, Point3{1, 0, 10}, Point3{0, 1, 10}},
                        {Point3{-1, -1, 5}, Point3{1, -1, 5}, Point3{0, 1, 5}},
                        {Point3{-10, -10, 0}, Point3{10, -10, 0}, Point3{0, 10, 0}}});
  const TriangleIndex index(s);
  const auto view = view_from_vertex(s, index, 0, 2);
  ASSERT_EQ(view.parts.at(0).pieces.size(), 1u);
  ASSERT_EQ(view.parts[0].pieces[0].holes.size(), 1u);
  // T (on z = 0, chart drops z): 20 * 20 / 2 = 200; the shadow: occluder area 2 scaled by 2^2 = 8.
  EXPECT_EQ(view.parts[0].area_2d, Exact(200));
  EXPECT_EQ(view.parts[0].visible_area_2d, Exact(192));
  EXPECT_EQ(view.blockers, (std::vector<std::int64_t>{1}));
}

TEST(BackprojectionFromVertex, RandomSoupsAgreeWithTheOracleOnSamples) {
  int seen = 0, hidden = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> c(0, 40);
    std::vector<std::array<Point3, 3>> tris;
    // The viewer's triangle high up, a receiver low, random occluders in between.
    tris.push_back({Point3{20, 20, 60}, Point3{21, 20, 61}, Point3{20, 21, 60}});
    tris.push_back({Point3{-10, -10, 0}, Point3{50, -5, 2}, Point3{15, 55, 1}});
    for (int k = 0; k < 6; ++k) {
      std::array<Point3, 3> t;
      for (auto& p : t) p = {double(c(rng)), double(c(rng)), double(10 + c(rng))};
      tris.push_back(t);
    }
    const Scene s = soup(tris);
    check_by_sampling(s, 0, 1, seed, &seen, &hidden);
  }
  EXPECT_GT(seen, 0);
  EXPECT_GT(hidden, 0);
}

}  // namespace
}  // namespace exactvis::shadows
