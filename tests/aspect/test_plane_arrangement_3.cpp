// Plane arrangements: cell counts against the closed formula for simple arrangements and against the
// great-circle oracle for central ones; every cell's sample re-checked with the oracle's rationals.
#include "aspect/plane_arrangement_3.hpp"

#include "oracles/aspect_oracle.hpp"
#include "tests/exact_to_mpq.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace {

using namespace exactvis;

using exact_to_mpq::q;
using exact_to_mpq::qv;

std::int64_t choose(std::int64_t n, int k) {
  std::int64_t r = 1;
  for (int i = 0; i < k; ++i) r = r * (n - i) / (i + 1);
  return r;
}

int rank(const std::vector<oracle::QVec>& v) {
  int r = v.empty() ? 0 : 1;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j) {
      const oracle::QVec c = oracle::cross(v[i], v[j]);
      if (oracle::is_zero(c)) continue;
      r = std::max(r, 2);
      for (std::size_t k = j + 1; k < v.size(); ++k)
        if (oracle::dot(c, v[k]) != 0) return 3;
    }
  return r;
}

// Checks shared by every arrangement: samples have their sign vectors, sign vectors are distinct, facets
// are one dimension lower with conforming signs (zero where the facet is, equal elsewhere).
void check_cells(const std::vector<ArrangementPlane>& planes, const PlaneArrangement& a) {
  std::set<std::string> seen;
  for (const auto& c : a.cells) {
    EXPECT_TRUE(seen.insert(c.signs).second);
    std::vector<oracle::QVec> zero_normals;
    for (std::size_t k = 0; k < planes.size(); ++k) {
      const int s = oracle::sign(oracle::dot(qv(planes[k].normal), qv(c.sample)) - q(planes[k].offset));
      const char e = s > 0 ? '+' : (s < 0 ? '-' : '0');
      ASSERT_EQ(c.signs[k], e) << "plane " << k;
      if (e == '0') zero_normals.push_back(qv(planes[k].normal));
    }
    EXPECT_EQ(c.dimension, 3 - rank(zero_normals));
    for (int f : c.facets) {
      const auto& g = a.cells[f];
      EXPECT_EQ(g.dimension + 1, c.dimension);
      for (std::size_t k = 0; k < planes.size(); ++k) {
        EXPECT_TRUE(g.signs[k] == '0' || g.signs[k] == c.signs[k]);
      }
    }
    // Every cell of dimension >= 2 has a facet (an edge may be a whole line without vertices).
    if (c.dimension >= 2) {
      EXPECT_FALSE(c.facets.empty());
    }
  }
}

std::vector<ArrangementPlane> random_planes(std::mt19937& rng, int m, bool central) {
  std::uniform_int_distribution<int> c(-9, 9);
  std::vector<ArrangementPlane> p;
  while (static_cast<int>(p.size()) < m) {
    Vec3<Exact> n(c(rng), c(rng), c(rng));
    if (n.x == 0 && n.y == 0 && n.z == 0) continue;
    p.push_back({n, central ? Exact(0) : Exact(c(rng))});
  }
  return p;
}

TEST(PlaneArrangement, SimpleArrangementsMatchTheFaceCountFormula) {
  std::mt19937 rng(7);
  int simple = 0;
  for (int round = 0; round < 12; ++round) {
    const int m = 4 + round % 4;
    const auto planes = random_planes(rng, m, false);
    std::vector<std::pair<oracle::QVec, mpq_class>> op;
    for (const auto& p : planes) op.push_back({qv(p.normal), q(p.offset)});
    const PlaneArrangement a = plane_arrangement(planes);
    check_cells(planes, a);
    // Euler characteristic of R^3 with compact supports: f0 - f1 + f2 - f3 = -1, simple or not.
    EXPECT_EQ(a.vertices - a.edges + a.faces - a.volumes, -1);
    if (!oracle::plane_arrangement_is_simple(op)) continue;
    ++simple;
    EXPECT_EQ(a.vertices, choose(m, 3));
    EXPECT_EQ(a.edges, 3 * choose(m, 3) + choose(m, 2));
    EXPECT_EQ(a.faces, 3 * choose(m, 3) + 2 * choose(m, 2) + m);
    EXPECT_EQ(a.volumes, choose(m, 3) + choose(m, 2) + m + 1);
  }
  EXPECT_GE(simple, 6);
}

TEST(PlaneArrangement, CentralArrangementsAreTheGreatCircleArrangement) {
  std::mt19937 rng(11);
  for (int round = 0; round < 10; ++round) {
    auto planes = random_planes(rng, 3 + round % 6, true);
    // Distinct planes: drop repeated normal lines.
    std::vector<ArrangementPlane> distinct;
    std::set<std::array<mpq_class, 3>> keys;
    std::vector<oracle::QVec> normals;
    for (const auto& p : planes) {
      const auto n = qv(p.normal);
      mpq_class big = abs(n.x) > abs(n.y) ? abs(n.x) : abs(n.y);
      if (abs(n.z) > big) big = abs(n.z);
      std::array<mpq_class, 3> k{n.x / big, n.y / big, n.z / big};
      for (const auto& x : k)
        if (x != 0) {
          if (x < 0) for (auto& y : k) y = -y;
          break;
        }
      if (keys.insert(k).second) distinct.push_back(p), normals.push_back(n);
    }
    if (oracle::great_circle_counts(normals).circles < 3) continue;
    PlaneArrangement a;
    try {
      a = plane_arrangement(distinct);
    } catch (const std::invalid_argument&) {
      continue;  // coplanar normals
    }
    check_cells(distinct, a);
    const auto g = oracle::great_circle_counts(normals);
    EXPECT_EQ(a.vertices, 1);  // the origin
    EXPECT_EQ(a.edges, g.vertices);
    EXPECT_EQ(a.faces, g.arcs);
    EXPECT_EQ(a.volumes, g.faces);
  }
}

TEST(PlaneArrangement, RejectsNormalsThatDoNotSpanSpace) {
  std::vector<ArrangementPlane> p{{{1, 0, 0}, Exact(0)}, {{0, 1, 0}, Exact(1)}, {{1, 1, 0}, Exact(3)}};
  EXPECT_THROW(plane_arrangement(p), std::invalid_argument);
}

TEST(PlaneArrangement, ParallelAndConcurrentPlanes) {
  // The cube's six planes: 8 vertices, 12 lines each cut in 3 -> 36 edges, 6 planes with 9 faces each,
  // 27 volumes.
  std::vector<ArrangementPlane> p;
  for (int a = 0; a < 3; ++a)
    for (int s : {-1, 1}) {
      Vec3<Exact> n(0, 0, 0);
      n[a] = 1;
      p.push_back({n, Exact(s)});
    }
  const PlaneArrangement a = plane_arrangement(p);
  check_cells(p, a);
  EXPECT_EQ(a.vertices, 8);
  EXPECT_EQ(a.edges, 36);
  EXPECT_EQ(a.faces, 54);
  EXPECT_EQ(a.volumes, 27);
}

}  // namespace
