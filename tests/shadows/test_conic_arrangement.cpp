// shadows/conic_arrangement: faces of segments and conic arcs in the unit triangle. Oracles: closed-form
// areas (circular segments, the integral under a hyperbola) and exact polynomial signs at the samples (no
// code shared with the arrangement).
#include "shadows/conic_arrangement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace exactvis::shadows {
namespace {

using P = std::array<Exact, 2>;

P pt(long a, long b, long d) { return {Exact(a, d), Exact(b, d)}; }

bool strictly_in_triangle(const P& p) { return p[0] > 0 && p[1] > 0 && p[0] + p[1] < 1; }

// The quarter circle u^2 + v^2 = 1/4 from (1/2, 0) to (0, 1/2) through rational points.
ArrangementCurve quarter_circle() {
  ArrangementCurve c;
  c.points = {pt(5, 0, 10), pt(4, 3, 10), pt(3, 4, 10), pt(0, 5, 10)};
  c.conic = std::array<Exact, 6>{1, 0, 1, 0, 0, Exact(-1, 4)};
  return c;
}

Exact circle(const P& p) { return p[0] * p[0] + p[1] * p[1] - Exact(1, 4); }

TEST(ConicArrangement, QuarterDiscHasExactAreaAndSamples) {
  const ReceiverArrangement a = receiver_arrangement({quarter_circle()}, {pt(1, 1, 10), pt(4, 4, 10)});
  EXPECT_EQ(a.conic_arcs, 1u);
  EXPECT_EQ(a.chord_curves, 0u);
  ASSERT_EQ(a.faces.size(), 2u);
  const double pi = std::acos(-1.0);
  int inside = -1;
  for (std::size_t i = 0; i < a.faces.size(); ++i) {
    const auto& f = a.faces[i];
    EXPECT_TRUE(strictly_in_triangle(f.sample));
    EXPECT_TRUE(f.conic_bounded);
    ASSERT_NE(circle(f.sample), 0);
    if (circle(f.sample) < 0) {
      inside = static_cast<int>(i);
      EXPECT_NEAR(f.area_uv, pi / 16, 1e-7);
    } else {
      EXPECT_NEAR(f.area_uv, 0.5 - pi / 16, 1e-7);
    }
  }
  ASSERT_GE(inside, 0);
  ASSERT_EQ(a.query_faces.size(), 2u);
  EXPECT_EQ(a.query_faces[0], inside);
  EXPECT_EQ(a.query_faces[1], 1 - inside);
}

// A segment u + v = 0.705 cuts the arc (max of u + v on it is 1/sqrt 2 = 0.7071) but not the chord
// polyline through the arc's points (max 0.7): the thin lens between them is a face of the true arrangement
// that chords would miss.
TEST(ConicArrangement, LensBeyondTheChordsIsAFace) {
  ArrangementCurve seg;
  seg.points = {{Exact(1, 10), Exact(605, 1000)}, {Exact(605, 1000), Exact(1, 10)}};
  const ReceiverArrangement a = receiver_arrangement({quarter_circle(), seg});
  ASSERT_EQ(a.faces.size(), 3u);  // outside the disc (with two antennas), the disc below the line, the lens
  const double R = 0.5, d = 0.705 / std::sqrt(2.0);
  const double lens = R * R * std::acos(d / R) - d * std::sqrt(R * R - d * d);
  int lenses = 0;
  for (const auto& f : a.faces) {
    ASSERT_TRUE(strictly_in_triangle(f.sample));
    const Exact line = f.sample[0] + f.sample[1] - Exact(705, 1000);
    ASSERT_NE(circle(f.sample), 0);
    ASSERT_NE(line, 0);
    if (circle(f.sample) < 0 && line > 0) {
      ++lenses;
      EXPECT_NEAR(f.area_uv, lens, 1e-3 * lens);
    }
  }
  EXPECT_EQ(lenses, 1);
}

// The hyperbola u v = 1/16 from (1/2, 1/8) through (1/4, 1/4) to (1/8, 1/2) and its chord u + v = 5/8: the
// region between has area 15/128 - ln(4)/16.
TEST(ConicArrangement, HyperbolaArcAgainstItsChord) {
  ArrangementCurve h;
  h.points = {pt(4, 1, 8), pt(2, 2, 8), pt(1, 4, 8)};
  h.conic = std::array<Exact, 6>{0, 1, 0, 0, 0, Exact(-1, 16)};
  ArrangementCurve chord;
  chord.points = {pt(4, 1, 8), pt(1, 4, 8)};
  const ReceiverArrangement a = receiver_arrangement({h, chord});
  EXPECT_EQ(a.conic_arcs, 1u);
  ASSERT_EQ(a.faces.size(), 2u);
  const double area = 15.0 / 128 - std::log(4.0) / 16;
  int between = 0;
  for (const auto& f : a.faces) {
    ASSERT_TRUE(strictly_in_triangle(f.sample));
    const Exact hv = f.sample[0] * f.sample[1] - Exact(1, 16);
    const Exact lv = f.sample[0] + f.sample[1] - Exact(5, 8);
    if (hv > 0 && lv < 0) {
      ++between;
      EXPECT_NEAR(f.area_uv, area, 1e-6 * area);
    } else {
      EXPECT_NEAR(f.area_uv, 0.5 - area, 1e-6);
    }
  }
  EXPECT_EQ(between, 1);
}

// A degenerate conic (the line pair u v = 0) enters as its polyline, counted as a chord curve.
TEST(ConicArrangement, DegenerateConicFallsBackToPolyline) {
  ArrangementCurve c;
  c.points = {pt(2, 1, 8), pt(2, 2, 8), pt(2, 3, 8)};  // on u = 1/4, an antenna below the cut
  c.conic = std::array<Exact, 6>{1, 0, 0, Exact(-1, 4), 0, 0};  // u (u - 1/4) = 0: two parallel lines
  ArrangementCurve cut;
  cut.points = {pt(0, 1, 2), pt(1, 1, 2)};  // v = 1/2 from the side u = 0 to the hypotenuse
  const ReceiverArrangement a = receiver_arrangement({c, cut});
  EXPECT_EQ(a.conic_arcs, 0u);
  EXPECT_EQ(a.chord_curves, 1u);
  ASSERT_EQ(a.faces.size(), 2u);
  double total = 0;
  for (const auto& f : a.faces) {
    EXPECT_TRUE(strictly_in_triangle(f.sample));
    EXPECT_FALSE(f.conic_bounded);
    total += f.area_uv;
  }
  EXPECT_NEAR(total, 0.5, 1e-15);
}

// Many queries in an arrangement of random chords (each from one side of the triangle to another) and three
// quarter circles about the origin (each from the side v = 0 to the side u = 0): every curve separates the
// triangle, so a query and the sample of the face it is located in lie on the same side of every chord's
// line and every circle (exact signs of the curves' polynomials, no code shared with the location). Checks
// the batched point location and its matching of results back to the queries.
TEST(ConicArrangement, QueriesLandInFacesOnTheSameSideOfEveryCurve) {
  std::mt19937_64 rng(20261202);
  auto rnd = [&](long d) { return Exact(static_cast<long>(rng() % static_cast<unsigned long>(d - 1)) + 1, d); };
  auto side_point = [&](int side) -> P {
    const Exact t = rnd(997);
    if (side == 0) return {t, Exact(0)};       // v = 0
    if (side == 1) return {Exact(0), t};       // u = 0
    return {t, 1 - t};                         // u + v = 1
  };
  std::vector<ArrangementCurve> curves;
  std::vector<std::array<P, 2>> chords;
  for (int k = 0; k < 8; ++k) {
    const int s0 = static_cast<int>(rng() % 3), s1 = (s0 + 1 + static_cast<int>(rng() % 2)) % 3;
    ArrangementCurve c;
    c.points = {side_point(s0), side_point(s1)};
    chords.push_back({c.points[0], c.points[1]});
    curves.push_back(c);
  }
  const std::vector<Exact> radii{Exact(1, 5), Exact(2, 5), Exact(3, 5)};
  for (const Exact& r : radii) {
    ArrangementCurve c;
    c.points = {{r, Exact(0)}, {r * Exact(4, 5), r * Exact(3, 5)}, {r * Exact(3, 5), r * Exact(4, 5)}, {Exact(0), r}};
    c.conic = std::array<Exact, 6>{1, 0, 1, 0, 0, -r * r};
    curves.push_back(c);
  }
  auto signs = [&](const P& p) {
    std::vector<int> out;
    for (const auto& [a, b] : chords)
      out.push_back(CGAL::sign((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])));
    for (const Exact& r : radii) out.push_back(CGAL::sign(p[0] * p[0] + p[1] * p[1] - r * r));
    return out;
  };
  std::vector<P> queries;
  while (queries.size() < 300) {
    const P q{rnd(1009), rnd(1013)};
    if (!strictly_in_triangle(q)) continue;
    const auto sv = signs(q);
    if (std::find(sv.begin(), sv.end(), 0) != sv.end()) continue;  // on a curve's line: no oracle
    queries.push_back(q);
  }
  const ReceiverArrangement a = receiver_arrangement(curves, queries);
  ASSERT_FALSE(a.failed) << a.failure;
  EXPECT_EQ(a.conic_arcs, 3u);
  ASSERT_EQ(a.query_faces.size(), queries.size());
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const int f = a.query_faces[k];
    ASSERT_GE(f, 0) << "query " << k;
    ASSERT_LT(f, static_cast<int>(a.faces.size()));
    EXPECT_EQ(signs(queries[k]), signs(a.faces[f].sample)) << "query " << k << " in face " << f;
  }
}

}  // namespace
}  // namespace exactvis::shadows
