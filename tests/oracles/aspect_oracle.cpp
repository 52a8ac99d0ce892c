#include "oracles/aspect_oracle.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace oracle {

namespace {

QVec centroid(const OTriangle& t) { return mpq_class(1, 3) * (t[0] + t[1] + t[2]); }
QVec normal(const OTriangle& t) { return cross(t[1] - t[0], t[2] - t[0]); }

// Is the open segment (a, b) free of every triangle other than `skip`?
bool free_segment(const std::vector<OTriangle>& model, std::size_t skip, const QVec& a, const QVec& b) {
  for (std::size_t k = 0; k < model.size(); ++k)
    if (k != skip && oracle_open_segment_meets_closed_triangle(a, b, model[k][0], model[k][1], model[k][2])) return false;
  return true;
}

// Direction key up to positive scaling: divide by the largest |component| (exact).
std::array<mpq_class, 3> ray_key(const QVec& v) {
  mpq_class big = abs(v.x);
  if (abs(v.y) > big) big = abs(v.y);
  if (abs(v.z) > big) big = abs(v.z);
  return {v.x / big, v.y / big, v.z / big};
}
// Up to any non-zero scaling.
std::array<mpq_class, 3> line_key(const QVec& v) {
  auto k = ray_key(v);
  for (const auto& c : k)
    if (c != 0) {
      if (c < 0) for (auto& x : k) x = -x;
      break;
    }
  return k;
}

}  // namespace

std::vector<int> convex_direction_aspect(const std::vector<OTriangle>& model, const QVec& d) {
  // Far enough: beyond every corner along d (the segment then leaves the model's box).
  mpq_class reach = 1;
  for (const auto& t : model)
    for (const auto& p : t) reach += abs(p.x) + abs(p.y) + abs(p.z);
  const mpq_class len = abs(d.x) + abs(d.y) + abs(d.z);
  std::vector<int> seen;
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (sign(dot(normal(model[i]), d)) == 0) continue;  // edge-on: null image
    const QVec c = centroid(model[i]);
    if (free_segment(model, i, c, c + mpq_class(2 * reach / len) * d)) seen.push_back(static_cast<int>(i));
  }
  return seen;
}

std::vector<int> convex_point_aspect(const std::vector<OTriangle>& model, const QVec& p) {
  std::vector<int> seen;
  for (std::size_t i = 0; i < model.size(); ++i) {
    const QVec c = centroid(model[i]);
    if (sign(dot(normal(model[i]), p - c)) == 0) continue;  // edge-on
    if (free_segment(model, i, c, p)) seen.push_back(static_cast<int>(i));
  }
  return seen;
}

namespace {

struct P2 {
  mpq_class x, y;
};
struct Seg2 {
  P2 a, b;  // a.x <= b.x
};

// y of the non-vertical segment s at abscissa x (a.x <= x <= b.x).
mpq_class y_at(const Seg2& s, const mpq_class& x) { return mpq_class(s.a.y + (s.b.y - s.a.y) * (x - s.a.x) / (s.b.x - s.a.x)); }

}  // namespace

