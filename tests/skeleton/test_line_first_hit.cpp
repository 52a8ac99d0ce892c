// line_first_hit and open_segment_meets_triangle on rays and segments in Q(sqrt D) and in Q (the spatial cover
// and the interval filter in front of the exact test; rational rays go through kernel/ray_first_hit, rational
// segments through the filter, then the kernel's test) against an oracle written here: its own Q(sqrt D)
// arithmetic on GMP rationals and no exactvis geometry. The oracle tests every triangle: a ray crossing a
// triangle's plane is decided by the crossing point's edge signs; a ray in the plane by the candidate
// parameters where it meets the three edge lines, each tested exactly and with the midpoints between them
// (the parameters in a convex triangle form an interval). Rays are random and adversarial: through scene
// vertices, along edge lines, in triangle planes, starting on triangles.
#include "kernel/predicates.hpp"
#include "kernel/triangle_index.hpp"
#include "skeleton/line_first_hit.hpp"
#include "tests/skeleton/skeleton3d_test_scenes.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace exactvis {
namespace {

using Q = mpq_class;

// a + b sqrt(D), one D per case.
struct QD {
  Q a, b;
};
using QD3 = std::array<QD, 3>;

struct Field {
  Q D;
  int sgn(const Q& x) const { return x > 0 ? 1 : (x < 0 ? -1 : 0); }
  QD add(const QD& x, const QD& y) const { return {x.a + y.a, x.b + y.b}; }
  QD sub(const QD& x, const QD& y) const { return {x.a - y.a, x.b - y.b}; }
  QD mul(const QD& x, const QD& y) const { return {x.a * y.a + x.b * y.b * D, x.a * y.b + x.b * y.a}; }
  QD div(const QD& x, const QD& y) const {  // D is not a square: y.a^2 - y.b^2 D != 0 for y != 0
    const Q n = y.a * y.a - y.b * y.b * D;
    const QD p = mul(x, QD{y.a, -y.b});
    return {p.a / n, p.b / n};
  }
  int sign(const QD& x) const {
    const int sa = sgn(x.a), sb = sgn(x.b);
    if (sb == 0) return sa;
    if (sa == 0 || sa == sb) return sb;
    const Q l = x.a * x.a, r = x.b * x.b * D;
    return l == r ? 0 : (l > r ? sa : sb);
  }
  int cmp(const QD& x, const QD& y) const { return sign(sub(x, y)); }
  QD3 sub(const QD3& x, const QD3& y) const { return {sub(x[0], y[0]), sub(x[1], y[1]), sub(x[2], y[2])}; }
  QD3 add(const QD3& x, const QD3& y) const { return {add(x[0], y[0]), add(x[1], y[1]), add(x[2], y[2])}; }
  QD3 scale(const QD& s, const QD3& x) const { return {mul(s, x[0]), mul(s, x[1]), mul(s, x[2])}; }
  QD dot(const QD3& x, const QD3& y) const { return add(add(mul(x[0], y[0]), mul(x[1], y[1])), mul(x[2], y[2])); }
  QD3 cross(const QD3& x, const QD3& y) const {
    return {sub(mul(x[1], y[2]), mul(x[2], y[1])), sub(mul(x[2], y[0]), mul(x[0], y[2])),
            sub(mul(x[0], y[1]), mul(x[1], y[0]))};
  }
};

QD3 lift(const Point3& p) { return {QD{Q(p.x), 0}, QD{Q(p.y), 0}, QD{Q(p.z), 0}}; }

// Is the point x of the triangle's plane inside the closed triangle (a, b, c) with normal n?
bool inside(const Field& f, const QD3& x, const QD3* v[3], const QD3& n) {
  for (int k = 0; k < 3; ++k)
    if (f.sign(f.dot(f.cross(f.sub(*v[(k + 1) % 3], *v[k]), f.sub(x, *v[k])), n)) < 0) return false;
  return true;
}

// The infimum of {s > 0 : o + s d in closed triangle} (0 when that set starts at o), nullopt if empty.
std::optional<QD> oracle_first(const Field& f, const QD3& o, const QD3& d, const Point3& pa, const Point3& pb,
                               const Point3& pc) {
  const QD3 a = lift(pa), b = lift(pb), c = lift(pc);
  const QD3* v[3] = {&a, &b, &c};
  const QD3 n = f.cross(f.sub(b, a), f.sub(c, a));
  const QD nd = f.dot(n, d), h = f.dot(n, f.sub(a, o));
  if (f.sign(nd) != 0) {
    const QD s = f.div(h, nd);
    if (f.sign(s) <= 0) return std::nullopt;
    if (!inside(f, f.add(o, f.scale(s, d)), v, n)) return std::nullopt;
    return s;
  }
  if (f.sign(h) != 0) return std::nullopt;
  // In the plane: candidates 0 and the s > 0 where the line meets an edge line.
  std::vector<QD> cand{QD{0, 0}};
  for (int k = 0; k < 3; ++k) {
    const QD3 e = f.sub(*v[(k + 1) % 3], *v[k]);
    const QD3 de = f.cross(d, e);
    const QD dd = f.dot(de, de);
    if (f.sign(dd) == 0) continue;
    // (o - p + s d) x e = 0  =>  s = -((o - p) x e) . (d x e) / |d x e|^2
    const QD num = f.dot(f.cross(f.sub(o, *v[k]), e), de);
    const QD t = f.sub(QD{0, 0}, f.div(num, dd));
    if (f.sign(t) > 0) cand.push_back(t);
  }
  std::sort(cand.begin(), cand.end(), [&](const QD& x, const QD& y) { return f.cmp(x, y) < 0; });
  auto at = [&](const QD& s) { return f.add(o, f.scale(s, d)); };
  for (std::size_t i = 0; i < cand.size(); ++i) {
    if (f.sign(cand[i]) > 0 && inside(f, at(cand[i]), v, n)) return cand[i];
    const QD next = i + 1 < cand.size() ? cand[i + 1] : f.add(cand[i], QD{2, 0});
    const QD mid = f.mul(f.add(cand[i], next), QD{Q(1, 2), 0});
    if (f.cmp(mid, cand[i]) > 0 && inside(f, at(mid), v, n)) return cand[i];
  }
  return std::nullopt;
}

// Stable id of the first triangle (lowest index on ties), -1 if none.
std::int64_t oracle_first_hit(const Field& f, const Scene& s, const QD3& o, const QD3& d) {
  std::optional<QD> best;
  std::int64_t id = -1;
  for (const SceneTriangle& t : s.triangles) {
    const auto x = oracle_first(f, o, d, s.corner(t, 0), s.corner(t, 1), s.corner(t, 2));
    if (x && (!best || f.cmp(*x, *best) < 0)) best = x, id = t.id;
  }
  return id;
}

// Small triangles (corners within 4 of a centre) or small tetrahedra spread over [0, 60]^3, so the ray
// covers exclude most of the scene; integer corners, so exact incidences occur.
Scene spread_scene(unsigned seed, int n, bool tetrahedra) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> centre(4, 56), off(-4, 4);
  Scene s;
  while (static_cast<int>(s.objects.size()) < n) {
    const Point3 c{double(centre(rng)), double(centre(rng)), double(centre(rng))};
    std::array<Point3, 4> p;
    for (auto& q : p) q = {c.x + off(rng), c.y + off(rng), c.z + off(rng)};
    if (tetrahedra) {
      if (orient3d(p[0], p[1], p[2], p[3]) == Sign::Zero) continue;
      if (orient3d(p[0], p[1], p[2], p[3]) == Sign::Negative) std::swap(p[2], p[3]);
      skeleton_test::add_tetrahedron(s, p, "tet" + std::to_string(s.objects.size()));
      continue;
    }
    if (collinear(p[0], p[1], p[2])) continue;
    const int b = static_cast<int>(s.vertices.size());
    s.vertices.insert(s.vertices.end(), {p[0], p[1], p[2]});
    s.objects.push_back({"t" + std::to_string(s.triangles.size())});
    s.triangles.push_back({s.faces_read++, {b, b + 1, b + 2}, static_cast<int>(s.objects.size()) - 1});
  }
  return s;
}

