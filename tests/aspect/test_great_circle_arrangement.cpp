// Great-circle arrangements: vertex, arc and face counts against the independent great-circle oracle
// (tests/oracles/aspect_oracle: distinct intersection directions counted directly, Euler for the faces) on
// random circles with forced concurrencies; every cell's sample re-checked with the oracle's rationals
// (faces strictly off every circle, with pairwise different sign vectors; arcs on exactly their circle;
// vertices on exactly their circles); each arc's left face on the + side of its circle, its right face on
// the - side, and the two differing only there.
#include "aspect/great_circle_arrangement.hpp"

#include "oracles/aspect_oracle.hpp"
#include "tests/exact_to_mpq.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <stdexcept>

namespace {

using namespace exactvis;

using exact_to_mpq::q;
using exact_to_mpq::qv;

std::string signs_at(const std::vector<oracle::QVec>& normals, const oracle::QVec& d) {
  std::string s;
  for (const auto& n : normals) {
    const int g = oracle::sign(oracle::dot(n, d));
    s += g > 0 ? '+' : (g < 0 ? '-' : '0');
  }
  return s;
}

void check(const std::vector<Vec3<Exact>>& normals) {
  const GreatCircleArrangement A = great_circle_arrangement(normals);
  std::vector<oracle::QVec> qn;
  for (const auto& n : normals) qn.push_back(qv(n));
  const oracle::GreatCircleCounts c = oracle::great_circle_counts(qn);
  EXPECT_EQ(static_cast<std::int64_t>(A.vertices.size()), c.vertices);
  EXPECT_EQ(static_cast<std::int64_t>(A.arcs.size()), c.arcs);
  EXPECT_EQ(static_cast<std::int64_t>(A.faces.size()), c.faces);

  std::vector<std::string> face_signs;
  std::set<std::string> distinct;
  for (std::size_t f = 0; f < A.faces.size(); ++f) {
    const std::string s = signs_at(qn, qv(face_sample(A, static_cast<int>(f))));
    EXPECT_EQ(s.find('0'), std::string::npos) << "face " << f << " sample on a circle";
    face_signs.push_back(s);
    distinct.insert(s);
  }
  EXPECT_EQ(distinct.size(), A.faces.size()) << "two faces with one sign vector";
  for (std::size_t a = 0; a < A.arcs.size(); ++a) {
    const auto& arc = A.arcs[a];
    const std::string s = signs_at(qn, qv(arc_sample(A, normals, static_cast<int>(a))));
    ASSERT_EQ(s[arc.circle], '0');
    EXPECT_EQ(std::count(s.begin(), s.end(), '0'), 1) << "arc " << a;
    std::string left = s, right = s;
    left[arc.circle] = '+';
    right[arc.circle] = '-';
    EXPECT_EQ(face_signs[arc.left], left) << "arc " << a;
    EXPECT_EQ(face_signs[arc.right], right) << "arc " << a;
    EXPECT_EQ(signs_at(qn, qv(A.vertices[arc.from]))[arc.circle], '0');
    EXPECT_EQ(signs_at(qn, qv(A.vertices[arc.to]))[arc.circle], '0');
  }
  for (std::size_t v = 0; v < A.vertices.size(); ++v) {
    const std::string s = signs_at(qn, qv(A.vertices[v]));
    std::vector<int> on;
    for (std::size_t k = 0; k < s.size(); ++k)
      if (s[k] == '0') on.push_back(static_cast<int>(k));
    EXPECT_EQ(on, A.vertex_circles[v]) << "vertex " << v;
  }
}

TEST(GreatCircleArrangement, CoordinateCircles) {
  const std::vector<Vec3<Exact>> n{{Exact(1), Exact(0), Exact(0)}, {Exact(0), Exact(1), Exact(0)}, {Exact(0), Exact(0), Exact(1)}};
  const GreatCircleArrangement A = great_circle_arrangement(n);
  EXPECT_EQ(A.vertices.size(), 6u);
  EXPECT_EQ(A.arcs.size(), 12u);
  EXPECT_EQ(A.faces.size(), 8u);
  check(n);
}

TEST(GreatCircleArrangement, RandomWithConcurrentCircles) {
  std::mt19937_64 rng(16);
  std::uniform_int_distribution<int> coord(-4, 4);
  for (int trial = 0; trial < 30; ++trial) {
    std::set<std::array<Exact, 3>> seen;
    std::vector<Vec3<Exact>> n;
    const auto add = [&](Vec3<Exact> v) {
      if (v.x == 0 && v.y == 0 && v.z == 0) return;
      int a = 0;
      for (int i = 1; i < 3; ++i)
        if (CGAL::abs(v[i]) > CGAL::abs(v[a])) a = i;
      const Exact s = v[a];
      for (int i = 0; i < 3; ++i) v[i] /= s;
      if (seen.insert({v.x, v.y, v.z}).second) n.push_back(v);
    };
    const int m = 3 + trial % 6;
    // A common direction c: some circles are forced through it (vertices of degree > 2).
    const Vec3<Exact> c{Exact(coord(rng)), Exact(coord(rng)), Exact(1)};
    for (int i = 0; i < m; ++i) {
      const Vec3<Exact> r{Exact(coord(rng)), Exact(coord(rng)), Exact(coord(rng))};
      add(i % 2 == 0 ? cross(c, r) : r);
    }
    std::vector<oracle::QVec> qn;
    for (const auto& v : n) qn.push_back(qv(v));
    if (oracle::great_circle_counts(qn).circles < 3) continue;
    bool spans = false;
    for (std::size_t i = 0; i < n.size() && !spans; ++i)
      for (std::size_t j = i + 1; j < n.size() && !spans; ++j)
        for (std::size_t k = j + 1; k < n.size() && !spans; ++k) spans = dot(cross(n[i], n[j]), n[k]) != 0;
    if (!spans) continue;
    SCOPED_TRACE(trial);
    check(n);
  }
}

TEST(GreatCircleArrangement, RejectsDegenerateInput) {
  const Vec3<Exact> x{Exact(1), Exact(0), Exact(0)}, y{Exact(0), Exact(1), Exact(0)}, xy{Exact(1), Exact(1), Exact(0)};
  EXPECT_THROW(great_circle_arrangement({x, y, xy}), std::invalid_argument);  // all through +-z
  EXPECT_THROW(great_circle_arrangement({x, y, Exact(2) * x}), std::invalid_argument);
}

}  // namespace
