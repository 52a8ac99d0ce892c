// The triangle index against brute force: candidate box queries vs a naive bounding-box overlap test,
// segment queries must contain every triangle the independent rational oracle says the closed segment meets
// (including touching at vertices and edges) and nothing whose bounding box misses the segment's; exact box
// queries contain every triangle with a corner in the box and nothing whose bounding box misses it;
// concurrent queries agree.
#include "kernel/scene_generators.hpp"
#include "kernel/triangle_index.hpp"

#include "oracles/rational_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <thread>

using namespace exactvis;

namespace {

Box3 corner_box(const Scene& s, const SceneTriangle& t) {
  Box3 b{s.corner(t, 0), s.corner(t, 0)};
  for (int k = 1; k < 3; ++k) {
    const Point3& p = s.corner(t, k);
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
  }
  return b;
}

bool boxes_meet(const Box3& a, const Box3& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

std::vector<std::int64_t> naive_in_box(const Scene& s, const Box3& q) {
  std::vector<std::int64_t> out;
  if (q.empty()) return out;
  for (size_t i = 0; i < s.triangles.size(); ++i)
    if (boxes_meet(corner_box(s, s.triangles[i]), q)) out.push_back(static_cast<std::int64_t>(i));
  return out;
}

oracle::QVec qv(const Point3& p) { return oracle::qvec(p.x, p.y, p.z); }

double grid(std::mt19937_64& rng, double lo, double hi) {  // a multiple of 1/64 in [lo, hi]
  const std::int64_t a = static_cast<std::int64_t>(lo * 64), b = static_cast<std::int64_t>(hi * 64);
  return static_cast<double>(a + static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(b - a + 1))) / 64;
}

}  // namespace

TEST(TriangleIndex, BoxQueriesMatchBruteForce) {
  for (const std::string kind : {"random", "town", "room"}) {
    const Scene s = generate_scene(kind, 3000, 11);
    const TriangleIndex index(s);
    EXPECT_EQ(index.size(), 3000);
    const Box3 all = bounding_box(s);
    std::mt19937_64 rng(5);
    for (int q = 0; q < 300; ++q) {
      Box3 b;
      for (int k = 0; k < 3; ++k) {
        double a = grid(rng, all.lo[k] - 1, all.hi[k] + 1), c = grid(rng, all.lo[k] - 1, all.hi[k] + 1);
        if (q % 3 == 0) c = a + grid(rng, 0, 2);  // small boxes
        if (q % 7 == 0) c = a;                    // flat boxes (closedness matters on the grid)
        b.lo[k] = std::min(a, c);
        b.hi[k] = std::max(a, c);
      }
      ASSERT_EQ(index.candidates_in_box(b), naive_in_box(s, b)) << kind << " query " << q;
    }
    // Boxes exactly touching a triangle's bounding box at a corner are closed: must be reported.
    for (size_t i = 0; i < s.triangles.size(); i += 97) {
      const Box3 tb = corner_box(s, s.triangles[i]);
      const Box3 corner{tb.hi, {tb.hi.x + 1, tb.hi.y + 1, tb.hi.z + 1}};
      const auto r = index.candidates_in_box(corner);
      EXPECT_TRUE(std::binary_search(r.begin(), r.end(), static_cast<std::int64_t>(i)));
      ASSERT_EQ(r, naive_in_box(s, corner));
    }
    EXPECT_TRUE(index.candidates_in_box(Box3{{1, 1, 1}, {0, 0, 0}}).empty());
  }
}

