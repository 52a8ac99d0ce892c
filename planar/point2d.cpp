#include "planar/point2d.hpp"

#include "kernel/line_intersection_2d.hpp"

namespace exactvis {

namespace {
// CGAL::to_double (mpq_get_d, truncation towards 0) read off the tight enclosure: its end nearer to 0.
double truncated(const Exact& v, const Interval& i) {
  if (!std::isfinite(i.inf()) || !std::isfinite(i.sup())) return CGAL::to_double(v);
  return CGAL::sign(v) < 0 ? i.sup() : i.inf();
}
}  // namespace

Point2::Point2(const Exact& X, const Exact& Y) : x(X), y(Y), ix(tight_interval(X)), iy(tight_interval(Y)) {
  ax = truncated(X, ix);
  ay = truncated(Y, iy);
}

namespace {
// p's coordinates are doubles (point enclosures; then ax, ay are them): the kernel's semi-static filters
// on doubles apply.
bool has_double_coordinates(const Point2& p) { return p.ix.inf() == p.ix.sup() && p.iy.inf() == p.iy.sup(); }

// Layer 1 of the cross-product predicates: the hand-written filter on double coordinates, else the
// expression in BoundedDouble on the enclosures.
template <class Expr>
std::optional<Sign> cross_semi_static(const Point2& u0, const Point2& u1, const Point2& v0, const Point2& v1,
                                      Expr& expr) {
  if (has_double_coordinates(u0) && has_double_coordinates(u1) && has_double_coordinates(v0) &&
      has_double_coordinates(v1))
    return cross2d_semi_static(u0.ax, u0.ay, u1.ax, u1.ay, v0.ax, v0.ay, v1.ax, v1.ay);
  return expr(NumberTag<BoundedDouble>{}).certified_sign();
}
}  // namespace

Sign orientation2(const Point2& a, const Point2& b, const Point2& c) {
  static PredicateCounter counter("orientation2");
  auto expr = [&](auto nt) {
    using NT = typename decltype(nt)::type;
    const NT ax = px<NT>(a), ay = py<NT>(a);
    return (px<NT>(b) - ax) * (py<NT>(c) - ay) - (py<NT>(b) - ay) * (px<NT>(c) - ax);
  };
  return filtered_sign_with(counter, [&] { return cross_semi_static(a, b, a, c, expr); }, expr);
}

Sign cross_sign(const Point2& u0, const Point2& u1, const Point2& v0, const Point2& v1) {
  static PredicateCounter counter("cross_sign2");
  auto expr = [&](auto nt) {
    using NT = typename decltype(nt)::type;
    return (px<NT>(u1) - px<NT>(u0)) * (py<NT>(v1) - py<NT>(v0)) -
           (py<NT>(u1) - py<NT>(u0)) * (px<NT>(v1) - px<NT>(v0));
  };
  return filtered_sign_with(counter, [&] { return cross_semi_static(u0, u1, v0, v1, expr); }, expr);
}

Sign dot_sign(const Point2& u0, const Point2& u1, const Point2& v0, const Point2& v1) {
  static PredicateCounter counter("dot_sign2");
  return filtered_sign(counter, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    return (px<NT>(u1) - px<NT>(u0)) * (px<NT>(v1) - px<NT>(v0)) +
           (py<NT>(u1) - py<NT>(u0)) * (py<NT>(v1) - py<NT>(v0));
  });
}

Sign dx_sign(const Point2& u0, const Point2& u1) {
  static PredicateCounter counter("dx_sign2");
  auto expr = [&](auto nt) {
    using NT = typename decltype(nt)::type;
    return px<NT>(u1) - px<NT>(u0);
  };
  return filtered_sign_with(counter, [&]() -> std::optional<Sign> {
    if (u0.ix.inf() == u0.ix.sup() && u1.ix.inf() == u1.ix.sup()) return difference_sign(u0.ax, u1.ax);
    return expr(NumberTag<BoundedDouble>{}).certified_sign();
  }, expr);
}

