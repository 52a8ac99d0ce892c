#include "shadows/polyline_arrangement.hpp"

#include "shadows/arrangement_face_id.hpp"

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_naive_point_location.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>

namespace exactvis::shadows {
namespace {

using P2 = std::array<Exact, 2>;
using Conic = std::array<Exact, 6>;  // u^2, uv, v^2, u, v, 1
using Box = std::array<double, 4>;   // xmin, ymin, xmax, ymax (widened: a filter only)

P2 sub(const P2& a, const P2& b) { return {a[0] - b[0], a[1] - b[1]}; }
P2 add(const P2& a, const P2& b) { return {a[0] + b[0], a[1] + b[1]}; }
Exact cross(const P2& u, const P2& v) { return u[0] * v[1] - u[1] * v[0]; }
Exact dot(const P2& u, const P2& v) { return u[0] * v[0] + u[1] * v[1]; }
int orient(const P2& a, const P2& b, const P2& c) { return CGAL::sign(cross(sub(b, a), sub(c, a))); }
Exact eval(const Conic& q, const P2& p) {
  return (q[0] * p[0] + q[1] * p[1] + q[3]) * p[0] + (q[2] * p[1] + q[4]) * p[1] + q[5];
}
P2 grad(const Conic& q, const P2& p) { return {2 * q[0] * p[0] + q[1] * p[1] + q[3], q[1] * p[0] + 2 * q[2] * p[1] + q[4]}; }
Exact form(const Conic& q, const P2& d) { return q[0] * d[0] * d[0] + q[1] * d[0] * d[1] + q[2] * d[1] * d[1]; }

Box box_of(std::initializer_list<const P2*> pts) {
  Box b{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const P2* p : pts) {
    const double x = CGAL::to_double((*p)[0]), y = CGAL::to_double((*p)[1]);
    b[0] = std::min(b[0], x), b[1] = std::min(b[1], y), b[2] = std::max(b[2], x), b[3] = std::max(b[3], y);
  }
  // Widened far beyond the conversion error (a relative 2^-53), so disjoint boxes prove disjoint sets.
  for (int k = 0; k < 4; ++k) b[k] += (k < 2 ? -1 : 1) * (1e-9 * std::abs(b[k]) + 1e-12);
  return b;
}
bool boxes_meet(const Box& a, const Box& b) { return a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3]; }

// An arc of a non-degenerate conic (one of the input curves): its turn (+1 left, -1 right) and its base
// point, the first point, from which every point of the conic is p0 + lambda(d) d for a direction d.
struct Arc {
  Conic q;
  P2 base;
  int turn = 0;
};

// A piece of an arc: the arc of its conic inside the lens (a, b, c) from a to b.
struct Piece {
  int arc = -1, curve = -1;
  P2 a, b, c;      // chord a -> b; c where the tangents at a and b meet
  P2 da, db;       // the directions of a and b seen from the arc's base point (the tangent for the base)
  P2 m, dm;        // the conic's point of direction dm = da + db from the base: strictly inside the lens
  int lens_orient = 0;  // orient(a, b, c)
  int outer = 0;   // the conic's sign at c: the side of the arc away from its chord
  Box box;
};

struct Seg {
  P2 e, f;
  Box box;
};

// The second point of the conic on the line base + lambda d: Q(base) = 0, so lambda = -grad.d / form(d).
std::optional<P2> pencil_point(const Conic& q, const P2& base, const P2& d) {
  const Exact f = form(q, d);
  if (f == 0) return std::nullopt;
  const Exact lambda = -dot(grad(q, base), d) / f;
  return P2{base[0] + lambda * d[0], base[1] + lambda * d[1]};
}

bool in_closed(const P2& x, const P2& a, const P2& b, const P2& c, int o) {
  return orient(a, b, x) * o >= 0 && orient(b, c, x) * o >= 0 && orient(c, a, x) * o >= 0;
}
bool in_open(const P2& x, const P2& a, const P2& b, const P2& c, int o) {
  return orient(a, b, x) * o > 0 && orient(b, c, x) * o > 0 && orient(c, a, x) * o > 0;
}
bool in_lens(const P2& x, const Piece& p) { return in_closed(x, p.a, p.b, p.c, p.lens_orient); }

// The piece from a to b on arc k, certified: the lens exists with c on the side the arc bulges to, c is off
// the conic, and the conic point of direction da + db lies strictly inside the lens (then the conic meets
// the closed lens exactly in an arc from a to b: docs/theory.md). None when a test fails.
std::optional<Piece> make_piece(const Arc& arc, int k, int curve, const P2& a, const P2& da, const P2& b, const P2& db) {
  const P2 ga = grad(arc.q, a), gb = grad(arc.q, b);
  const Exact det = cross(ga, gb);
  if (det == 0 || a == b) return std::nullopt;
  const Exact ra = dot(ga, a), rb = dot(gb, b);
  Piece p;
  p.arc = k;
  p.curve = curve;
  p.a = a, p.b = b, p.da = da, p.db = db;
  p.c = {(ra * gb[1] - ga[1] * rb) / det, (ga[0] * rb - ra * gb[0]) / det};
  p.lens_orient = orient(a, b, p.c);
  if (p.lens_orient == 0 || p.lens_orient != -arc.turn) return std::nullopt;
  p.outer = CGAL::sign(eval(arc.q, p.c));
  if (p.outer == 0) return std::nullopt;
  p.dm = add(da, db);
  const auto m = pencil_point(arc.q, arc.base, p.dm);
  if (!m || !in_open(*m, a, b, p.c, p.lens_orient)) return std::nullopt;
  p.m = *m;
  p.box = box_of({&p.a, &p.b, &p.c});
  return p;
}

// Closed half-plane {x : orient(p, q, x) * o >= 0} of a convex point set given as a polygon (1 or 2 points
// allowed: a point, a segment). Exact Sutherland-Hodgman.
std::vector<P2> clip(const std::vector<P2>& poly, const P2& p, const P2& q, int o) {
  std::vector<P2> out;
  const std::size_t n = poly.size();
  if (n == 1) {
    if (orient(p, q, poly[0]) * o >= 0) out.push_back(poly[0]);
    return out;
  }
  const P2 d = sub(q, p);
  for (std::size_t i = 0; i < n; ++i) {
    const P2& x = poly[i];
    const P2& y = poly[(i + 1) % n];
    const Exact ox = cross(d, sub(x, p)), oy = cross(d, sub(y, p));
    const int sx = CGAL::sign(ox) * o, sy = CGAL::sign(oy) * o;
    if (sx >= 0) out.push_back(x);
    if ((sx > 0 && sy < 0) || (sx < 0 && sy > 0)) {
      const Exact s = ox / (ox - oy);
      out.push_back({x[0] + s * (y[0] - x[0]), x[1] + s * (y[1] - x[1])});
    }
  }
  std::vector<P2> uniq;
  for (const auto& x : out)
    if (std::find(uniq.begin(), uniq.end(), x) == uniq.end()) uniq.push_back(x);
  return uniq;
}
std::vector<P2> clip_lens(std::vector<P2> poly, const Piece& l) {
  const int o = l.lens_orient;
  poly = clip(poly, l.a, l.b, o);
  if (!poly.empty()) poly = clip(poly, l.b, l.c, o);
  if (!poly.empty()) poly = clip(poly, l.c, l.a, o);
  return poly;
}

bool on_closed_segment(const P2& x, const P2& e, const P2& f) {
  return orient(e, f, x) == 0 && dot(sub(x, e), sub(f, e)) >= 0 && dot(sub(x, f), sub(e, f)) >= 0;
}

// w (unoriented) in the closed cone of the piece's tangent directions, c - a to b - c (less than a half turn).
bool in_cone(const P2& w, const Piece& p) {
  const P2 u1 = sub(p.c, p.a), u2 = sub(p.b, p.c);
  return CGAL::sign(cross(w, u2)) * CGAL::sign(cross(u1, w)) >= 0;
}
bool cones_meet(const Piece& p, const Piece& q) {
  return in_cone(sub(q.c, q.a), p) || in_cone(sub(q.b, q.c), p) || in_cone(sub(p.c, p.a), q) ||
         in_cone(sub(p.b, p.c), q);
}

// Lenses with the common corner x on opposite closed sides of the tangent at x of one of them.
bool separated_at(const Piece& p, const Piece& q, const P2& x) {
  for (int k = 0; k < 2; ++k) {
    const Piece& s = k == 0 ? p : q;
    const Piece& t = k == 0 ? q : p;
    const P2& other = x == s.a ? s.b : s.a;
    const int side = orient(x, s.c, other);
    if (side != 0 && orient(x, s.c, t.a) * side <= 0 && orient(x, s.c, t.b) * side <= 0 &&
        orient(x, s.c, t.c) * side <= 0)
      return true;
  }
  return false;
}

// The intersection point of two non-parallel closed segments, if any; `overlap` when collinear and meeting.
std::optional<P2> segment_crossing(const Seg& s, const Seg& t, bool& overlap) {
  overlap = false;
  const P2 d1 = sub(s.f, s.e), d2 = sub(t.f, t.e);
  const Exact den = cross(d1, d2);
  if (den == 0) {
    if (orient(s.e, s.f, t.e) == 0)
      overlap = on_closed_segment(t.e, s.e, s.f) || on_closed_segment(t.f, s.e, s.f) ||
                on_closed_segment(s.e, t.e, t.f);
    return std::nullopt;
  }
  const P2 w = sub(t.e, s.e);
  const Exact a = cross(w, d2) / den, b = cross(w, d1) / den;
  if (a < 0 || a > 1 || b < 0 || b > 1) return std::nullopt;
  return P2{s.e[0] + a * d1[0], s.e[1] + a * d1[1]};
}

struct Certifier {
  const std::vector<Arc>& arcs;
  const std::vector<Seg>& segs;
  const std::vector<Piece>& pieces;
  std::vector<const P2*> vertices;  // every segment end and piece corner
  std::vector<Box> vertex_boxes;
  std::size_t v_fail = 0, s_fail = 0, a_fail = 0, t_fail = 0;