TEST(TriangleIndex, SegmentQueriesContainEveryTriangleMet) {
  const Scene s = generate_scene("town", 2000, 3);
  const TriangleIndex index(s);
  const Box3 all = bounding_box(s);
  std::mt19937_64 rng(17);
  auto random_point = [&] {
    return Point3{grid(rng, all.lo.x, all.hi.x), grid(rng, all.lo.y, all.hi.y), grid(rng, all.lo.z, all.hi.z)};
  };
  int hits = 0;
  for (int q = 0; q < 200; ++q) {
    Point3 a = random_point(), b = random_point();
    if (q % 4 == 1) {
      // Through a vertex of a triangle (touching cases): from the vertex outwards, or passing through it.
      const auto& t = s.triangles[rng() % s.triangles.size()];
      a = s.corner(t, static_cast<int>(rng() % 3));
      if (q % 8 == 1) b = {2 * a.x - b.x, 2 * a.y - b.y, 2 * a.z - b.z};
    } else if (q % 4 == 2) {
      // Through an edge midpoint (exact: sums of multiples of 1/64 halve exactly).
      const auto& t = s.triangles[rng() % s.triangles.size()];
      const Point3 p = s.corner(t, 0), r = s.corner(t, 1);
      const Point3 m{(p.x + r.x) / 2, (p.y + r.y) / 2, (p.z + r.z) / 2};
      a = {2 * m.x - b.x, 2 * m.y - b.y, 2 * m.z - b.z};
    } else if (q % 4 == 3) {
      b = a;  // a point
    }
    const auto result = index.triangles_meeting_segment(a, b);
    ASSERT_TRUE(std::is_sorted(result.begin(), result.end()));
    const Box3 sb{{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
                  {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
    const auto candidates = naive_in_box(s, sb);
    for (auto i : result) ASSERT_TRUE(std::binary_search(candidates.begin(), candidates.end(), i)) << "query " << q;
    for (auto i : candidates) {
      const auto& t = s.triangles[i];
      const bool meets = a == b ? oracle::oracle_point_in_closed_triangle(qv(a), qv(s.corner(t, 0)), qv(s.corner(t, 1)), qv(s.corner(t, 2)))
                                : oracle::oracle_closed_segment_meets_closed_triangle(qv(a), qv(b), qv(s.corner(t, 0)),
                                                                                     qv(s.corner(t, 1)), qv(s.corner(t, 2)));
      if (meets) {
        ++hits;
        ASSERT_TRUE(std::binary_search(result.begin(), result.end(), i)) << "query " << q << " misses triangle " << i;
      }
    }
  }
  EXPECT_GT(hits, 100);  // the queries really exercise hits
}

TEST(TriangleIndex, ConcurrentQueriesAgree) {
  const Scene s = generate_scene("forest", 5000, 8);
  const TriangleIndex index(s);
  const Box3 all = bounding_box(s);
  std::vector<Box3> queries;
  std::mt19937_64 rng(3);
  for (int q = 0; q < 400; ++q) {
    Box3 b;
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = grid(rng, all.lo[k], all.hi[k]);
      b.hi[k] = b.lo[k] + grid(rng, 0, 4);
    }
    queries.push_back(b);
  }
  std::vector<std::vector<std::int64_t>> expected;
  for (const auto& q : queries) expected.push_back(index.candidates_in_box(q));
  std::vector<int> mismatches(4, 0);
  std::vector<std::thread> threads;
  const TriangleIndex copy = index;  // copies share the tree
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (size_t q = 0; q < queries.size(); ++q) {
        const auto& idx = (t % 2 == 0) ? index : copy;
        if (idx.candidates_in_box(queries[q]) != expected[q]) ++mismatches[t];
        const Point3 a = queries[q].lo, b = queries[q].hi;
        if (idx.triangles_meeting_segment(a, b) != index.triangles_meeting_segment(a, b)) ++mismatches[t];
      }
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(mismatches, (std::vector<int>(4, 0)));
}

TEST(TriangleIndex, EmptyAndSingle) {
  const TriangleIndex empty;
  EXPECT_TRUE(empty.candidates_in_box({{0, 0, 0}, {1, 1, 1}}).empty());
  EXPECT_TRUE(empty.triangles_meeting_segment({0, 0, 0}, {1, 1, 1}).empty());
  Scene one;
  one.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  one.triangles = {{0, {0, 1, 2}, 0}};
  one.objects = {{"t"}};
  const TriangleIndex index(one);
  EXPECT_EQ(index.candidates_in_box({{1, 0, 0}, {2, 2, 2}}), (std::vector<std::int64_t>{0}));
  EXPECT_TRUE(index.candidates_in_box({{1.5, 0, 0}, {2, 2, 2}}).empty());
  EXPECT_EQ(index.triangles_meeting_segment({0.5, 0.5, -1}, {0.5, 0.5, 1}), (std::vector<std::int64_t>{0}));  // on the edge
  EXPECT_TRUE(index.triangles_meeting_segment({0.5, 0.5000001, -1}, {0.5, 0.5000001, 1}).empty());
  EXPECT_EQ(index.triangles_meeting_segment({0, 1, 0}, {0, 1, 0}), (std::vector<std::int64_t>{0}));  // a corner point
}

namespace {

bool corner_inside(const Point3& p, const Box3& b) {
  return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y && p.z >= b.lo.z && p.z <= b.hi.z;
}

bool bbox_disjoint(const std::array<Point3, 3>& c, const Box3& b) {
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = std::min({c[0][axis], c[1][axis], c[2][axis]});
    const double hi = std::max({c[0][axis], c[1][axis], c[2][axis]});
    if (hi < b.lo[axis] || lo > b.hi[axis]) return true;
  }
  return false;
}

}  // namespace

// (was OccluderIndex.TrianglesInBoxBruteForce) Necessary conditions only.
TEST(TriangleIndex, TrianglesMeetingBoxBruteForce) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-10, 10), size(0.1, 4);
  for (int round = 0; round < 20; ++round) {
    Scene s;
    for (int k = 0; k < 200; ++k) {
      const int b = static_cast<int>(s.vertices.size());
      const Point3 c{u(rng), u(rng), u(rng)};
      for (int q = 0; q < 3; ++q) s.vertices.push_back({c.x + size(rng), c.y - size(rng), c.z + size(rng) - 2});
      s.triangles.push_back({k, {b, b + 1, b + 2}, 0});
    }
    s.objects.push_back({"test"});
    const TriangleIndex index(s);
    for (int q = 0; q < 20; ++q) {
      const Point3 a{u(rng), u(rng), u(rng)}, d{u(rng), u(rng), u(rng)};
      const Box3 box{{std::min(a.x, d.x), std::min(a.y, d.y), std::min(a.z, d.z)},
                     {std::max(a.x, d.x), std::max(a.y, d.y), std::max(a.z, d.z)}};
      const std::vector<std::int64_t> got = index.triangles_meeting_box(box);
      EXPECT_TRUE(std::is_sorted(got.begin(), got.end()));
      for (int ti = 0; ti < static_cast<int>(s.triangles.size()); ++ti) {
        const auto& t = s.triangles[ti];
        const std::array<Point3, 3> c{s.corner(t, 0), s.corner(t, 1), s.corner(t, 2)};
        const bool returned = std::binary_search(got.begin(), got.end(), static_cast<std::int64_t>(ti));
        if (corner_inside(c[0], box) || corner_inside(c[1], box) || corner_inside(c[2], box)) {
          EXPECT_TRUE(returned) << "triangle with a corner in the box not returned";
        }
        if (bbox_disjoint(c, box)) {
          EXPECT_FALSE(returned) << "triangle far from the box returned";
        }
      }
    }
  }
}