std::vector<int> direction_aspect(const std::vector<OTriangle>& model, const QVec& d) {
  // Project along d onto the coordinate plane of the two other axes than the dominant one (k); a point
  // p = (u, v) + depth * d with depth = p_k / d_k; larger depth = nearer the viewer.
  int k = 0;
  const mpq_class c[3] = {d.x, d.y, d.z};
  for (int i = 1; i < 3; ++i)
    if (abs(c[i]) > abs(c[k])) k = i;
  const int i0 = (k + 1) % 3, i1 = (k + 2) % 3;
  const auto coord = [](const QVec& p, int i) -> mpq_class { return i == 0 ? p.x : (i == 1 ? p.y : p.z); };
  const std::size_t n = model.size();
  std::vector<std::array<P2, 3>> img(n);
  std::vector<std::array<mpq_class, 3>> depth(n);
  std::vector<bool> flat(n);
  for (std::size_t t = 0; t < n; ++t) {
    for (int j = 0; j < 3; ++j) {
      const QVec& p = model[t][j];
      depth[t][j] = coord(p, k) / c[k];
      img[t][j] = {coord(p, i0) - depth[t][j] * c[i0], coord(p, i1) - depth[t][j] * c[i1]};
    }
    const mpq_class area2 = (img[t][1].x - img[t][0].x) * (img[t][2].y - img[t][0].y) -
                            (img[t][1].y - img[t][0].y) * (img[t][2].x - img[t][0].x);
    flat[t] = area2 == 0;
  }
  // Barycentric interpolation of the depth of triangle t at q (q inside its image).
  const auto depth_at = [&](std::size_t t, const P2& q) -> mpq_class {
    const P2 &a = img[t][0], &b = img[t][1], &cc = img[t][2];
    const mpq_class den = (b.x - a.x) * (cc.y - a.y) - (b.y - a.y) * (cc.x - a.x);
    const mpq_class l1 = ((q.x - a.x) * (cc.y - a.y) - (q.y - a.y) * (cc.x - a.x)) / den;
    const mpq_class l2 = ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) / den;
    return depth[t][0] + l1 * (depth[t][1] - depth[t][0]) + l2 * (depth[t][2] - depth[t][0]);
  };
  const auto strictly_inside = [&](std::size_t t, const P2& q) {
    int s[3];
    for (int j = 0; j < 3; ++j) {
      const P2& a = img[t][j];
      const P2& b = img[t][(j + 1) % 3];
      s[j] = sign((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x));
    }
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
  };
  // Segments: the edges of every triangle with an image; event abscissae: their ends and crossings (once).
  std::vector<Seg2> segs;
  for (std::size_t u = 0; u < n; ++u) {
    if (flat[u]) continue;
    for (int j = 0; j < 3; ++j) {
      P2 a = img[u][j], b = img[u][(j + 1) % 3];
      if (b.x < a.x) std::swap(a, b);
      segs.push_back({a, b});
    }
  }
  std::vector<mpq_class> all_xs;
  for (const auto& s : segs) all_xs.push_back(s.a.x), all_xs.push_back(s.b.x);
  for (std::size_t a = 0; a < segs.size(); ++a)
    for (std::size_t b = a + 1; b < segs.size(); ++b) {
      const Seg2 &s = segs[a], &r = segs[b];
      if (s.b.x < r.a.x || r.b.x < s.a.x) continue;
      const mpq_class dx1 = s.b.x - s.a.x, dy1 = s.b.y - s.a.y, dx2 = r.b.x - r.a.x, dy2 = r.b.y - r.a.y;
      const mpq_class den = dx1 * dy2 - dy1 * dx2;
      if (den == 0) continue;  // parallel: no single crossing (overlaps add no abscissa)
      const mpq_class u = ((r.a.x - s.a.x) * dy2 - (r.a.y - s.a.y) * dx2) / den;
      const mpq_class v = ((r.a.x - s.a.x) * dy1 - (r.a.y - s.a.y) * dx1) / den;
      if (u < 0 || u > 1 || v < 0 || v > 1) continue;
      all_xs.push_back(mpq_class(s.a.x + u * dx1));
    }
  std::sort(all_xs.begin(), all_xs.end());
  all_xs.erase(std::unique(all_xs.begin(), all_xs.end()), all_xs.end());
  // Per slab (between all_xs[j] and all_xs[j + 1]), the sorted ordinates of the edges at its middle.
  std::vector<std::vector<mpq_class>> slab_ys(all_xs.empty() ? 0 : all_xs.size() - 1);
  std::vector<bool> slab_done(slab_ys.size(), false);
  std::vector<int> seen;
  for (std::size_t t = 0; t < n; ++t) {
    if (flat[t]) continue;
    mpq_class lo = img[t][0].x, hi = img[t][0].x;
    for (int j = 1; j < 3; ++j) lo = std::min(lo, img[t][j].x), hi = std::max(hi, img[t][j].x);
    std::vector<std::size_t> others;
    for (std::size_t u = 0; u < n; ++u)
      if (!flat[u] && u != t) others.push_back(u);
    bool visible = false;
    const std::size_t first = std::lower_bound(all_xs.begin(), all_xs.end(), lo) - all_xs.begin();
    for (std::size_t j = first; j + 1 < all_xs.size() && all_xs[j] < hi && !visible; ++j) {
      const mpq_class xm = (all_xs[j] + all_xs[j + 1]) / 2;
      if (!slab_done[j]) {
        for (const auto& s : segs)
          if (s.a.x < xm && xm < s.b.x) slab_ys[j].push_back(y_at(s, xm));
        std::sort(slab_ys[j].begin(), slab_ys[j].end());
        slab_ys[j].erase(std::unique(slab_ys[j].begin(), slab_ys[j].end()), slab_ys[j].end());
        slab_done[j] = true;
      }
      const std::vector<mpq_class>& ys = slab_ys[j];
      for (std::size_t m = 0; m + 1 < ys.size() && !visible; ++m) {
        const P2 q{xm, (ys[m] + ys[m + 1]) / 2};
        if (!strictly_inside(t, q)) continue;
        const mpq_class dt = depth_at(t, q);
        bool hidden = false;
        for (std::size_t u : others) {
          if (!strictly_inside(u, q)) continue;
          const mpq_class du = depth_at(u, q);
          if (du == dt) throw std::invalid_argument("direction_aspect: triangles cross or overlap");
          if (du > dt) { hidden = true; break; }
        }
        visible = !hidden;
      }
    }
    if (visible) seen.push_back(static_cast<int>(t));
  }
  return seen;
}

