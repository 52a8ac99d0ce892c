#include "aspect/direction_aspect.hpp"

#include "kernel/predicates.hpp"
#include "kernel/ray_first_hit.hpp"
#include "kernel/triangle_index.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Simple_cartesian.h>
#include <gmpxx.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace exactvis {
namespace {

// A Cartesian kernel over a lazy exact number type (as aspect/aspect_graph_2d: every decision falls back to
// the exact value, whatever the magnitude of the coordinates).
using K = CGAL::Simple_cartesian<CGAL::Lazy_exact_nt<mpq_class>>;
using Point2 = K::Point_2;
using Polygon2 = CGAL::Polygon_2<K>;
using PolygonWithHoles2 = CGAL::Polygon_with_holes_2<K>;
using PolygonSet2 = CGAL::Polygon_set_2<K>;

mpq_class q(const Exact& x) { return mpq_class(x.mpq()); }
Exact ex(const mpq_class& x) { return Exact(x.get_mpq_t()); }

// The projection along d onto the coordinate plane of the two axes other than k (d_k != 0), coordinates in
// cyclic order (k+1, k+2): p -> (p_i - p_k d_i / d_k, p_j - p_k d_j / d_k). Affine, so images of convex sets
// are the convex hulls of the images of their corners.
struct Projection {
  int k = 2, i = 0, j = 1;
  mpq_class ri, rj;  // d_i / d_k, d_j / d_k
  Point2 operator()(const Vec3<Exact>& p) const {
    const mpq_class pk = q(p[k]);
    return Point2(K::FT(mpq_class(q(p[i]) - pk * ri)), K::FT(mpq_class(q(p[j]) - pk * rj)));
  }
};

Vec3<Exact> exact_point(const Point3& p) { return {Exact(p.x), Exact(p.y), Exact(p.z)}; }

// The convex polygon of the images of `pts` (in order around a planar convex polygon), counter-clockwise,
// or an empty polygon when the image has no area.
Polygon2 image_polygon(const std::vector<Vec3<Exact>>& pts, const Projection& proj) {
  std::vector<Point2> c;
  for (const auto& p : pts) {
    const Point2 x = proj(p);
    if (c.empty() || c.back() != x) c.push_back(x);
  }
  while (c.size() > 1 && c.front() == c.back()) c.pop_back();
  if (c.size() < 3) return {};
  // Clipping a triangle by a plane through a corner, or projecting, can leave collinear points; drop them (a
  // convex polygon whose image has no area is left with fewer than three vertices).
  Polygon2 clean;
  for (std::size_t m = 0; m < c.size(); ++m) {
    const Point2& a = c[(m + c.size() - 1) % c.size()];
    const Point2& b = c[m];
    const Point2& e = c[(m + 1) % c.size()];
    if (CGAL::orientation(a, b, e) != CGAL::COLLINEAR) clean.push_back(b);
  }
  if (clean.size() < 3) return {};
  if (clean.orientation() == CGAL::CLOCKWISE) clean.reverse_orientation();
  return clean;
}

// The part of triangle u on the closed side `side` (+1 / -1) of t's plane, as its corners in order around it
// (empty when nothing of u is there or u lies in t's plane).
std::vector<Vec3<Exact>> clip_to_side(const Scene& scene, const SceneTriangle& t, const SceneTriangle& u, int side) {
  const Point3 &a = scene.corner(t, 0), &b = scene.corner(t, 1), &c = scene.corner(t, 2);
  std::array<int, 3> s{};
  bool any_in = false, all_zero = true;
  for (int k = 0; k < 3; ++k) {
    s[k] = to_int(orient3d(a, b, c, scene.corner(u, k))) * side;
    if (s[k] > 0) any_in = true;
    if (s[k] != 0) all_zero = false;
  }
  if (!any_in || all_zero) return {};
  // Sutherland-Hodgman against one plane, exact: the crossing of edge pq with the plane at
  // p + (p.n - c)/((p - q).n) (q - p), computed from the exact plane values.
  const Vec3<Exact> ea = exact_point(a);
  const Vec3<Exact> n = cross(exact_point(b) - ea, exact_point(c) - ea);
  std::vector<Vec3<Exact>> out;
  for (int k = 0; k < 3; ++k) {
    const int l = (k + 1) % 3;
    const Vec3<Exact> p = exact_point(scene.corner(u, k)), r = exact_point(scene.corner(u, l));
    if (s[k] >= 0) out.push_back(p);
    if ((s[k] > 0 && s[l] < 0) || (s[k] < 0 && s[l] > 0)) {
      const Exact fp = dot(n, p - ea), fr = dot(n, r - ea);
      const Exact lambda = fp / (fp - fr);
      out.push_back(p + lambda * (r - p));
    }
  }
  return out;
}

// A point strictly inside the polygon with holes `pwh`, the `attempt`-th of a sequence of distinct such points:
// on the vertical line x0 strictly between two consecutive distinct vertex abscissae (the line then crosses
// every boundary edge it meets transversally, never at a vertex), between two consecutive crossings that
// enclose the interior (even-odd), at a fraction of that chord. Returns false when the sequence is exhausted.
bool interior_point(const PolygonWithHoles2& pwh, int attempt, Point2* out) {
  std::vector<std::pair<Point2, Point2>> edges;
  std::vector<mpq_class> xs;
  auto add = [&](const Polygon2& p) {
    for (auto e = p.edges_begin(); e != p.edges_end(); ++e) edges.push_back({e->source(), e->target()});
    for (const auto& v : p.container()) xs.push_back(CGAL::exact(v.x()));
  };
  add(pwh.outer_boundary());
  for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) add(*h);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  // Attempts walk the slabs (x0 at fractions 1/2, 1/3, ... of each) and, per line, chords at fractions of them.
  const int per_line = 8;
  const int line = attempt / per_line, frac = attempt % per_line;
  const int slabs = static_cast<int>(xs.size()) - 1;
  if (slabs <= 0 || line >= slabs * 16) return false;
  const int slab = line % slabs, level = line / slabs;
  const mpq_class x0 = xs[slab] + (xs[slab + 1] - xs[slab]) / (level + 2);
  std::vector<mpq_class> ys;
  for (const auto& [p, r] : edges) {
    const mpq_class px = CGAL::exact(p.x()), rx = CGAL::exact(r.x());
    if ((px < x0 && x0 < rx) || (rx < x0 && x0 < px)) {
      const mpq_class py = CGAL::exact(p.y()), ry = CGAL::exact(r.y());
      ys.push_back(py + (ry - py) * (x0 - px) / (rx - px));
    }
  }
  std::sort(ys.begin(), ys.end());
  if (ys.size() < 2) return false;  // cannot happen for a polygon with positive area
  const std::size_t chords = ys.size() / 2;
  const std::size_t chord = static_cast<std::size_t>(frac) % chords;
  const mpq_class y0 = ys[2 * chord], y1 = ys[2 * chord + 1];
  const mpq_class y = y0 + (y1 - y0) * (frac / static_cast<int>(chords) + 1) / (frac / static_cast<int>(chords) + 2);
  *out = Point2(K::FT(x0), K::FT(y));
  return true;
}