  Certifier(const std::vector<Arc>& a, const std::vector<Seg>& s, const std::vector<Piece>& p)
      : arcs(a), segs(s), pieces(p) {
    for (const auto& g : segs) vertices.push_back(&g.e), vertices.push_back(&g.f);
    for (const auto& q : pieces) vertices.push_back(&q.a), vertices.push_back(&q.b);
    for (const P2* v : vertices) vertex_boxes.push_back(box_of({v}));
  }

  bool adjacent(const Piece& p, const Piece& q) const {
    return p.curve == q.curve && (p.b == q.a || p.a == q.b);
  }

  // Marks pieces that fail a condition of docs/theory.md ("Certified polyline arrangement"), returns the
  // number marked. (V) no segment end or piece corner in the closed lens but the piece's own ends; (S) a
  // segment meeting the lens: through an end of the piece, only along that end's tangent side; else its
  // direction outside the piece's tangent cone; (A) another lens meeting it: with a common corner,
  // separated by a tangent there; else disjoint tangent cones; (T) no three of the piece and two
  // neighbours (segments or lenses) with a common point but the piece's ends.
  std::size_t mark(std::vector<char>& split) {
    std::size_t marked = 0;
    auto flag = [&](std::size_t i) {
      if (!split[i]) ++marked;
      split[i] = 1;
    };
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const Piece& p = pieces[i];
      bool bad = false;
      for (std::size_t k = 0; k < vertices.size() && !bad; ++k) {
        const P2& v = *vertices[k];
        if (!boxes_meet(vertex_boxes[k], p.box) || v == p.a || v == p.b) continue;
        if (in_lens(v, p)) bad = true, ++v_fail;
      }
      if (bad) {
        flag(i);
        continue;
      }
      std::vector<int> near_segs, near_pieces;
      for (std::size_t k = 0; k < segs.size() && !bad; ++k) {
        const Seg& s = segs[k];
        if (!boxes_meet(s.box, p.box)) continue;
        const std::vector<P2> in = clip_lens({s.e, s.f}, p);
        if (in.empty()) continue;
        near_segs.push_back(static_cast<int>(k));
        const bool at_a = on_closed_segment(p.a, s.e, s.f), at_b = on_closed_segment(p.b, s.e, s.f);
        if (at_a && at_b) bad = true;
        else if (at_a || at_b) {
          const P2& x = at_a ? p.a : p.b;
          for (const auto& y : in)
            if (!on_closed_segment(y, x, p.c)) bad = true;
        } else if (in_cone(sub(s.f, s.e), p)) {
          bad = true;
        }
        if (bad) ++s_fail;
      }
      if (bad) {
        flag(i);
        continue;
      }
      for (std::size_t k = 0; k < pieces.size(); ++k) {
        if (k == i) continue;
        const Piece& q = pieces[k];
        if (!boxes_meet(q.box, p.box)) continue;
        const std::vector<P2> common = clip_lens({q.a, q.b, q.c}, p);
        if (common.empty()) continue;
        near_pieces.push_back(static_cast<int>(k));
        if (adjacent(p, q)) continue;  // consecutive pieces of one arc meet only at their common end
        const bool shares = p.a == q.a || p.a == q.b || p.b == q.a || p.b == q.b;
        bool ok;
        if (shares) {
          // Lenses meeting only at the common end x, or separated there by a tangent: the curves meet
          // only at x during the deformation, in the same order around x.
          const bool both = (p.a == q.a || p.a == q.b) && (p.b == q.a || p.b == q.b);
          const P2& x = (p.a == q.a || p.a == q.b) ? p.a : p.b;
          ok = !both && ((common.size() == 1 && common[0] == x) || separated_at(p, q, x));
        } else {
          ok = !cones_meet(p, q);
        }
        if (!ok) {
          ++a_fail;
          flag(i);
          flag(k);
        }
      }
      // (T) triples.
      auto allowed = [&](const std::vector<P2>& k) { return k.empty() || (k.size() == 1 && (k[0] == p.a || k[0] == p.b)); };
      const std::size_t ns = near_segs.size(), np = near_pieces.size();
      for (std::size_t x = 0; x < ns + np && !bad; ++x)
        for (std::size_t y = x + 1; y < ns + np && !bad; ++y) {
          std::vector<P2> k;
          if (y < ns) {  // two segments
            bool overlap = false;
            const auto c = segment_crossing(segs[near_segs[x]], segs[near_segs[y]], overlap);
            if (c && in_lens(*c, p)) k.push_back(*c);
          } else if (x < ns) {  // a segment and a lens
            const Seg& s = segs[near_segs[x]];
            const Piece& q = pieces[near_pieces[y - ns]];
            if (!boxes_meet(s.box, q.box)) continue;
            k = clip_lens(clip_lens({s.e, s.f}, p), q);
          } else {
            const Piece& q = pieces[near_pieces[x - ns]];
            const Piece& r = pieces[near_pieces[y - ns]];
            if (!boxes_meet(q.box, r.box)) continue;
            k = clip_lens(clip_lens({q.a, q.b, q.c}, p), r);
          }
          if (!allowed(k)) {
            bad = true;
            ++t_fail;
            if (x >= ns) flag(static_cast<std::size_t>(near_pieces[x - ns]));
            if (y >= ns) flag(static_cast<std::size_t>(near_pieces[y - ns]));
          }
        }
      if (bad) flag(i);
    }
    return marked;
  }
};

