#include "rational_geometry.hpp"

#include <algorithm>

namespace oracle {

QVec qvec(double x, double y, double z) { return {mpq_class(x), mpq_class(y), mpq_class(z)}; }
QVec operator+(const QVec& a, const QVec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
QVec operator-(const QVec& a, const QVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
QVec operator*(const mpq_class& s, const QVec& a) { return {s * a.x, s * a.y, s * a.z}; }
mpq_class dot(const QVec& a, const QVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
QVec cross(const QVec& a, const QVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
bool is_zero(const QVec& a) { return sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0; }
bool operator==(const QVec& a, const QVec& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
int sign(const mpq_class& x) { return sgn(x); }

QLine line_through(const QVec& p, const QVec& q) { return {q - p, cross(p, q)}; }
mpq_class side(const QLine& a, const QLine& b) { return dot(a.d, b.m) + dot(b.d, a.m); }
mpq_class quadric(const QLine& a) { return dot(a.d, a.m); }
QVec point_on(const QLine& l) { return mpq_class(1) / dot(l.d, l.d) * cross(l.d, l.m); }
bool on_line(const QVec& p, const QLine& l) { return cross(p, l.d) == l.m; }

namespace {

mpq_class det3(const std::array<std::array<mpq_class, 3>, 3>& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

mpq_class det4(const std::array<std::array<mpq_class, 4>, 4>& m) {
  mpq_class r = 0;
  for (int c = 0; c < 4; ++c) {
    std::array<std::array<mpq_class, 3>, 3> minor;
    for (int i = 1; i < 4; ++i) {
      int k = 0;
      for (int j = 0; j < 4; ++j)
        if (j != c) minor[i - 1][k++] = m[i][j];
    }
    const mpq_class term = m[0][c] * det3(minor);
    r += (c % 2 == 0) ? term : mpq_class(-term);
  }
  return r;
}

struct Interval {
  mpq_class lo, hi;
};
using MaybeInterval = std::optional<std::pair<mpq_class, mpq_class>>;

// Barycentric coordinates of a point X of the plane of a triangle with normal N != 0, up to the common
// positive factor |N|^2: lambda_i = N . ((t_j - X) x (t_k - X)).
std::array<mpq_class, 3> barycentric(const QVec& x, const QVec& t0, const QVec& t1, const QVec& t2) {
  const QVec n = cross(t1 - t0, t2 - t0);
  return {dot(n, cross(t1 - x, t2 - x)), dot(n, cross(t2 - x, t0 - x)), dot(n, cross(t0 - x, t1 - x))};
}

// Extreme pair of three collinear points: the segment they span (p == q if all equal).
std::pair<QVec, QVec> hull_segment(const QVec& t0, const QVec& t1, const QVec& t2) {
  const std::array<std::pair<QVec, QVec>, 3> pairs = {{{t0, t1}, {t1, t2}, {t0, t2}}};
  int best = 0;
  mpq_class bd = -1;
  for (int i = 0; i < 3; ++i) {
    const QVec e = pairs[i].second - pairs[i].first;
    const mpq_class d2 = dot(e, e);
    if (d2 > bd) {
      bd = d2;
      best = i;
    }
  }
  return pairs[best];
}

// {s in [0,1] : a + s e = p}, e = b - a != 0.
MaybeInterval point_param(const QVec& a, const QVec& b, const QVec& p) {
  const QVec e = b - a;
  const mpq_class s = dot(p - a, e) / dot(e, e);
  if (!(a + s * e == p) || s < 0 || s > 1) return std::nullopt;
  return std::make_pair(s, s);
}

// {s in [0,1] : a + s (b-a) in [c,d]}, a != b, c != d.
MaybeInterval segment_segment_interval(const QVec& a, const QVec& b, const QVec& c, const QVec& d) {
  const QVec e = b - a, f = d - c, w = c - a;
  const QVec exf = cross(e, f);
  if (!is_zero(exf)) {
    if (sgn(dot(w, exf)) != 0) return std::nullopt;  // skew
    const mpq_class n2 = dot(exf, exf);
    const mpq_class s = dot(cross(w, f), exf) / n2;
    const mpq_class u = dot(cross(w, e), exf) / n2;
    if (s < 0 || s > 1 || u < 0 || u > 1) return std::nullopt;
    return std::make_pair(s, s);
  }
  if (!is_zero(cross(w, e))) return std::nullopt;  // parallel, distinct lines
  const mpq_class ee = dot(e, e);
  mpq_class sc = dot(w, e) / ee, sd = dot(d - a, e) / ee;
  if (sc > sd) std::swap(sc, sd);
  const mpq_class lo = std::max(sc, mpq_class(0)), hi = std::min(sd, mpq_class(1));
  if (lo > hi) return std::nullopt;
  return std::make_pair(lo, hi);
}

}  // namespace

int orient3d(const QVec& a, const QVec& b, const QVec& c, const QVec& d) {
  std::array<std::array<mpq_class, 4>, 4> m;
  const std::array<const QVec*, 4> p = {&a, &b, &c, &d};
  for (int i = 0; i < 4; ++i) m[i] = {p[i]->x, p[i]->y, p[i]->z, mpq_class(1)};
  return -sgn(det4(m));
}

MaybeInterval segment_triangle_interval(const QVec& a, const QVec& b, const QVec& t0, const QVec& t1,
                                        const QVec& t2) {
  const QVec n = cross(t1 - t0, t2 - t0);
  const QVec e = b - a;
  if (is_zero(n)) {
    const auto [p, q] = hull_segment(t0, t1, t2);
    if (p == q) return point_param(a, b, p);
    return segment_segment_interval(a, b, p, q);
  }
  const mpq_class ha = dot(n, a - t0), hb = dot(n, b - t0);
  if (sgn(ha) == 0 && sgn(hb) == 0) {
    // Coplanar: clip [0,1] by the three in-plane half-planes (N x edge points inward).
    mpq_class lo = 0, hi = 1;
    const std::array<QVec, 3> t = {t0, t1, t2};
    for (int i = 0; i < 3; ++i) {
      const QVec w = cross(n, t[(i + 1) % 3] - t[i]);
      const mpq_class g0 = dot(w, a - t[i]), g1 = dot(w, e);
      if (sgn(g1) == 0) {
        if (g0 < 0) return std::nullopt;
      } else if (g1 > 0) {
        lo = std::max(lo, mpq_class(-g0 / g1));
      } else {
        hi = std::min(hi, mpq_class(-g0 / g1));
      }
    }
    if (lo > hi) return std::nullopt;
    return std::make_pair(lo, hi);
  }
  if (sgn(ha) * sgn(hb) > 0) return std::nullopt;
  const mpq_class s = ha / (ha - hb);
  const QVec x = a + s * e;
  for (const mpq_class& l : barycentric(x, t0, t1, t2))
    if (l < 0) return std::nullopt;
  return std::make_pair(s, s);
}

bool oracle_point_in_closed_triangle(const QVec& p, const QVec& t0, const QVec& t1, const QVec& t2) {
  const QVec n = cross(t1 - t0, t2 - t0);
  if (is_zero(n)) {
    const auto [a, b] = hull_segment(t0, t1, t2);
    if (a == b) return p == a;
    return point_param(a, b, p).has_value();
  }
  if (sgn(dot(n, p - t0)) != 0) return false;
  for (const mpq_class& l : barycentric(p, t0, t1, t2))
    if (l < 0) return false;
  return true;
}

bool oracle_point_in_triangle_relative_interior(const QVec& p, const QVec& t0, const QVec& t1, const QVec& t2) {
  const QVec n = cross(t1 - t0, t2 - t0);
  if (is_zero(n)) {
    const auto [a, b] = hull_segment(t0, t1, t2);
    if (a == b) return p == a;
    const auto r = point_param(a, b, p);
    return r && r->first > 0 && r->first < 1;
  }
  if (sgn(dot(n, p - t0)) != 0) return false;
  for (const mpq_class& l : barycentric(p, t0, t1, t2))
    if (l <= 0) return false;
  return true;
}

bool oracle_closed_segment_meets_closed_triangle(const QVec& a, const QVec& b, const QVec& t0, const QVec& t1,
                                                 const QVec& t2) {
  if (a == b) return oracle_point_in_closed_triangle(a, t0, t1, t2);
  return segment_triangle_interval(a, b, t0, t1, t2).has_value();
}

bool oracle_open_segment_meets_closed_triangle(const QVec& a, const QVec& b, const QVec& t0, const QVec& t1,
                                               const QVec& t2) {
  if (a == b) return false;
  const auto r = segment_triangle_interval(a, b, t0, t1, t2);
  return r && r->second > 0 && r->first < 1;
}

bool oracle_segment_crosses_triangle_interior(const QVec& a, const QVec& b, const QVec& t0, const QVec& t1,
                                              const QVec& t2) {
  const QVec n = cross(t1 - t0, t2 - t0);
  if (is_zero(n)) return false;
  const mpq_class ha = dot(n, a - t0), hb = dot(n, b - t0);
  if (sgn(ha) * sgn(hb) >= 0) return false;
  const QVec x = a + mpq_class(ha / (ha - hb)) * (b - a);
  for (const mpq_class& l : barycentric(x, t0, t1, t2))
    if (l <= 0) return false;
  return true;
}

bool oracle_point_in_closed_box(const QVec& p, const QVec& lo, const QVec& hi) {
  return lo.x <= p.x && p.x <= hi.x && lo.y <= p.y && p.y <= hi.y && lo.z <= p.z && p.z <= hi.z;
}
bool oracle_point_in_open_box(const QVec& p, const QVec& lo, const QVec& hi) {
  return lo.x < p.x && p.x < hi.x && lo.y < p.y && p.y < hi.y && lo.z < p.z && p.z < hi.z;
}

namespace {
// (x0 + x1 r)(y0 + y1 r) with r^2 = root.
std::pair<mpq_class, mpq_class> mul(const mpq_class& x0, const mpq_class& x1, const mpq_class& y0,
                                    const mpq_class& y1, const mpq_class& root) {
  return {x0 * y0 + x1 * y1 * root, x0 * y1 + x1 * y0};
}
}  // namespace

bool is_zero_in_extension(const mpq_class& x, const mpq_class& y, const mpq_class& root) {
  if (sgn(y) == 0 || sgn(root) == 0) return sgn(x) == 0;
  if (sgn(x) == 0) return false;
  if (sgn(x) == sgn(y)) return false;
  return x * x == y * y * root;
}

int sign_in_extension(const mpq_class& x, const mpq_class& y, const mpq_class& root) {
  const int sx = sgn(x), sy = sgn(root) == 0 ? 0 : sgn(y);
  if (sy == 0) return sx;
  if (sx == 0 || sx == sy) return sy;
  const int c = cmp(mpq_class(x * x), mpq_class(y * y * root));  // |x| vs |y| sqrt(root)
  return c > 0 ? sx : (c < 0 ? sy : 0);
}

int side_sign(const RootLine& x, const QLine& l) {
  const std::array<mpq_class, 6> v = {l.d.x, l.d.y, l.d.z, l.m.x, l.m.y, l.m.z};
  mpq_class s0 = 0, s1 = 0;
  for (int i = 0; i < 3; ++i) {
    s0 += x.a[i] * v[i + 3] + x.a[i + 3] * v[i];
    s1 += x.b[i] * v[i + 3] + x.b[i + 3] * v[i];
  }
  return sign_in_extension(s0, s1, x.root);
}

bool on_line(const RootPoint& p, const RootLine& x) {
  const mpq_class root = sgn(p.root) != 0 ? p.root : x.root;
  // (p x d)_i = p_j d_k - p_k d_j, compared with m_i, all in Q(sqrt(root)).
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const auto [u0, u1] = mul(p.a[j], p.b[j], x.a[k], x.b[k], root);
    const auto [w0, w1] = mul(p.a[k], p.b[k], x.a[j], x.b[j], root);
    if (!is_zero_in_extension(u0 - w0 - x.a[i + 3], u1 - w1 - x.b[i + 3], root)) return false;
  }
  return true;
}

bool on_line(const RootPoint& p, const QLine& l) {
  RootLine x;
  const std::array<mpq_class, 6> v = {l.d.x, l.d.y, l.d.z, l.m.x, l.m.y, l.m.z};
  for (int i = 0; i < 6; ++i) x.a[i] = v[i], x.b[i] = 0;
  x.root = p.root;
  return on_line(p, x);
}

bool check_transversal(const RootLine& x, const std::array<QLine, 4>& lines, std::string* why) {
  bool d_zero = true;
  for (int i = 0; i < 3; ++i)
    if (!is_zero_in_extension(x.a[i], x.b[i], x.root)) d_zero = false;
  if (d_zero) {
    if (why) *why = "direction is zero";
    return false;
  }
  mpq_class q0 = 0, q1 = 0;
  for (int i = 0; i < 3; ++i) {
    const auto [p0, p1] = mul(x.a[i], x.b[i], x.a[i + 3], x.b[i + 3], x.root);
    q0 += p0;
    q1 += p1;
  }
  if (!is_zero_in_extension(q0, q1, x.root)) {
    if (why) *why = "not on the Pluecker quadric (d.m != 0)";
    return false;
  }
  for (int k = 0; k < 4; ++k) {
    const std::array<mpq_class, 6> l = {lines[k].d.x, lines[k].d.y, lines[k].d.z,
                                        lines[k].m.x, lines[k].m.y, lines[k].m.z};
    // side(x, l) = d_x . m_l + m_x . d_l
    mpq_class s0 = 0, s1 = 0;
    for (int i = 0; i < 3; ++i) {
      s0 += x.a[i] * l[i + 3] + x.a[i + 3] * l[i];
      s1 += x.b[i] * l[i + 3] + x.b[i + 3] * l[i];
    }
    if (!is_zero_in_extension(s0, s1, x.root)) {
      if (why) *why = "does not meet input line " + std::to_string(k);
      return false;
    }
  }
  return true;
}

bool same_line(const RootLine& x, const RootLine& y) {
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) {
      const auto [p0, p1] = mul(x.a[i], x.b[i], y.a[j], y.b[j], x.root);
      const auto [q0, q1] = mul(x.a[j], x.b[j], y.a[i], y.b[i], x.root);
      if (!is_zero_in_extension(p0 - q0, p1 - q1, x.root)) return false;
    }
  return true;
}

int count_transversals_via_quadric(const std::array<QLine, 4>& l) {
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (sgn(side(l[i], l[j])) == 0) return -2;
  auto f = [&](const QVec& x) {
    std::array<std::array<mpq_class, 3>, 3> m;
    for (int i = 0; i < 3; ++i) {
      const QVec n = cross(x, l[i].d) - l[i].m;
      m[i] = {n.x, n.y, n.z};
    }
    return det3(m);
  };
  const QVec p = point_on(l[3]);
  auto g = [&](int s) { return f(p + mpq_class(s) * l[3].d); };
  const mpq_class g0 = g(0), g1 = g(1), gm = g(-1), g2 = g(2);
  const mpq_class alpha = (g1 + gm) / 2 - g0, beta = (g1 - gm) / 2, gamma = g0;
  if (g2 != 4 * alpha + 2 * beta + gamma || g(3) != 9 * alpha + 3 * beta + gamma) return -3;
  if (sgn(alpha) == 0 && sgn(beta) == 0 && sgn(gamma) == 0) return -1;
  const mpq_class disc = beta * beta - 4 * alpha * gamma;
  return sgn(disc) > 0 ? 2 : (sgn(disc) == 0 ? 1 : 0);
}

}  // namespace oracle