// The point of t's plane whose image is x (t not parallel to d): p_i = u + lambda r_i, p_j = v + lambda r_j,
// p_k = lambda with n . p = n . a.
Vec3<Exact> lift(const Scene& scene, const SceneTriangle& t, const Projection& proj, const Point2& x) {
  const Vec3<Exact> a = exact_point(scene.corner(t, 0));
  const Vec3<Exact> n = cross(exact_point(scene.corner(t, 1)) - a, exact_point(scene.corner(t, 2)) - a);
  const Exact u = ex(CGAL::exact(x.x())), v = ex(CGAL::exact(x.y()));
  const Exact ri = ex(proj.ri), rj = ex(proj.rj);
  const Exact lambda = (dot(n, a) - n[proj.i] * u - n[proj.j] * v) / (n[proj.i] * ri + n[proj.j] * rj + n[proj.k]);
  Vec3<Exact> p;
  p[proj.i] = u + lambda * ri;
  p[proj.j] = v + lambda * rj;
  p[proj.k] = lambda;
  return p;
}

}  // namespace

DirectionAspect direction_aspect(const Scene& scene, const Vec3<Exact>& d, const TriangleIndex* index) {
  if (CGAL::sign(d.x) == 0 && CGAL::sign(d.y) == 0 && CGAL::sign(d.z) == 0)
    throw std::invalid_argument("direction_aspect: the direction is zero");
  std::unique_ptr<TriangleIndex> own;
  if (!index) {
    own = std::make_unique<TriangleIndex>(scene);
    index = own.get();
  }
  const Box3 box = bounding_box(scene);
  Projection proj;
  {
    int k = 0;
    for (int m = 1; m < 3; ++m)
      if (CGAL::abs(d[m]) > CGAL::abs(d[k])) k = m;
    proj.k = k;
    proj.i = (k + 1) % 3;
    proj.j = (k + 2) % 3;
    proj.ri = q(d[proj.i]) / q(d[k]);
    proj.rj = q(d[proj.j]) / q(d[k]);
  }
  // Images of whole triangles, for the box culls.
  const std::size_t n = scene.triangles.size();
  std::vector<CGAL::Bbox_2> boxes(n);
  for (std::size_t m = 0; m < n; ++m) {
    CGAL::Bbox_2 b = proj(exact_point(scene.corner(scene.triangles[m], 0))).bbox();
    for (int c = 1; c < 3; ++c) b += proj(exact_point(scene.corner(scene.triangles[m], c))).bbox();
    boxes[m] = b;
  }
  DirectionAspect out;
  for (std::size_t m = 0; m < n; ++m) {
    const SceneTriangle& t = scene.triangles[m];
    const Vec3<Exact> a = exact_point(scene.corner(t, 0));
    const Vec3<Exact> nt = cross(exact_point(scene.corner(t, 1)) - a, exact_point(scene.corner(t, 2)) - a);
    const int side = CGAL::sign(dot(nt, d));
    if (side == 0) continue;  // seen edge-on: a null image
    const Polygon2 image = image_polygon({a, exact_point(scene.corner(t, 1)), exact_point(scene.corner(t, 2))}, proj);
    if (image.is_empty()) continue;
    std::vector<Polygon2> occluders;
    for (std::size_t o = 0; o < n; ++o) {
      if (o == m || !CGAL::do_overlap(boxes[m], boxes[o])) continue;
      const std::vector<Vec3<Exact>> part = clip_to_side(scene, t, scene.triangles[o], side);
      if (part.empty()) continue;
      Polygon2 img = image_polygon(part, proj);
      if (!img.is_empty()) occluders.push_back(std::move(img));
    }
    PolygonSet2 visible(image);
    if (!occluders.empty()) {
      PolygonSet2 hidden;
      hidden.join(occluders.begin(), occluders.end());
      visible.difference(hidden);
    }
    if (visible.is_empty()) continue;
    // Regularized: a non-empty result has positive area. Its interior points are in no occluder image; only
    // triangles seen edge-on (left out above) can still meet the ray, so candidates are re-checked exactly.
    std::vector<PolygonWithHoles2> parts;
    visible.polygons_with_holes(std::back_inserter(parts));
    bool found = false;
    Vec3<Exact> witness;
    for (int attempt = 0; !found; ++attempt) {
      Point2 x;
      if (!interior_point(parts.front(), attempt, &x)) break;
      witness = lift(scene, t, proj, x);
      found = ray_first_hit(scene, *index, box, witness, d).triangle < 0;
    }
    if (!found) throw std::logic_error("direction_aspect: no free witness point found in a visible region");
    out.aspect.push_back(t.id);
    out.witnesses.push_back({t.id, witness});
  }
  // Scene::triangles is sorted by id, so `aspect` is ascending.
  return out;
}

}  // namespace exactvis
