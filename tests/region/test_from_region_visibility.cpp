// From-region visibility against the independent oracle (tests/oracles/visibility_oracle): every "visible"
// carries a witness re-checked exactly; every "hidden" is attacked by random segments. Hand-built scenes
// pin down the degenerate rules (touching = blocked, measure-zero apertures hidden, coplanar and
// edge-sharing occluders) with their known answers.
#include "region/from_region_visibility.hpp"

#include "oracles/visibility_oracle.hpp"
#include "tests/region/region_scene_builder.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {

using region_test::SceneBuilder;

oracle::QVec qv(const Point3& p) { return oracle::qvec(p.x, p.y, p.z); }
oracle::QVec qv(const RationalPoint3& p) {
  return {mpq_class(p.x.mpq()), mpq_class(p.y.mpq()), mpq_class(p.z.mpq())};
}

std::vector<oracle::Triangle> oracle_scene(const Scene& s) {
  std::vector<oracle::Triangle> out;
  for (const auto& t : s.triangles) out.push_back({qv(s.corner(t, 0)), qv(s.corner(t, 1)), qv(s.corner(t, 2))});
  return out;
}

oracle::Source oracle_source(const Polygon3& poly) {
  oracle::Source s;
  for (const auto& p : poly) s.polygon.push_back(qv(p));
  return s;
}
oracle::Source oracle_source(const Box3& b) {
  oracle::Source s;
  s.is_box = true;
  s.lo = qv(b.lo);
  s.hi = qv(b.hi);
  return s;
}

Polygon3 polygon(std::initializer_list<Point3> pts) {
  Polygon3 out;
  for (const auto& p : pts) out.push_back(to_rational(p));
  return out;
}

// Check one answer against the oracle; returns the answer. The query runs twice: with random-segment early
// acceptance and with none (samples = 0, so the exact CSG decides); both answers must agree.
template <class Src>
bool checked_visible(const Scene& scene, const Src& src, std::int64_t target, int refute_samples = 400) {
  const auto os = oracle_scene(scene);
  bool answers[2];
  for (int samples : {48, 0}) {
    VisibilityOptions opt;
    opt.samples = samples;
    VisibilityResult r;
    if constexpr (std::is_same_v<Src, Box3>) r = visible_from_box(scene, brute_force_candidates(scene), src, target, opt);
    else r = visible_from_polygon(scene, brute_force_candidates(scene), src, target, opt);
    answers[samples == 0] = r.visible;
    if (r.visible) {
      EXPECT_TRUE(r.witness.has_value());
      if (r.witness) {
        std::string why;
        EXPECT_TRUE(oracle::witness_is_valid(os, static_cast<std::size_t>(target), oracle_source(src),
                                             qv(r.witness->p), qv(r.witness->q), &why))
            << "triangle " << target << ": " << why;
      }
    } else if (samples == 0) {
      const auto refute = oracle::find_robust_free_segment(os, static_cast<std::size_t>(target), oracle_source(src),
                                                           refute_samples, 1000 + static_cast<unsigned long>(target));
      EXPECT_FALSE(refute.has_value()) << "triangle " << target << " reported hidden but a free segment exists";
    }
  }
  EXPECT_EQ(answers[0], answers[1]) << "triangle " << target << ": sampling and exact CSG disagree";
  return answers[1];
}

}  // namespace

TEST(FromRegionVisibility, EmptySceneSeesEverything) {
  SceneBuilder b;
  const auto t = b.triangle({10, -1, -1}, {10, 1, -1}, {10, 0, 1});
  EXPECT_TRUE(checked_visible(b.scene, polygon({{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}}), t));
}

TEST(FromRegionVisibility, SlitOfWidth1e9IsVisibleTouchingSlitIsHidden) {
  const Polygon3 src = polygon({{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}});
  for (double w : {1e-9, 0.0, -1e-9}) {
    SceneBuilder b;
    const auto t = b.triangle({10, -1, -1}, {10, 1, -1}, {10, 0, 1});
    b.quad({5, -10, -10}, {5, -w / 2, -10}, {5, -w / 2, 10}, {5, -10, 10});
    b.quad({5, w / 2, -10}, {5, 10, -10}, {5, 10, 10}, {5, w / 2, 10});
    EXPECT_EQ(checked_visible(b.scene, src, t), w > 0) << "slit width " << w;
  }
}