using SegKernel = CGAL::Simple_cartesian<Exact>;
using SegTraits = CGAL::Arr_segment_traits_2<SegKernel>;
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<SegTraits, int>;  // data: piece index, -1 fixed
using Dcel = CGAL::Arr_face_extended_dcel<Traits, int>;
using Arrangement = CGAL::Arrangement_2<Traits, Dcel>;

int chord_piece(const Arrangement::Halfedge_const_handle& h) {
  for (int d : h->curve().data())
    if (d >= 0) return d;
  return -1;
}

struct DConic {
  std::array<double, 6> q;
  double eval(double x, double y) const { return (q[0] * x + q[1] * y + q[3]) * x + (q[2] * y + q[4]) * y + q[5]; }
  std::array<double, 2> grad(double x, double y) const {
    return {2 * q[0] * x + q[1] * y + q[3], q[1] * x + 2 * q[2] * y + q[4]};
  }
};
DConic dconic(const Conic& q) {
  DConic d;
  for (int i = 0; i < 6; ++i) d.q[i] = CGAL::to_double(q[i]);
  return d;
}

// The conic's root on the line x + tau w nearest to tau = 0 (doubles).
std::array<double, 2> nearest_on_line(const DConic& c, double x, double y, double wx, double wy) {
  const auto g = c.grad(x, y);
  const double A = c.q[0] * wx * wx + c.q[1] * wx * wy + c.q[2] * wy * wy, B = g[0] * wx + g[1] * wy, C = c.eval(x, y);
  double tau = 0;
  if (std::abs(A) * (wx * wx + wy * wy) < 1e-300 || B * B - 4 * A * C < 0) {
    if (B != 0) tau = -C / B;
  } else {
    const double sq = std::sqrt(B * B - 4 * A * C);
    const double r1 = (-B + sq) / (2 * A), r2 = (-B - sq) / (2 * A);
    tau = std::abs(r1) <= std::abs(r2) ? r1 : r2;
  }
  if (!std::isfinite(tau)) tau = 0;
  return {x + tau * wx, y + tau * wy};
}

