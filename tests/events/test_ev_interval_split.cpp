// Splitting EV free intervals where the end objects change (events/ev_interval_split.hpp): on each piece the
// reported objects are the first hits at many exact sample parameters (independent ray oracle,
// tests/events/ev_oracle.hpp), neighbours split inside one free interval differ, and the pieces re-join into
// exactly the unsplit free intervals.
#include "events/ev_events.hpp"
#include "kernel/predicates.hpp"
#include "tests/events/ev_oracle.hpp"
#include "tests/events/event_test_scenes.hpp"

#include <gtest/gtest.h>

#include <random>

namespace exactvis {
namespace {

using namespace event_test;

// The reported object is a first hit of the ray (or none when the oracle finds none).
void expect_first_hit(const Scene& s, const ev_oracle::Mesh& m, const ev_oracle::P3& origin, const ev_oracle::P3& dir,
                      std::int64_t got, const std::string& what) {
  mpq_class best;
  const bool any = ev_oracle::first_entry(m, origin, dir, &best);
  ASSERT_EQ(got >= 0, any) << what;
  if (!any) return;
  const auto& tri = m.t[s.index_of_id(got)];
  mpq_class mine;
  ASSERT_TRUE(ev_oracle::ray_entry(origin, dir, m.v[tri[0]], m.v[tri[1]], m.v[tri[2]], &mine)) << what;
  EXPECT_EQ(mine, best) << what;
}

TEST(EvIntervalSplit, EndObjectsConstantOnEachPieceAndPiecesRejoin) {
  int splits = 0, pieces_checked = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const Scene s = random_soup(4000 + seed, 9, 8);
    const ev_oracle::Mesh m = to_oracle(s);
    EvOptions unsplit_opt;
    unsplit_opt.split_at_end_objects = false;
    const auto split = enumerate_ev_events(s);
    const auto unsplit = enumerate_ev_events(s, unsplit_opt);
    ASSERT_EQ(split.events.size(), unsplit.events.size());
    for (std::size_t e = 0; e < split.events.size(); ++e) {
      const auto& ev = split.events[e];
      // Re-join pieces across EndObjectChange ends: the unsplit intervals.
      std::vector<std::pair<RootNumber, RootNumber>> joined;
      for (std::size_t i = 0; i < ev.intervals.size(); ++i) {
        const auto& iv = ev.intervals[i];
        EXPECT_LT(iv.t0, iv.t1);
        if (iv.end0.cause == CriticalEnd::Cause::EndObjectChange) {
          ASSERT_GT(i, 0u);
          const auto& prev = ev.intervals[i - 1];
          EXPECT_EQ(prev.t1, iv.t0);
          EXPECT_EQ(prev.end1.cause, CriticalEnd::Cause::EndObjectChange);
          EXPECT_TRUE(prev.front_object != iv.front_object || prev.back_object != iv.back_object);
          joined.back().second = iv.t1;
          ++splits;
        } else {
          joined.emplace_back(iv.t0, iv.t1);
        }
      }
      const auto& un = unsplit.events[e];
      ASSERT_EQ(joined.size(), un.intervals.size()) << "seed " << seed;
      for (std::size_t i = 0; i < joined.size(); ++i) {
        EXPECT_EQ(joined[i].first, un.intervals[i].t0);
        EXPECT_EQ(joined[i].second, un.intervals[i].t1);
      }
      // Objects at many exact parameters strictly inside each piece.
      const auto& V = s.vertices[ev.vertex];
      const auto& A = s.vertices[ev.edge[0]];
      const auto& B = s.vertices[ev.edge[1]];
      const ev_oracle::P3 OV{V.x, V.y, V.z}, OA{A.x, A.y, A.z}, OB{B.x, B.y, B.z};
      for (const auto& iv : ev.intervals) {
        auto q = [](const Exact& x) {
          mpq_class r(to_rational_string(x));
          r.canonicalize();
          return r;
        };
        const mpq_class t0 = q(rational_parameter(iv.t0)), t1 = q(rational_parameter(iv.t1)), ts = q(iv.sample_t);
        EXPECT_TRUE(ts > t0 && ts < t1);
        // Generic parameters (large prime denominator: not on the small-denominator breakpoints of these
        // small-integer scenes, where an isolated line may see a different object), near both ends and across.
        std::vector<mpq_class> samples{ts};
        const mpq_class p(10007);
        for (int k = 0; k < 5; ++k) samples.push_back(t0 + (t1 - t0) * (mpq_class(k * 2001 + 1) / p));
        samples.push_back(t1 - (t1 - t0) / p);
        for (const auto& t : samples) {
          const ev_oracle::P3 P = OA + t * (OB - OA);
          const ev_oracle::P3 d = P - OV;
          const std::string what = "seed " + std::to_string(seed) + " V=" + std::to_string(ev.vertex) + " t=" + t.get_str();
          expect_first_hit(s, m, P, d, iv.front_object, what + " beyond");
          expect_first_hit(s, m, OV, mpq_class(-1) * d, iv.back_object, what + " behind");
        }
        ++pieces_checked;
      }
    }
  }
  EXPECT_GT(splits, 20);  // real splits happened
  EXPECT_GT(pieces_checked, 200);
}

// By hand: V above a floor made of two triangles meeting along the diagonal x = y; the wedge to an edge
// above the floor sweeps the floor across the diagonal, so its one free interval is split there.
TEST(EvIntervalSplit, FloorDiagonalSplitsTheWedge) {
  const std::vector<Point3> v{{-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0},  // floor
                              {0, 0, 8},                                               // V (a lone triangle's corner)
                              {1, 0, 9}, {0, 1, 9},
                              {-4, 2, 4}, {4, 2, 4}, {0, 2, 6}};                         // edge (7, 8) y = 2, z = 4
  const Scene s = make_scene(v, {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {7, 8, 9}});
  const auto r = enumerate_ev_events(s);
  const EvEvent* found = nullptr;
  for (const auto& ev : r.events)
    if (ev.vertex == 4 && ev.edge == std::array<int, 2>{7, 8}) found = &ev;
  ASSERT_NE(found, nullptr);
  // Line from (0,0,8) through (-4 + 8t, 2, 4) meets z = 0 at (-8 + 16t, 4): on the diagonal when t = 3/4.
  ASSERT_EQ(found->intervals.size(), 2u);
  EXPECT_EQ(found->intervals[0].t0, 0);
  EXPECT_EQ(found->intervals[0].t1, Exact(3, 4));
  EXPECT_EQ(found->intervals[1].t1, 1);
  EXPECT_EQ(found->intervals[0].end1.cause, CriticalEnd::Cause::EndObjectChange);
  EXPECT_EQ(found->intervals[0].front_object, 1);  // (0, 2, 3): y > x
  EXPECT_EQ(found->intervals[1].front_object, 0);  // (0, 1, 2): y < x
}

}  // namespace
}  // namespace exactvis