Sign dy_sign(const Point2& u0, const Point2& u1) {
  static PredicateCounter counter("dy_sign2");
  auto expr = [&](auto nt) {
    using NT = typename decltype(nt)::type;
    return py<NT>(u1) - py<NT>(u0);
  };
  return filtered_sign_with(counter, [&]() -> std::optional<Sign> {
    if (u0.iy.inf() == u0.iy.sup() && u1.iy.inf() == u1.iy.sup()) return difference_sign(u0.ay, u1.ay);
    return expr(NumberTag<BoundedDouble>{}).certified_sign();
  }, expr);
}

namespace {
// 0 for directions with angle in [0, pi), 1 for [pi, 2pi).
int half_of(const Point2& u0, const Point2& u1) {
  const Sign sy = dy_sign(u0, u1);
  if (sy == Sign::Positive) return 0;
  if (sy == Sign::Negative) return 1;
  return dx_sign(u0, u1) == Sign::Positive ? 0 : 1;
}
}  // namespace

int compare_angle(const Point2& u0, const Point2& u1, const Point2& v0, const Point2& v1) {
  const int hu = half_of(u0, u1), hv = half_of(v0, v1);
  if (hu != hv) return hu < hv ? -1 : 1;
  const Sign s = cross_sign(u0, u1, v0, v1);
  return s == Sign::Positive ? -1 : (s == Sign::Negative ? 1 : 0);
}

bool in_open_ccw_sector(const Point2& d0, const Point2& d1, const Point2& a0, const Point2& a1,
                        const Point2& b0, const Point2& b1) {
  const Sign ab = cross_sign(a0, a1, b0, b1);
  if (ab == Sign::Positive)  // sector narrower than pi
    return cross_sign(a0, a1, d0, d1) == Sign::Positive && cross_sign(d0, d1, b0, b1) == Sign::Positive;
  if (ab == Sign::Negative)  // wider than pi: not in the closed complementary sector [b, a]
    return !(cross_sign(b0, b1, d0, d1) != Sign::Negative && cross_sign(d0, d1, a0, a1) != Sign::Negative);
  if (dot_sign(a0, a1, b0, b1) == Sign::Negative)  // exactly pi: open half-plane left of a
    return cross_sign(a0, a1, d0, d1) == Sign::Positive;
  // a and b have the same direction: everything but that direction
  return !(cross_sign(a0, a1, d0, d1) == Sign::Zero && dot_sign(a0, a1, d0, d1) == Sign::Positive);
}

Point2 line_intersection(const Point2& c, const Point2& d0, const Point2& d1, const Point2& a, const Point2& b) {
  // All coordinates doubles (point enclosures): the kernel's integer construction, without a gcd per operation.
  auto is_double = [](const Point2& p) { return p.ix.inf() == p.ix.sup() && p.iy.inf() == p.iy.sup(); };
  if (is_double(c) && is_double(d0) && is_double(d1) && is_double(a) && is_double(b)) {
    const auto x = line_intersection_2d({c.ax, c.ay}, {d0.ax, d0.ay}, {d1.ax, d1.ay}, {a.ax, a.ay}, {b.ax, b.ay});
    return Point2(x[0], x[1]);
  }
  const Exact dx = d1.x - d0.x, dy = d1.y - d0.y;
  const Exact ex = b.x - a.x, ey = b.y - a.y;
  const Exact den = dx * ey - dy * ex;
  const Exact t = ((a.x - c.x) * ey - (a.y - c.y) * ex) / den;
  return Point2(c.x + t * dx, c.y + t * dy);
}

namespace {
// p on the closed segment [a,b], given that a, b, p are collinear.
bool on_collinear_segment(const Point2& a, const Point2& b, const Point2& p) {
  return dot_sign(p, a, p, b) != Sign::Positive;
}
}  // namespace

bool segments_intersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const Sign o1 = orientation2(a, b, c), o2 = orientation2(a, b, d);
  const Sign o3 = orientation2(c, d, a), o4 = orientation2(c, d, b);
  if (o1 != Sign::Zero && o1 == o2) return false;
  if (o3 != Sign::Zero && o3 == o4) return false;
  if (o1 == Sign::Zero && o2 == Sign::Zero) {  // collinear: overlap of the projections
    return on_collinear_segment(a, b, c) || on_collinear_segment(a, b, d) || on_collinear_segment(c, d, a) ||
           on_collinear_segment(c, d, b);
  }
  return true;
}

}  // namespace exactvis