RootNumber to_root(const QD& x, const Q& D) {
  if (x.b == 0) return RootNumber(Exact(x.a.get_mpq_t()));
  return RootNumber(Exact(x.a.get_mpq_t()), Exact(x.b.get_mpq_t()), Exact(D.get_mpq_t()));
}
Vec3<RootNumber> to_root(const QD3& v, const Q& D) { return {to_root(v[0], D), to_root(v[1], D), to_root(v[2], D)}; }

// Rays and segments of one scene: random and adversarial, every origin a convex combination of scene points
// with an irrational weight (so it lies in the scene box and is irrational), or with `rational` a rational
// weight and rational directions (the node lines through vertices and VEE lines).
struct Cases {
  int rays = 0, hits = 0, coplanar = 0, segments = 0, segment_hits = 0;
  int on_edge = 0;  // rays also asked with the edge line their origin lies on (RayOriginOnEdgeLine)
};

Cases run_scene(const Scene& scene, unsigned seed, int count, bool rational = false) {
  std::mt19937 rng(seed);
  const TriangleIndex index(scene);
  const Box3 box = bounding_box(scene);
  const int nv = static_cast<int>(scene.vertices.size());
  std::uniform_int_distribution<int> pick_v(0, nv - 1), pick_t(0, static_cast<int>(scene.triangles.size()) - 1),
      small(-8, 8), weight(1, 7), kind(0, 5);
  const Q roots[3] = {2, 3, 5};
  Cases c;
  for (int i = 0; i < count; ++i) {
    Field f{roots[i % 3]};
    // lambda = w/16 + sqrt(D)/16 in (0, 1)
    auto lam = [&] { return QD{Q(weight(rng), 16), Q(rational ? 0 : 1, 16)}; };
    auto point = [&](int v) { return lift(scene.vertices[v]); };
    auto between = [&](const QD3& p, const QD3& q) { return f.add(p, f.scale(lam(), f.sub(q, p))); };
    auto random_dir = [&] {
      const int r = rational ? 0 : 1;
      return QD3{QD{small(rng), Q(r * small(rng), 4)}, QD{small(rng), Q(r * small(rng), 4)},
                 QD{small(rng), Q(r * small(rng), 4)}};
    };
    const SceneTriangle& t = scene.triangles[pick_t(rng)];
    const QD3 a = point(t.v[0]), b = point(t.v[1]), cc = point(t.v[2]);
    QD3 o, d;
    const int k = kind(rng);
    switch (k) {
      case 0:  // random
        o = between(point(pick_v(rng)), point(pick_v(rng)));
        d = random_dir();
        break;
      case 1:  // through a scene vertex
        o = between(point(pick_v(rng)), point(pick_v(rng)));
        d = f.sub(point(pick_v(rng)), o);
        break;
      case 2:  // along an edge line, from a point of the edge
        o = between(a, b);
        d = f.scale(QD{Q(weight(rng) % 2 ? 1 : -1), 0}, f.sub(b, a));
        break;
      case 3:  // in a triangle's plane, from a point of the triangle
        o = between(between(a, b), cc);
        d = f.add(f.scale(QD{Q(small(rng)), Q(rational ? 0 : 1, 3)}, f.sub(b, a)),
                  f.scale(QD{Q(small(rng)), 0}, f.sub(cc, a)));
        break;
      case 4:  // from a point of a triangle, anywhere
        o = between(between(a, b), cc);
        d = random_dir();
        break;
      default:  // from a point of an edge through another vertex
        o = between(a, b);
        d = f.sub(point(pick_v(rng)), o);
        break;
    }
    if (f.sign(d[0]) == 0 && f.sign(d[1]) == 0 && f.sign(d[2]) == 0) continue;
    const bool irrational = o[0].b != 0 || o[1].b != 0 || o[2].b != 0 || d[0].b != 0 || d[1].b != 0 || d[2].b != 0;
    if (irrational == rational) continue;
    ++c.rays;
    const std::int64_t want = oracle_first_hit(f, scene, o, d);
    const std::int64_t got = line_first_hit(scene, index, box, to_root(o, f.D), to_root(d, f.D));
    EXPECT_EQ(got, want) << "ray " << i << " (seed " << seed << ")";
    if (k == 2 || k == 5) {  // the origin lies on the line of t's edge (v0, v1): the same answer with that knowledge
      ++c.on_edge;
      EXPECT_EQ(line_first_hit(scene, index, box, to_root(o, f.D), to_root(d, f.D), {t.v[0], t.v[1]}), want)
          << "ray " << i << " with its origin's edge line (seed " << seed << ")";
    }
    c.hits += want >= 0;
    {
      const SceneTriangle& u = scene.triangles[pick_t(rng)];
      const QD3 ua = point(u.v[0]), ub = point(u.v[1]), uc = point(u.v[2]);
      const QD3 n = f.cross(f.sub(ub, ua), f.sub(uc, ua));
      c.coplanar += f.sign(f.dot(n, d)) == 0 && f.sign(f.dot(n, f.sub(o, ua))) == 0;
    }
    // The segment from o to a point q further along (q = o + d / 2^j stays in the box only when it is a
    // convex combination; take q between o and a scene point instead, with d = q - o).
    const QD3 q = between(o, point(pick_v(rng)));
    const QD3 sd = f.sub(q, o);
    if (f.sign(sd[0]) == 0 && f.sign(sd[1]) == 0 && f.sign(sd[2]) == 0) continue;
    for (const SceneTriangle& u : scene.triangles) {
      const auto first = oracle_first(f, o, sd, scene.corner(u, 0), scene.corner(u, 1), scene.corner(u, 2));
      const bool want_seg = first && f.cmp(*first, QD{1, 0}) < 0;
      const bool got_seg = open_segment_meets_triangle(to_root(o, f.D), to_root(q, f.D), scene.corner(u, 0),
                                                       scene.corner(u, 1), scene.corner(u, 2));
      EXPECT_EQ(got_seg, want_seg) << "segment " << i << ", triangle " << u.id << " (seed " << seed << ")";
      ++c.segments;
      c.segment_hits += want_seg;
    }
  }
  return c;
}