// Where the arc of piece k meets the curve that makes the chord's vertex v (doubles): v itself at the
// piece's ends; on a crossing segment, the conic's point on the segment's line nearest v; on another chord,
// the two conics' common point near v (Newton from v).
std::array<double, 2> arc_vertex(const Arrangement::Vertex_const_handle& v, int k, const std::vector<Piece>& pieces,
                                 const std::vector<Arc>& arcs) {
  const double x = CGAL::to_double(v->point().x()), y = CGAL::to_double(v->point().y());
  const Piece& p = pieces[k];
  const P2 vp{v->point().x(), v->point().y()};
  if (vp == p.a || vp == p.b) return {x, y};
  const DConic c = dconic(arcs[p.arc].q);
  auto h0 = v->incident_halfedges();
  auto h = h0;
  do {
    const int d = chord_piece(h);
    if (d == k) continue;
    if (d < 0) {
      const double wx = CGAL::to_double(h->source()->point().x()) - x, wy = CGAL::to_double(h->source()->point().y()) - y;
      return nearest_on_line(c, x, y, wx, wy);
    }
    const DConic e = dconic(arcs[pieces[d].arc].q);
    double zx = x, zy = y;
    for (int it = 0; it < 30; ++it) {
      const auto g1 = c.grad(zx, zy), g2 = e.grad(zx, zy);
      const double f1 = c.eval(zx, zy), f2 = e.eval(zx, zy), det = g1[0] * g2[1] - g1[1] * g2[0];
      if (det == 0) break;
      zx -= (f1 * g2[1] - g1[1] * f2) / det;
      zy -= (g1[0] * f2 - f1 * g2[0]) / det;
    }
    if (std::isfinite(zx) && std::isfinite(zy)) return {zx, zy};
    return {x, y};
  } while (++h != h0);
  return {x, y};
}