GreatCircleCounts great_circle_counts(const std::vector<QVec>& normals) {
  GreatCircleCounts g;
  std::vector<QVec> circles;
  std::set<std::array<mpq_class, 3>> seen;
  for (const auto& n : normals)
    if (seen.insert(line_key(n)).second) circles.push_back(n);
  g.circles = static_cast<std::int64_t>(circles.size());
  // Vertex lines (each two antipodal vertices) and, per line, how many circles hold it.
  std::set<std::array<mpq_class, 3>> lines;
  for (std::size_t i = 0; i < circles.size(); ++i)
    for (std::size_t j = i + 1; j < circles.size(); ++j) lines.insert(line_key(cross(circles[i], circles[j])));
  g.vertices = 2 * static_cast<std::int64_t>(lines.size());
  for (const auto& l : lines) {
    const QVec v{l[0], l[1], l[2]};
    int on = 0;
    for (const auto& c : circles) on += sign(dot(c, v)) == 0;
    g.arcs += 2 * on;  // each of the two vertices splits each of its circles once more
    if (on != 2) g.simple = false;
  }
  g.faces = 2 - g.vertices + g.arcs;
  return g;
}

bool plane_arrangement_is_simple(const std::vector<std::pair<QVec, mpq_class>>& planes) {
  const std::size_t m = planes.size();
  auto det = [](const QVec& a, const QVec& b, const QVec& c) { return dot(a, cross(b, c)); };
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j) {
      if (is_zero(cross(planes[i].first, planes[j].first))) return false;
      for (std::size_t k = j + 1; k < m; ++k) {
        const mpq_class D = det(planes[i].first, planes[j].first, planes[k].first);
        if (D == 0) {
          // Normals coplanar: the three planes share a line iff the system is consistent; treat both as
          // non-generic unless the three are pairwise crossing without a common point (still no vertex).
          // A simple arrangement needs every three to meet in exactly one point.
          return false;
        }
        // The common point by Cramer's rule; a fourth plane through it breaks simplicity.
        const QVec e{planes[i].second, planes[j].second, planes[k].second};
        const QVec& a = planes[i].first;
        const QVec& b = planes[j].first;
        const QVec& c = planes[k].first;
        // Solve [a; b; c] x = e.
        const QVec col0{a.x, b.x, c.x}, col1{a.y, b.y, c.y}, col2{a.z, b.z, c.z};
        const mpq_class Dx = det(e, col1, col2), Dy = det(col0, e, col2), Dz = det(col0, col1, e);
        const mpq_class Dc = det(col0, col1, col2);
        const QVec x{Dx / Dc, Dy / Dc, Dz / Dc};
        for (std::size_t l = k + 1; l < m; ++l)
          if (dot(planes[l].first, x) == planes[l].second) return false;
      }
    }
  return true;
}

}  // namespace oracle

