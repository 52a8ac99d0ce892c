// shadows/eee_interval_split: the exact end-object split of EEE free intervals. Oracle: a brute-force first
// hit (tests/oracles segment-triangle intervals, GMP rationals, no kernel ray casting) at rational parameters
// inside every piece and next to its ends; and the line polynomials against eee_line_points.
#include "events/eee_enumeration.hpp"
#include "shadows/blocker_eee_events.hpp"
#include "shadows/eee_interval_split.hpp"
#include "kernel/rational_between.hpp"
#include "tests/shadows/shadow_test_scenes.hpp"

#include <gtest/gtest.h>

namespace exactvis::shadows {
namespace {

using shadow_test::object_triangles;

oracle::QVec q3(const Vec3<Exact>& v) { return shadow_test::oracle_point(v); }

// Stable id of the first closed triangle met by the open ray from o along d (-1: none), ties to the lowest
// index: the smallest entry parameter over all triangles of the segment [o, o + S d] (S beyond the scene).
std::int64_t oracle_first_hit(const Scene& s, const oracle::QVec& o, const oracle::QVec& d) {
  const mpq_class len2 = oracle::dot(d, d);
  const mpq_class S = mpq_class(1000000) / len2;  // |S d| = 10^6 / |d| >= 10^6 / ... : far beyond the box
  const oracle::QVec far = o + (S * mpq_class(1000)) * d;
  std::int64_t best = -1;
  mpq_class best_s;
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const auto& t = s.triangles[i];
    const auto a = s.corner(t, 0), b = s.corner(t, 1), c = s.corner(t, 2);
    const auto iv = oracle::segment_triangle_interval(o, far, oracle::qvec(a.x, a.y, a.z), oracle::qvec(b.x, b.y, b.z),
                                                      oracle::qvec(c.x, c.y, c.z));
    if (!iv) continue;
    mpq_class s0 = iv->first;
    if (s0 == 0 && iv->second == 0) continue;  // only the origin: not on the open ray
    if (best < 0 || s0 < best_s) {
      best = static_cast<std::int64_t>(i);
      best_s = s0;
    }
  }
  return best >= 0 ? s.triangles[best].id : -1;
}

TEST(EeeIntervalSplit, LinePolynomialsMatchTheEventsLines) {
  const Scene s = shadow_test::random_blocker_scene(3, 3);
  EeeOptions o;
  o.light_triangles = object_triangles(s, "lamp");
  o.parallel = false;
  const EeeResult r = enumerate_eee_events(s, o);
  ASSERT_FALSE(r.events.empty());
  for (const auto& e : r.events) {
    const EeeLinePolynomials l = eee_line_polynomials(s, e);
    for (const Exact t : {Exact(1, 7), Exact(5, 9), Exact(3, 2)}) {
      const EeeLinePoints p = eee_line_points(s, e, RootNumber(t));
      for (int k = 0; k < 3; ++k) EXPECT_EQ(RootNumber(l.d[k](t)), p.direction[k]);
      // The moment is on_e1 x direction.
      const Vec3<Exact> on{l.d[0](t), l.d[1](t), l.d[2](t)};
      Vec3<Exact> p1;
      ASSERT_TRUE(root_number_rational(p.on_e1.x, &p1.x) && root_number_rational(p.on_e1.y, &p1.y) &&
                  root_number_rational(p.on_e1.z, &p1.z));
      const Vec3<Exact> m = cross(p1, on);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(l.m[k](t), m[k]);
    }
  }
}

// Every piece's objects at three rational parameters inside it (middle, near each end) are the oracle's,
// and neighbouring pieces differ. Two stakes pierce the floor (the first hit passes from a stake to the floor
// where the lines cross their common segment) and each other.
TEST(EeeIntervalSplit, PiecesHaveTheOracleEndObjects) {
  int pieces = 0, multi = 0;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    Scene s = shadow_test::random_blocker_scene(200 + seed, 4);
    shadow_test::add_object(s, "stake0", {Point3{2, 3, -2}, Point3{8, 4, -2}, Point3{5, 6, 5}}, {{0, 1, 2}});
    shadow_test::add_object(s, "stake1", {Point3{3, 7, -2}, Point3{6, 1, -1}, Point3{4, 4, 4}}, {{0, 1, 2}});
    const std::vector<int> light = object_triangles(s, "lamp");
    EeeOptions o;
    o.light_triangles = light;
    o.parallel = false;
    EeeResult r = enumerate_eee_events(s, o);
    BlockerEvOptions bo;
    bo.parallel = false;
    for (auto& e : blocker_eee_events(s, light, bo).events) r.events.push_back(std::move(e));
    const TriangleIndex index(s);
    const Box3 box = bounding_box(s);
    int intervals = 0;
    for (const auto& e : r.events)
      for (const auto& iv : e.intervals) {
        if (++intervals > 60) break;
        const auto split = split_eee_interval(s, index, box, e, iv);
        ASSERT_FALSE(split.empty());
        EXPECT_EQ(split.front().t0, iv.t0);
        EXPECT_EQ(split.back().t1, iv.t1);
        multi += split.size() > 1;
        for (std::size_t k = 0; k < split.size(); ++k) {
          const auto& p = split[k];
          if (k > 0) {
            EXPECT_EQ(split[k - 1].t1, p.t0);
            EXPECT_TRUE(split[k - 1].front != p.front || split[k - 1].back != p.back);
          }
          const Exact mid = rational_strictly_between(p.t0, p.t1);
          Exact near0 = mid, near1 = mid;
          for (int j = 0; j < 12; ++j) {
            near0 = rational_strictly_between(p.t0, RootNumber(near0));
            near1 = rational_strictly_between(RootNumber(near1), p.t1);
          }
          for (const Exact& t : {mid, near0, near1}) {
            const auto g = eee_generator_segment(s, e, t);
            ASSERT_TRUE(g);
            EXPECT_EQ(oracle_first_hit(s, q3(g->front), q3(g->direction)), p.front) << "seed " << seed;
            EXPECT_EQ(oracle_first_hit(s, q3(g->back), q3(-g->direction)), p.back) << "seed " << seed;
          }
          ++pieces;
        }
      }
  }
  EXPECT_GT(pieces, 50);
  EXPECT_GT(multi, 5);
}

}  // namespace
}  // namespace exactvis::shadows