// Boundary integral of (x dy - y dx) / 2 along the halfedge; a chord edge from x0 to x1 is replaced by the
// path x0, z0, the arc from z0 to z1, z1, x1 (z the arc's true vertices, arc_vertex; x0 -> z0 runs along the
// crossing curve), the arc through its points on the rays from the lens apex c through n + 1 points between
// the rays' chord points of z0 and z1 (the arc meets each such ray once, in the lens). The rays at the
// chord's ends are the tangents, where the arc point moves like the square root of the chord parameter:
// the points are cosine-graded, s = (1 - cos(pi j / n)) / 2, in which the arc is smooth, so the polygon's
// error is O(n^-2) with an even expansion and Richardson applies. Doubles.
double halfedge_area(const Arrangement::Halfedge_const_handle& h, const std::vector<Piece>& pieces,
                     const std::vector<Arc>& arcs, int n) {
  const double x0 = CGAL::to_double(h->source()->point().x()), y0 = CGAL::to_double(h->source()->point().y());
  const double x1 = CGAL::to_double(h->target()->point().x()), y1 = CGAL::to_double(h->target()->point().y());
  std::vector<std::array<double, 2>> pts{{x0, y0}};
  const int k = chord_piece(h);
  if (k >= 0) {
    const Piece& p = pieces[k];
    const DConic c = dconic(arcs[p.arc].q);
    const double cx = CGAL::to_double(p.c[0]), cy = CGAL::to_double(p.c[1]);
    const double ax = CGAL::to_double(p.a[0]), ay = CGAL::to_double(p.a[1]);
    const double bx = CGAL::to_double(p.b[0]), by = CGAL::to_double(p.b[1]);
    const auto z0 = arc_vertex(h->source(), k, pieces, arcs), z1 = arc_vertex(h->target(), k, pieces, arcs);
    // The chord point a + s (b - a) on the ray from c through z.
    auto chord_of = [&](const std::array<double, 2>& z) {
      const double zx = z[0] - cx, zy = z[1] - cy;
      const double den = (bx - ax) * zy - (by - ay) * zx;
      const double s = den == 0 ? 0 : -((ax - cx) * zy - (ay - cy) * zx) / den;
      return std::array<double, 2>{ax + s * (bx - ax), ay + s * (by - ay)};
    };
    const auto s0 = chord_of(z0), s1 = chord_of(z1);
    pts.push_back(z0);
    const double pi = std::acos(-1.0);
    for (int j = 1; j < n; ++j) {
      const double g = (1 - std::cos(pi * j / n)) / 2;
      const double wx = s0[0] + (s1[0] - s0[0]) * g - cx, wy = s0[1] + (s1[1] - s0[1]) * g - cy;
      pts.push_back(nearest_on_line(c, cx + wx, cy + wy, wx, wy));  // the arc point on the ray, near the chord
    }
    pts.push_back(z1);
  }
  pts.push_back({x1, y1});
  double a = 0;
  for (std::size_t j = 0; j + 1 < pts.size(); ++j) a += pts[j][0] * pts[j + 1][1] - pts[j + 1][0] * pts[j][1];
  return 0.5 * a;
}


}  // namespace

