// FloatRayCaster (Embree) against an exact oracle: on rays whose exact first hit is unambiguous (the
// segment crosses the triangle's interior and no other triangle is hit at a nearby parameter), Embree must
// propose exactly that triangle; `ignore` skips triangles; rays that meet nothing report -1; triangles beyond
// float32 are left out. The oracle (tests/oracles/rational_geometry) shares no code with Embree or the kernel.
#include "kernel/float_ray_caster.hpp"
#include "oracles/rational_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace {

using namespace exactvis;
using oracle::qvec;

Scene random_triangles(unsigned seed, int n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(-10.0, 10.0), off(-1.5, 1.5);
  Scene s;
  for (int i = 0; i < n; ++i) {
    // float32 coordinates: Embree sees exactly the scene the oracle sees
    const auto f = [&](double x) { return static_cast<double>(static_cast<float>(x)); };
    const Point3 c{pos(rng), pos(rng), pos(rng)};
    SceneTriangle t;
    t.id = i;
    for (int k = 0; k < 3; ++k) {
      s.vertices.push_back({f(c.x + off(rng)), f(c.y + off(rng)), f(c.z + off(rng))});
      t.v[k] = static_cast<int>(s.vertices.size()) - 1;
    }
    s.triangles.push_back(t);
  }
  s.objects.push_back({"soup"});
  s.faces_read = n;
  return s;
}

// Exact first hit of the segment a -> b (parameter in [0, 1]) among the triangles not in `ignore`: the index,
// and whether the answer is unambiguous (a transversal crossing, next hit at a clearly larger parameter).
struct OracleHit {
  std::int64_t index = -1;
  bool clear = true;
};

OracleHit oracle_first_hit(const Scene& s, const Point3& a, const Point3& b, std::int64_t ignore) {
  const oracle::QVec qa = qvec(a.x, a.y, a.z), qb = qvec(b.x, b.y, b.z);
  struct Entry {
    mpq_class s;
    std::int64_t index;
    bool transversal;
  };
  std::vector<Entry> hits;
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    if (static_cast<std::int64_t>(i) == ignore) continue;
    const auto& t = s.triangles[i];
    const auto& p0 = s.vertices[t.v[0]];
    const auto& p1 = s.vertices[t.v[1]];
    const auto& p2 = s.vertices[t.v[2]];
    const auto q0 = qvec(p0.x, p0.y, p0.z), q1 = qvec(p1.x, p1.y, p1.z), q2 = qvec(p2.x, p2.y, p2.z);
    const auto range = oracle::segment_triangle_interval(qa, qb, q0, q1, q2);
    if (!range) continue;
    hits.push_back({range->first, static_cast<std::int64_t>(i),
                    oracle::oracle_segment_crosses_triangle_interior(qa, qb, q0, q1, q2)});
  }
  if (hits.empty()) return {};
  std::sort(hits.begin(), hits.end(), [](const Entry& x, const Entry& y) { return x.s < y.s; });
  OracleHit out;
  out.index = hits[0].index;
  out.clear = hits[0].transversal && hits[0].s > mpq_class(1, 1000) &&
              (hits.size() == 1 || hits[1].s - hits[0].s > mpq_class(1, 1000));
  return out;
}

TEST(FloatRayCaster, ProposesTheExactFirstHitOnClearRays) {
  const Scene s = random_triangles(7, 150);
  const FloatRayCaster caster(s);
  EXPECT_EQ(caster.size(), 150);
  EXPECT_EQ(caster.skipped(), 0);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(-12.0, 12.0);
  int clear = 0, hits = 0;
  for (int r = 0; r < 400; ++r) {
    const Point3 a{pos(rng), pos(rng), pos(rng)}, b{pos(rng), pos(rng), pos(rng)};
    const OracleHit want = oracle_first_hit(s, a, b, -1);
    if (!want.clear) continue;
    ++clear;
    hits += want.index >= 0;
    const glm::vec3 o(a.x, a.y, a.z), d(b.x - a.x, b.y - a.y, b.z - a.z);
    const auto got = caster.first_hit(o, d, 0.0f, 1.0f);
    ASSERT_EQ(got.triangle_index, want.index) << "ray " << r;
    EXPECT_EQ(caster.occluded(o, d, 0.0f, 1.0f), want.index >= 0) << "ray " << r;
  }
  EXPECT_GT(clear, 330);
  EXPECT_GT(hits, 50);  // the rays do hit things: the comparison is not vacuous
}

TEST(FloatRayCaster, IgnoreSkipsTheFirstHit) {
  const Scene s = random_triangles(3, 120);
  const FloatRayCaster caster(s);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> pos(-12.0, 12.0);
  int checked = 0;
  for (int r = 0; r < 800 && checked < 40; ++r) {
    const Point3 a{pos(rng), pos(rng), pos(rng)}, b{pos(rng), pos(rng), pos(rng)};
    const OracleHit first = oracle_first_hit(s, a, b, -1);
    if (!first.clear || first.index < 0) continue;
    const OracleHit second = oracle_first_hit(s, a, b, first.index);
    if (!second.clear) continue;
    const glm::vec3 o(a.x, a.y, a.z), d(b.x - a.x, b.y - a.y, b.z - a.z);
    const std::int64_t skip[] = {first.index};
    EXPECT_EQ(caster.first_hit(o, d, 0.0f, 1.0f, skip).triangle_index, second.index);
    EXPECT_EQ(caster.occluded(o, d, 0.0f, 1.0f, skip), second.index >= 0);
    ++checked;
  }
  EXPECT_GE(checked, 40);
}

TEST(FloatRayCaster, EmptySceneAndHugeCoordinates) {
  Scene empty;
  const FloatRayCaster none(empty);
  EXPECT_EQ(none.first_hit({0, 0, 0}, {1, 0, 0}, 0, 100).triangle_index, -1);
  EXPECT_FALSE(none.occluded({0, 0, 0}, {1, 0, 0}, 0, 100));

  Scene s;
  s.vertices = {{5, -1, -1}, {5, 1, -1}, {5, 0, 1}, {7, -1, -1}, {7, 1, -1}, {7, 0, 1e39}};
  s.triangles = {{0, {0, 1, 2}, 0}, {1, {3, 4, 5}, 0}};
  s.objects = {{"o"}};
  const FloatRayCaster caster(s);
  EXPECT_EQ(caster.size(), 1);
  EXPECT_EQ(caster.skipped(), 1);
  const auto hit = caster.first_hit({0, 0, 0}, {1, 0, 0}, 0, 100);
  EXPECT_EQ(hit.triangle_index, 0);
  EXPECT_FLOAT_EQ(hit.t, 5.0f);
  const std::int64_t skip[] = {0};
  EXPECT_EQ(caster.first_hit({0, 0, 0}, {1, 0, 0}, 0, 100, skip).triangle_index, -1);
}

}  // namespace