TEST(LineFirstHit, IrrationalRaysMatchTheOracleOnSoups) {
  for (unsigned seed : {1u, 2u}) {
    const Scene s = seed == 1 ? spread_scene(seed, 60, false) : skeleton_test::random_soup(seed, 30, 24);
    const Cases c = run_scene(s, 100 + seed, 250);
    EXPECT_GT(c.rays, 200);
    EXPECT_GT(c.hits, c.rays / 10);             // not all misses
    EXPECT_LT(c.hits, c.rays);                  // not all hits
    EXPECT_GT(c.segment_hits, 0);
  }
}

TEST(LineFirstHit, IrrationalRaysMatchTheOracleOnClosedMeshes) {
  // Closed meshes: shared vertices and edges, so rays through vertices and along edges meet several
  // triangles at one parameter (ties go to the lowest index).
  Scene s = spread_scene(7, 12, true);
  skeleton_test::add_box(s, {20, 20, 20}, {26, 26, 26}, "box");
  skeleton_test::add_box(s, {20, 20, 28}, {26, 26, 34}, "box2");  // faces coplanar with the first box's
  const Cases c = run_scene(s, 300, 300);
  EXPECT_GT(c.rays, 250);
  EXPECT_GT(c.hits, c.rays / 10);
  EXPECT_LT(c.hits, c.rays);
  EXPECT_GT(c.segment_hits, 0);
}

TEST(LineFirstHit, RationalRaysAndSegmentsMatchTheOracle) {
  // Rational segments take the interval filter before the kernel's exact test (node validity's spanned
  // segments through vertices and VEE lines): on soups, and on closed meshes with shared edges and coplanar
  // faces, where segments start on triangles, run along edges and lie in faces' planes.
  Scene mesh = spread_scene(7, 12, true);
  skeleton_test::add_box(mesh, {20, 20, 20}, {26, 26, 26}, "box");
  skeleton_test::add_box(mesh, {20, 20, 28}, {26, 26, 34}, "box2");
  const Cases m = run_scene(mesh, 500, 300, true);
  EXPECT_GT(m.rays, 250);
  EXPECT_GT(m.on_edge, 50);
  EXPECT_GT(m.hits, m.rays / 10);
  EXPECT_LT(m.hits, m.rays);
  EXPECT_GT(m.segment_hits, m.segments / 1000);
  const Cases c = run_scene(spread_scene(3, 60, false), 600, 300, true);
  EXPECT_GT(c.rays, 250);
  EXPECT_GT(c.hits, c.rays / 10);
  EXPECT_GT(c.segment_hits, 0);
}

}  // namespace
}  // namespace exactvis

