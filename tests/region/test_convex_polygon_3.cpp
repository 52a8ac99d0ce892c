// Exact clipping of convex polygons by planes, against the oracle: the clipped polygon's vertices are on the
// kept side, every kept original vertex survives, and points sampled inside the clip lie in the original
// polygon and on the kept side.
#include "region/convex_polygon_3.hpp"

#include "oracles/rational_geometry.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace exactvis;
using namespace exactvis::region;

namespace {
oracle::QVec qv(const RationalPoint3& p) { return {mpq_class(p.x.mpq()), mpq_class(p.y.mpq()), mpq_class(p.z.mpq())}; }
}  // namespace

TEST(ConvexPolygon3, ClipAgainstOracle) {
  std::mt19937_64 rng(5);
  auto c = [&] { return Exact(static_cast<long>(rng() % 17) - 8); };
  int nontrivial = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Polygon3 tri{{c(), c(), c()}, {c(), c(), c()}, {c(), c(), c()}};
    if (is_degenerate(tri)) continue;
    const Plane3 pl = plane_through({c(), c(), c()}, {c(), c(), c()}, {c(), c(), c()});
    if (pl.normal == Vec3<Exact>(Exact(0), Exact(0), Exact(0))) continue;
    const Polygon3 out = clip_polygon(tri, pl);
    for (const auto& v : out) {
      EXPECT_GE(CGAL::sign(pl.value(v)), 0);
      EXPECT_TRUE(oracle::oracle_point_in_closed_triangle(qv(v), qv(tri[0]), qv(tri[1]), qv(tri[2])));
    }
    int kept = 0;
    for (const auto& v : tri)
      if (CGAL::sign(pl.value(v)) >= 0) {
        ++kept;
        EXPECT_NE(std::find(out.begin(), out.end(), v), out.end());
      }
    if (kept == 0) EXPECT_TRUE(out.empty());
    if (kept > 0 && kept < 3) ++nontrivial;
    if (out.size() >= 3 && !is_degenerate(out)) {
      const Plane3 tp = plane_of(tri);
      EXPECT_TRUE(lies_in_plane(out, tp));
      // Centroid of the clip is strictly inside the clip: on the kept side, inside the triangle.
      const RationalPoint3 g = centroid(out);
      EXPECT_GE(CGAL::sign(pl.value(g)), 0);
      EXPECT_TRUE(oracle::oracle_point_in_closed_triangle(qv(g), qv(tri[0]), qv(tri[1]), qv(tri[2])));
    }
  }
  EXPECT_GT(nontrivial, 100);
}