TEST(FromRegionVisibility, GrazingAndMeasureZeroAperturesAreHidden) {
  // Occluder covers y >= 0 at x = 5. Lines from the source (y in [-1,1], x = 0) to a target at x = 10 with
  // y >= 1 pass x = 5 at y = (ys + yt) / 2 >= 0: only the grazing lines ys = -1, yt = 1 touch y = 0.
  const Polygon3 src = polygon({{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}});
  SceneBuilder b;
  const auto hidden = b.triangle({10, 1, -1}, {10, 3, -1}, {10, 1, 1});
  const auto visible = b.triangle({10, 0.5, -1}, {10, 3, -1}, {10, 0.5, 1});
  b.quad({5, 0, -10}, {5, 10, -10}, {5, 10, 10}, {5, 0, 10});
  EXPECT_FALSE(checked_visible(b.scene, src, hidden));
  EXPECT_TRUE(checked_visible(b.scene, src, visible));
}

TEST(FromRegionVisibility, ClosedCubeOnlyFacingTrianglesVisible) {
  SceneBuilder b;
  b.box({-1, -1, -1}, {1, 1, 1});
  const Polygon3 src = polygon({{5, -0.5, -0.5}, {5, 0.5, -0.5}, {5, 0.5, 0.5}, {5, -0.5, 0.5}});
  for (std::int64_t t = 0; t < 12; ++t) EXPECT_EQ(checked_visible(b.scene, src, t), t < 2) << "triangle " << t;
  // A wide source sees the +x face and the four side faces, never the back face.
  const Polygon3 wide = polygon({{5, -3, -3}, {5, 3, -3}, {5, 3, 3}, {5, -3, 3}});
  for (std::int64_t t = 0; t < 12; ++t) EXPECT_EQ(checked_visible(b.scene, wide, t), t < 2 || t >= 4) << t;
}

TEST(FromRegionVisibility, GroundCoplanarWithBuildingBottom) {
  SceneBuilder b;
  b.box({0, 0, 0}, {2, 2, 2});  // triangles 10, 11 = bottom (z = 0), 8, 9 = top
  b.quad({-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0});  // 12, 13: ground, coplanar with the bottom
  const Box3 cell{{-5, -5, 8}, {7, 7, 9}};
  for (std::int64_t t = 0; t < 14; ++t) EXPECT_EQ(checked_visible(b.scene, cell, t), t != 10 && t != 11) << t;
}

TEST(FromRegionVisibility, BoxBehindTargetDoesNotHideIt) {
  SceneBuilder b;
  const auto t = b.triangle({5, -1, -1}, {5, 1, -1}, {5, 0, 1});
  b.box({5, -2, -2}, {8, 2, 2});  // shares the plane x = 5 with the target, behind it
  const Box3 cell{{-2, -1, -1}, {-1, 1, 1}};
  EXPECT_TRUE(checked_visible(b.scene, cell, t));
  for (std::int64_t o = 1; o < 13; ++o) checked_visible(b.scene, cell, o);
}

TEST(FromRegionVisibility, OccludersSharingEdgesWithTheTarget) {
  // A fan of triangles around a vertex, some folded towards the source: the target's neighbours share its
  // edges; visibility must follow the geometry, not the shared edges.
  SceneBuilder b;
  const Point3 c{0, 0, 0};
  const Point3 r[6] = {{2, 0, 0}, {1, 2, 0.5}, {-1, 2, 0}, {-2, 0, 1}, {-1, -2, 0}, {1, -2, -0.5}};
  for (int i = 0; i < 6; ++i) b.triangle(c, r[i], r[(i + 1) % 6]);
  const Box3 above{{-1, -1, 4}, {1, 1, 5}};
  const Box3 below{{-1, -1, -5}, {1, 1, -4}};
  for (std::int64_t t = 0; t < 6; ++t) {
    checked_visible(b.scene, above, t);
    checked_visible(b.scene, below, t);
  }
}