ReceiverArrangement polyline_arrangement(const std::vector<ArrangementCurve>& curves,
                                         const std::vector<std::array<Exact, 2>>& queries, int max_rounds) {
  ReceiverArrangement out;
  out.polyline = true;
  std::vector<Arc> arcs;
  std::vector<Seg> segs;
  std::vector<Piece> pieces;
  auto add_seg = [&](const P2& e, const P2& f) {
    if (e != f) segs.push_back({e, f, box_of({&e, &f})});
  };
  const P2 corner[3] = {{Exact(0), Exact(0)}, {Exact(1), Exact(0)}, {Exact(0), Exact(1)}};
  for (int k = 0; k < 3; ++k) add_seg(corner[k], corner[(k + 1) % 3]);
  // Identical curves (same points and conic) enter once: an arc overlapping itself cannot be certified.
  std::vector<const ArrangementCurve*> distinct;
  for (const auto& c : curves) {
    bool dup = false;
    for (const auto* d : distinct)
      if (d->points == c.points && d->conic == c.conic) dup = true;
    if (!dup) distinct.push_back(&c);
  }
  for (std::size_t ci = 0; ci < distinct.size(); ++ci) {
    const ArrangementCurve& c = *distinct[ci];
    std::vector<P2> pts;
    for (const auto& p : c.points)
      if (pts.empty() || pts.back() != p) pts.push_back(p);
    bool as_arc = false;
    if (c.conic && pts.size() >= 3 && pts.front() != pts.back()) {
      const Conic& q = *c.conic;
      const Exact det = 2 * q[0] * (4 * q[2] * q[5] - q[4] * q[4]) - q[1] * (2 * q[1] * q[5] - q[3] * q[4]) +
                        q[3] * (q[1] * q[4] - 2 * q[2] * q[3]);
      Arc arc{q, pts.front(), orient(pts.front(), pts[pts.size() / 2], pts.back())};
      bool ok = det != 0 && arc.turn != 0;
      for (const auto& p : pts) ok = ok && eval(q, p) == 0;
      std::vector<Piece> mine;
      if (ok) {
        const P2 g = grad(q, arc.base);
        P2 t{-g[1], g[0]};  // the tangent at the base, oriented along the arc
        if (CGAL::sign(cross(t, sub(pts[1], arc.base))) != arc.turn) t = {g[1], -g[0]};
        std::vector<P2> dirs{t};
        for (std::size_t k = 1; k < pts.size(); ++k) dirs.push_back(sub(pts[k], arc.base));
        for (std::size_t k = 0; k + 1 < pts.size() && ok; ++k) {
          auto pc = make_piece(arc, static_cast<int>(arcs.size()), static_cast<int>(ci), pts[k], dirs[k], pts[k + 1],
                               dirs[k + 1]);
          if (pc) mine.push_back(std::move(*pc));
          else ok = false;
        }
      }
      if (ok) {
        arcs.push_back(arc);
        for (auto& p : mine) pieces.push_back(std::move(p));
        as_arc = true;
        ++out.conic_arcs;
      } else {
        ++out.chord_curves;
      }
    }
    if (!as_arc)
      for (std::size_t k = 0; k + 1 < pts.size(); ++k) add_seg(pts[k], pts[k + 1]);
  }

  // A segment end or another curve's point exactly on an arc (a curve ending on it) becomes a piece end:
  // a point of the conic in a lens is on that lens's piece. Test (V) would reject it in every round.
  {
    std::vector<P2> verts;
    for (const auto& s : segs) verts.push_back(s.e), verts.push_back(s.f);
    for (const auto& p : pieces) verts.push_back(p.a), verts.push_back(p.b);
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    std::vector<Box> vboxes;
    for (const auto& v : verts) vboxes.push_back(box_of({&v}));
    for (bool again = true; again;) {
      again = false;
      std::vector<Piece> next;
      for (const Piece& p : pieces) {
        const Arc& arc = arcs[p.arc];
        std::optional<Piece> l, r;
        for (std::size_t k = 0; k < verts.size() && !l; ++k) {
          const P2& v = verts[k];
          if (v == p.a || v == p.b || v == arc.base || !boxes_meet(vboxes[k], p.box)) continue;
          if (!in_lens(v, p) || eval(arc.q, v) != 0) continue;
          const P2 dv = sub(v, arc.base);
          l = make_piece(arc, p.arc, p.curve, p.a, p.da, v, dv);
          r = make_piece(arc, p.arc, p.curve, v, dv, p.b, p.db);
          if (!l || !r) l.reset(), r.reset();
        }
        if (l && r) {
          next.push_back(std::move(*l));
          next.push_back(std::move(*r));
          again = true;
        } else {
          next.push_back(p);
        }
      }
      pieces = std::move(next);
    }
  }

  // Refine until certified (pieces kept in arc order: a split replaces a piece by its two halves).
  auto split_marked = [&](const std::vector<char>& split) {
    std::vector<Piece> next;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const Piece& p = pieces[i];
      if (!split[i]) {
        next.push_back(p);
        continue;
      }
      const Arc& arc = arcs[p.arc];
      auto l = make_piece(arc, p.arc, p.curve, p.a, p.da, p.m, p.dm);
      auto r = make_piece(arc, p.arc, p.curve, p.m, p.dm, p.b, p.db);
      if (!l || !r) throw std::logic_error("polyline_arrangement: a sub-piece of a certified piece failed");
      next.push_back(std::move(*l));
      next.push_back(std::move(*r));
    }
    pieces = std::move(next);
  };
  // The tests are quadratic in the pieces: refinement may at most quadruple the arcs' initial pieces (and
  // always reach 4000). A fixed 4000 refused, before any test, a town receiver with 668 arcs (10688 initial
  // pieces), which then fell back to the triangulation (session 11).
  const std::size_t max_pieces = std::max<std::size_t>(4000, 4 * pieces.size());
  for (int round = 0;; ++round) {
    std::vector<char> split(pieces.size(), 0);
    Certifier cert(arcs, segs, pieces);
    std::size_t marked = cert.mark(split);
    std::optional<ReceiverArrangement> built;
    if (marked == 0) {
      // Build and sample; a face without a sample outside every sliver marks the pieces at its candidates.
      Arrangement arr;
      std::vector<Traits::Curve_2> input;
      for (const auto& s : segs) input.emplace_back(SegKernel::Segment_2({s.e[0], s.e[1]}, {s.f[0], s.f[1]}), -1);
      for (std::size_t i = 0; i < pieces.size(); ++i)
        input.emplace_back(SegKernel::Segment_2({pieces[i].a[0], pieces[i].a[1]}, {pieces[i].b[0], pieces[i].b[1]}),
                           static_cast<int>(i));
      CGAL::insert(arr, input.begin(), input.end());
      ReceiverArrangement res = out;
      res.vertices = arr.number_of_vertices();
      res.edges = arr.number_of_edges();
      res.arc_pieces = pieces.size();
      std::vector<Exact> vx;
      for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) vx.push_back(v->point().x());
      std::sort(vx.begin(), vx.end());
      vx.erase(std::unique(vx.begin(), vx.end()), vx.end());
      auto in_some_sliver = [&](const P2& x, bool mark_them) {
        bool any = false;
        const Box b = box_of({&x});
        for (std::size_t i = 0; i < pieces.size(); ++i) {
          const Piece& p = pieces[i];
          if (!boxes_meet(b, p.box) || !in_lens(x, p)) continue;
          if (CGAL::sign(eval(arcs[p.arc].q, x)) == p.outer) continue;  // beyond the arc, towards c
          any = true;
          if (mark_them) split[i] = 1;
        }
        return any;
      };
      for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
        f->set_data(-1);
        if (f->is_unbounded()) continue;
        ReceiverArrangement::Face face;
        double a1 = 0, a2 = 0;
        auto add_ccb = [&](Arrangement::Ccb_halfedge_const_circulator c0) {
          auto c = c0;
          do {
            if (chord_piece(c) >= 0) face.conic_bounded = true;
            a1 += halfedge_area(c, pieces, arcs, 16);
            a2 += halfedge_area(c, pieces, arcs, 32);
          } while (++c != c0);
        };
        add_ccb(f->outer_ccb());
        for (auto ic = f->inner_ccbs_begin(); ic != f->inner_ccbs_end(); ++ic) add_ccb(*ic);
        face.area_uv = face.conic_bounded ? a2 + (a2 - a1) / 3 : a2;  // Richardson
        bool found = false, certified = false;
        std::vector<P2> candidates;
        auto c0 = f->outer_ccb();
        auto c = c0;
        do {
          const Arrangement::Halfedge_const_handle hc = c;
          const auto& cv = hc->curve();
          if (cv.is_vertical()) continue;
          const Exact xl = cv.left().x(), xr = cv.right().x();
          const auto nx = std::upper_bound(vx.begin(), vx.end(), xl);
          const Exact xhi = (nx != vx.end() && *nx < xr) ? *nx : xr;
          const Exact x0 = (xl + xhi) / 2;
          auto y_at = [&](const Traits::X_monotone_curve_2& s) {
            const auto& l = s.left();
            const auto& r = s.right();
            return l.y() + (x0 - l.x()) * (r.y() - l.y()) / (r.x() - l.x());
          };
          const Exact yc = y_at(cv);
          const bool above = hc->direction() == CGAL::ARR_LEFT_TO_RIGHT;
          std::optional<Exact> yb;
          for (auto ei = arr.edges_begin(); ei != arr.edges_end(); ++ei) {
            const Arrangement::Halfedge_const_handle e = ei;
            if (e == hc || e == hc->twin() || e->curve().is_vertical()) continue;
            if (!(e->curve().left().x() < x0 && x0 < e->curve().right().x())) continue;
            const Exact y = y_at(e->curve());
            if (above ? (y > yc && (!yb || y < *yb)) : (y < yc && (!yb || y > *yb))) yb = y;
          }
          if (!yb) continue;
          const P2 cand{x0, (yc + *yb) / 2};
          if (!found) face.sample = cand;
          found = true;
          candidates.push_back(cand);
          if (!in_some_sliver(cand, false)) {
            face.sample = cand;
            certified = true;
            break;
          }
        } while (++c != c0);
        if (!found) throw std::logic_error("polyline_arrangement: no sample found for a bounded face");
        if (!certified) {
          for (const auto& cand : candidates) in_some_sliver(cand, true);
          ++marked;
        }
        const auto& q = face.sample;
        if (!(q[0] > 0 && q[1] > 0 && q[0] + q[1] < 1)) continue;
        f->set_data(static_cast<int>(res.faces.size()));
        res.faces.push_back(std::move(face));
      }
      if (marked == 0) {
        const CGAL::Arr_naive_point_location<Arrangement> naive(arr);
        for (const auto& qp : queries)
          res.query_faces.push_back(arrangement_face_id<Arrangement>(naive.locate(SegKernel::Point_2(qp[0], qp[1]))));
        return res;
      }
    }
    if (round + 1 >= max_rounds || pieces.size() > max_pieces) {
      out.failed = true;
      out.failure = "polyline_arrangement: not certified after " + std::to_string(round + 1) + " rounds (" +
                    std::to_string(pieces.size()) + " pieces; failed tests: vertex " + std::to_string(cert.v_fail) +
                    ", segment " + std::to_string(cert.s_fail) + ", lens " + std::to_string(cert.a_fail) +
                    ", triple " + std::to_string(cert.t_fail) + ")";
      return out;
    }
    split_marked(split);
  }
}

}  // namespace exactvis::shadows