namespace oracle {

namespace {

using Poly3 = std::vector<QVec>;

// Sutherland-Hodgman: the part of a convex polygon with m . (y - q) >= 0 (closed), exact.
Poly3 clip_closed(const Poly3& poly, const QVec& m, const QVec& q) {
  Poly3 out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const QVec& a = poly[i];
    const QVec& b = poly[(i + 1) % poly.size()];
    const mpq_class fa = dot(m, a - q), fb = dot(m, b - q);
    if (fa >= 0) out.push_back(a);
    if ((fa > 0 && fb < 0) || (fa < 0 && fb > 0)) out.push_back(a + mpq_class(fa / (fa - fb)) * (b - a));
  }
  return out;
}

mpq_class cross2(const P2& o, const P2& a, const P2& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// q inside (or on) the convex polygon `poly` (counter-clockwise, consecutive duplicates allowed).
bool in_convex(const std::vector<P2>& poly, const P2& q) {
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P2& a = poly[i];
    const P2& b = poly[(i + 1) % poly.size()];
    if (a.x == b.x && a.y == b.y) continue;
    if (sign(cross2(a, b, q)) < 0) return false;
  }
  return true;
}

}  // namespace

std::vector<int> point_aspect(const std::vector<OTriangle>& model, const QVec& p) {
  std::vector<int> seen;
  for (std::size_t t = 0; t < model.size(); ++t) {
    const OTriangle& T = model[t];
    QVec nrm = normal(T);
    if (is_zero(nrm)) continue;
    mpq_class hp = dot(nrm, p - T[0]);
    if (hp == 0) continue;  // p in t's plane: t has no image
    if (hp < 0) nrm = mpq_class(-1) * nrm, hp = -hp;
    const auto h = [&](const QVec& y) { return mpq_class(dot(nrm, y - T[0])); };
    // The pyramid conv(p, t): t's plane side of p and the three planes through p and t's edges.
    std::vector<std::pair<QVec, QVec>> planes{{nrm, T[0]}};
    for (int j = 0; j < 3; ++j) {
      QVec m = cross(T[j] - p, T[(j + 1) % 3] - p);
      if (sign(dot(m, T[(j + 2) % 3] - p)) < 0) m = mpq_class(-1) * m;
      planes.push_back({m, p});
    }
    // 2D coordinates in t's plane: drop the dominant axis of its normal.
    int k = 0;
    const mpq_class c[3] = {nrm.x, nrm.y, nrm.z};
    for (int i = 1; i < 3; ++i)
      if (abs(c[i]) > abs(c[k])) k = i;
    const auto to2 = [&](const QVec& v) {
      return k == 0 ? P2{v.y, v.z} : (k == 1 ? P2{v.z, v.x} : P2{v.x, v.y});
    };
    std::vector<std::vector<P2>> polys;  // t's image first, then the shadows, all counter-clockwise
    const auto add_poly = [&](std::vector<P2> poly) {
      mpq_class area = 0;
      for (std::size_t i = 1; i + 1 < poly.size(); ++i) area += cross2(poly[0], poly[i], poly[i + 1]);
      if (area == 0) return false;
      if (area < 0) std::reverse(poly.begin(), poly.end());
      polys.push_back(std::move(poly));
      return true;
    };
    add_poly({to2(T[0]), to2(T[1]), to2(T[2])});
    for (std::size_t u = 0; u < model.size(); ++u) {
      if (u == t) continue;
      Poly3 poly(model[u].begin(), model[u].end());
      for (const auto& [m, q] : planes) {
        if (poly.empty()) break;
        poly = clip_closed(poly, m, q);
      }
      bool ahead = false;
      for (const auto& y : poly) ahead |= h(y) > 0;
      if (!ahead) continue;  // nothing strictly between t's plane and p
      std::vector<P2> shadow;
      for (const auto& y : poly) {
        const mpq_class hy = h(y);
        if (hy == hp) throw std::invalid_argument("point_aspect: the viewpoint lies on the model");
        shadow.push_back(to2(p + mpq_class(hp / (hp - hy)) * (y - p)));
      }
      add_poly(std::move(shadow));
    }
    // Vertical slabs over t's image; samples between consecutive edges of the polygons at the slab middles.
    std::vector<Seg2> segs;
    for (const auto& poly : polys)
      for (std::size_t i = 0; i < poly.size(); ++i) {
        P2 a = poly[i], b = poly[(i + 1) % poly.size()];
        if (a.x == b.x && a.y == b.y) continue;
        if (b.x < a.x) std::swap(a, b);
        segs.push_back({a, b});
      }
    const std::vector<P2>& img = polys.front();
    mpq_class lo = img[0].x, hi = img[0].x;
    for (const auto& v : img) lo = std::min(lo, v.x), hi = std::max(hi, v.x);
    std::vector<mpq_class> xs{lo, hi};
    for (const auto& s : segs) {
      if (s.a.x > lo && s.a.x < hi) xs.push_back(s.a.x);
      if (s.b.x > lo && s.b.x < hi) xs.push_back(s.b.x);
    }
    for (std::size_t a = 0; a < segs.size(); ++a)
      for (std::size_t b = a + 1; b < segs.size(); ++b) {
        const Seg2 &s = segs[a], &r = segs[b];
        const mpq_class dx1 = s.b.x - s.a.x, dy1 = s.b.y - s.a.y, dx2 = r.b.x - r.a.x, dy2 = r.b.y - r.a.y;
        const mpq_class den = dx1 * dy2 - dy1 * dx2;
        if (den == 0) continue;
        const mpq_class uu = ((r.a.x - s.a.x) * dy2 - (r.a.y - s.a.y) * dx2) / den;
        const mpq_class vv = ((r.a.x - s.a.x) * dy1 - (r.a.y - s.a.y) * dx1) / den;
        if (uu < 0 || uu > 1 || vv < 0 || vv > 1) continue;
        const mpq_class x = s.a.x + uu * dx1;
        if (x > lo && x < hi) xs.push_back(x);
      }
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    bool visible = false;
    for (std::size_t j = 0; j + 1 < xs.size() && !visible; ++j) {
      const mpq_class xm = (xs[j] + xs[j + 1]) / 2;
      std::vector<mpq_class> ys;
      for (const auto& s : segs)
        if (s.a.x < xm && xm < s.b.x) ys.push_back(y_at(s, xm));
      std::sort(ys.begin(), ys.end());
      ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
      for (std::size_t m = 0; m + 1 < ys.size() && !visible; ++m) {
        const P2 q{xm, (ys[m] + ys[m + 1]) / 2};
        if (!in_convex(img, q)) continue;
        bool hidden = false;
        for (std::size_t s = 1; s < polys.size() && !hidden; ++s) hidden = in_convex(polys[s], q);
        visible = !hidden;
      }
    }
    if (visible) seen.push_back(static_cast<int>(t));
  }
  return seen;
}

}  // namespace oracle