// Exact triangle queries against the rational oracle: closed triangles meet iff an edge of one meets the
// other (their intersection is convex; its relative boundary lies on the triangles' boundaries).
TEST(TriangleIndex, TrianglesMeetingTriangleMatchOracle) {
  const Scene s = generate_scene("random", 600, 21);
  const TriangleIndex index(s);
  const Box3 all = bounding_box(s);
  std::mt19937_64 rng(29);
  int hits = 0;
  for (int q = 0; q < 60; ++q) {
    std::array<Point3, 3> c;
    for (auto& p : c) p = {grid(rng, all.lo.x, all.hi.x), grid(rng, all.lo.y, all.hi.y), grid(rng, all.lo.z, all.hi.z)};
    if (q % 3 == 0) c[0] = s.corner(s.triangles[rng() % s.triangles.size()], 0);  // touching at a corner
    const auto got = index.triangles_meeting_triangle(c[0], c[1], c[2]);
    ASSERT_TRUE(std::is_sorted(got.begin(), got.end()));
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
      const auto& t = s.triangles[i];
      const std::array<Point3, 3> d{s.corner(t, 0), s.corner(t, 1), s.corner(t, 2)};
      bool meets = false;
      for (int k = 0; k < 3 && !meets; ++k) {
        meets = oracle::oracle_closed_segment_meets_closed_triangle(qv(c[k]), qv(c[(k + 1) % 3]), qv(d[0]), qv(d[1]), qv(d[2])) ||
                oracle::oracle_closed_segment_meets_closed_triangle(qv(d[k]), qv(d[(k + 1) % 3]), qv(c[0]), qv(c[1]), qv(c[2]));
      }
      hits += meets;
      ASSERT_EQ(std::binary_search(got.begin(), got.end(), static_cast<std::int64_t>(i)), meets) << "query " << q << " triangle " << i;
    }
  }
  EXPECT_GT(hits, 30);
}
