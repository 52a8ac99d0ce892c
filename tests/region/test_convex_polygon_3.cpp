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

namespace {
// The oracle's clip: Sutherland-Hodgman on plain GMP rationals, every value computed exactly, the same vertex
// sequence rule as clip_polygon's contract (kept vertices in order, a crossing point on each crossing edge,
// repeated consecutive vertices removed).
std::vector<oracle::QVec> oracle_clip(const std::vector<oracle::QVec>& poly, const oracle::QVec& n,
                                      const mpq_class& off) {
  std::vector<oracle::QVec> out, clean;
  const std::size_t k = poly.size();
  for (std::size_t i = 0; i < k; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % k];
    const mpq_class va = oracle::dot(n, a) - off, vb = oracle::dot(n, b) - off;
    if (sgn(va) >= 0) out.push_back(a);
    if ((sgn(va) > 0 && sgn(vb) < 0) || (sgn(va) < 0 && sgn(vb) > 0)) {
      const mpq_class t = va / (va - vb);
      out.push_back(a + t * (b - a));
    }
  }
  for (const auto& p : out)
    if (clean.empty() || !(clean.back() == p)) clean.push_back(p);
  while (clean.size() > 1 && clean.front() == clean.back()) clean.pop_back();
  return clean;
}
}  // namespace

// clip_polygon decides the vertices' sides with a floating-point filter and computes exact values only at
// crossing edges: on polygons with large rational vertices (crossing points of earlier clips) and planes
// through some of them or at distances below any double's resolution (2^-80), where the filter cannot
// decide, the output is the oracle's vertex sequence exactly.
TEST(ConvexPolygon3, FilteredClipMatchesExactOracleNearDegenerate) {
  std::mt19937_64 rng(11);
  auto c = [&] { return Exact(static_cast<long>(rng() % 2001) - 1000) / Exact(7 + static_cast<long>(rng() % 97)); };
  Exact tiny(1);
  for (int k = 0; k < 80; ++k) tiny /= 2;
  int on_plane = 0, near_plane = 0, crossings = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Polygon3 poly{{c(), c(), c()}, {c(), c(), c()}, {c(), c(), c()}};
    if (is_degenerate(poly)) continue;
    // Two clips first, so that the vertices are crossing points with large numerators and denominators.
    for (int k = 0; k < 2 && poly.size() >= 3; ++k) {
      const RationalPoint3 a = centroid(poly);
      const Vec3<Exact> nrm{c(), c(), c()};
      poly = clip_polygon(poly, Plane3{nrm, dot(nrm, a)});
    }
    if (poly.size() < 3) continue;
    // The plane: through one or two vertices, or shifted from such a plane by +-2^-80, or generic.
    const int mode = static_cast<int>(rng() % 4);
    const Vec3<Exact> nrm{c(), c(), c()};
    const RationalPoint3& v0 = poly[rng() % poly.size()];
    Exact off = dot(nrm, v0);
    if (mode == 1) off += (rng() % 2 ? tiny : -tiny);
    if (mode == 2) off = dot(nrm, centroid(poly));
    const Plane3 pl{nrm, off};
    std::vector<oracle::QVec> qpoly;
    for (const auto& v : poly) qpoly.push_back(qv(v));
    const auto want = oracle_clip(qpoly, qv(nrm), mpq_class(off.mpq()));
    const Polygon3 got = clip_polygon(poly, pl);
    ASSERT_EQ(got.size(), want.size()) << "trial " << trial;
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(qv(got[i]) == want[i]) << "trial " << trial;
    for (const auto& v : poly) {
      const int s = CGAL::sign(pl.value(v));
      on_plane += s == 0;
      near_plane += s != 0 && mode == 1 && v == v0;
    }
    crossings += got.size() != poly.size() || !(got == poly);
  }
  EXPECT_GT(on_plane, 100);
  EXPECT_GT(near_plane, 50);
  EXPECT_GT(crossings, 100);
}