TEST(FromRegionVisibility, ThreeOccluderEdgesOnOneRegulus) {
  // Rulings of one regulus of the hyperboloid x^2 + y^2 - z^2 = 1: (cos t, sin t, 0) + s (-sin t, cos t, 1) for
  // (cos t, sin t) = (1,0), (0,1), (-1,0), (0,-1). Each occluder is a thin triangle with one edge on a ruling and
  // its third corner pushed outwards; the lines passing all rulings on the inner side form the free set, and
  // lines near the rulings themselves (the conic case of section 5.3) are what the CSG must decide.
  for (int outer : {1, 2}) {
    SceneBuilder b;
    const double cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    for (int i = 0; i < 4; ++i) {
      const double c = cs[i][0], s = cs[i][1];
      const Point3 a{c + 3 * s, s - 3 * c, -3}, e{c - 3 * s, s + 3 * c, 3};
      const Point3 out{c * (1 + outer), s * (1 + outer), 0};
      b.triangle(a, e, out);
    }
    const auto small = b.triangle({-0.25, -0.25, 6}, {0.25, -0.25, 6}, {0, 0.25, 6});
    const auto ring = b.triangle({1.5, -1.5, 6}, {3, -1.5, 6}, {3, 0, 6});
    const Polygon3 src = polygon({{-0.3, -0.3, -6}, {0.3, -0.3, -6}, {0.3, 0.3, -6}, {-0.3, 0.3, -6}});
    EXPECT_TRUE(checked_visible(b.scene, src, small));
    checked_visible(b.scene, src, ring);
    for (std::int64_t t = 0; t < 4; ++t) checked_visible(b.scene, src, t);
  }
}

TEST(FromRegionVisibility, RandomScenesAgreeWithOracle) {
  // Layers of large random occluders between the sources and small targets behind them, plus random
  // triangles anywhere; every triangle is queried (occluders are targets too).
  std::mt19937_64 rng(4242);
  auto coord = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng() % 4096) / 4096.0;  // exact multiples of 1/4096
  };
  int visible = 0, hidden = 0;
  std::int64_t face_tests = 0;
  for (int scene_no = 0; scene_no < 6; ++scene_no) {
    SceneBuilder b;
    auto add_random = [&](double x0, double x1, double r, double size) {
      for (;;) {
        const Point3 c{coord(x0, x1), coord(-r, r), coord(-r, r)};
        const Point3 p{c.x + coord(-size, size) / 4, c.y + coord(-size, size), c.z + coord(-size, size)};
        const Point3 q{c.x + coord(-size, size) / 4, c.y + coord(-size, size), c.z + coord(-size, size)};
        const Point3 s{c.x + coord(-size, size) / 4, c.y + coord(-size, size), c.z + coord(-size, size)};
        if (collinear(p, q, s)) continue;
        b.triangle(p, q, s);
        return;
      }
    };
    for (int i = 0; i < 4; ++i) add_random(9, 10, 1.5, 0.7);    // targets
    for (int i = 0; i < 22; ++i) add_random(3, 7, 1.5, 3.0);    // occluder layers
    for (int i = 0; i < 2; ++i) add_random(1, 9, 3.0, 1.0);     // clutter
    const Box3 cell{{-2, -1, -1}, {-1, 1, 1}};
    const Polygon3 src = polygon({{0, -1, -1}, {0, 1, -1}, {0.5, 1, 1}, {0.5, -1, 1}});
    for (std::int64_t t = 0; t < static_cast<std::int64_t>(b.scene.triangles.size()); ++t) {
      (checked_visible(b.scene, cell, t, 300) ? visible : hidden)++;
      (checked_visible(b.scene, src, t, 300) ? visible : hidden)++;
      face_tests += visible_from_polygon(b.scene, brute_force_candidates(b.scene), src, t).stats.face_tests;
    }
  }
  RecordProperty("face_tests", static_cast<int>(face_tests));
  EXPECT_GT(visible, 40);
  EXPECT_GT(hidden, 20);
}
