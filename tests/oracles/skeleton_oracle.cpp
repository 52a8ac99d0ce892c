#include "oracles/skeleton_oracle.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace skeleton_oracle {
namespace {

using V3 = std::array<Q, 3>;

int sgn(const Q& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

// ---- Q(sqrt r)
struct Field {
  Q r;
  QS add(const QS& x, const QS& y) const { return {x.a + y.a, x.b + y.b}; }
  QS sub(const QS& x, const QS& y) const { return {x.a - y.a, x.b - y.b}; }
  QS mul(const QS& x, const QS& y) const { return {x.a * y.a + x.b * y.b * r, x.a * y.b + x.b * y.a}; }
  QS div(const QS& x, const QS& y) const {
    const Q n = y.a * y.a - y.b * y.b * r;  // != 0 for y != 0 when r is not a square; else see sign()
    if (n == 0) {
      // r is a square s^2 and y = a + b s with a = -b s... (y = 0 as a real number) or a = b s.
      throw std::runtime_error("oracle: division in a split extension");
    }
    const QS c{y.a, -y.b};
    const QS p = mul(x, c);
    return {p.a / n, p.b / n};
  }
  int sign(const QS& x) const {
    const int sa = sgn(x.a), sb = sgn(x.b);
    if (sb == 0 || r == 0) return sa;
    if (sa == 0) return sb;
    if (sa == sb) return sa;
    // a and b sqrt(r) of opposite signs: compare a^2 with b^2 r.
    const Q l = x.a * x.a, rr = x.b * x.b * r;
    if (l == rr) return 0;
    return l > rr ? sa : sb;
  }
  bool zero(const QS& x) const { return sign(x) == 0; }
  QS3 add(const QS3& x, const QS3& y) const { return {add(x[0], y[0]), add(x[1], y[1]), add(x[2], y[2])}; }
  QS3 sub(const QS3& x, const QS3& y) const { return {sub(x[0], y[0]), sub(x[1], y[1]), sub(x[2], y[2])}; }
  QS3 scale(const QS& s, const QS3& x) const { return {mul(s, x[0]), mul(s, x[1]), mul(s, x[2])}; }
  QS dot(const QS3& x, const QS3& y) const { return add(add(mul(x[0], y[0]), mul(x[1], y[1])), mul(x[2], y[2])); }
  QS3 cross(const QS3& x, const QS3& y) const {
    return {sub(mul(x[1], y[2]), mul(x[2], y[1])), sub(mul(x[2], y[0]), mul(x[0], y[2])),
            sub(mul(x[0], y[1]), mul(x[1], y[0]))};
  }
  bool zero(const QS3& x) const { return zero(x[0]) && zero(x[1]) && zero(x[2]); }
  QS det(const QS3& x, const QS3& y, const QS3& z) const { return dot(cross(x, y), z); }
};

QS3 lift(const V3& p) { return {QS{p[0], 0}, QS{p[1], 0}, QS{p[2], 0}}; }

bool has_corner(const std::array<int, 3>& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }
bool has_edge(const std::array<int, 3>& t, const std::array<int, 2>& e) {
  for (int k = 0; k < 3; ++k) {
    const int a = t[k], b = t[(k + 1) % 3];
    if ((a == e[0] && b == e[1]) || (a == e[1] && b == e[0])) return true;
  }
  return false;
}

// Parameter u of the point where the line meets edge line a + u (b - a) (nullopt: parallel or skew).
std::optional<QS> edge_parameter(const Field& f, const Line& l, const V3& a, const V3& b) {
  const QS3 A = lift(a), W = f.sub(lift(b), A);
  const QS3 c = f.cross(W, l.d);
  if (f.zero(c)) return std::nullopt;
  const QS3 g = f.cross(f.sub(A, l.p), l.d);  // g + u c = 0
  int k = 0;
  while (f.zero(c[k])) ++k;
  const QS u = f.div(QS{-g[k].a, -g[k].b}, c[k]);
  const QS3 res = f.add(g, f.scale(u, c));
  if (!f.zero(res)) return std::nullopt;
  return u;
}

// The generator points: vertices, then the edges' meeting points (nullopt if some edge is not met).
std::optional<std::vector<QS3>> generator_points(const Field& f, const Mesh& m, const Generators& g, const Line& l,
                                                 bool require_interior, std::string* why) {
  std::vector<QS3> pts;
  for (int v : g.vertices) pts.push_back(lift(m.v[v]));
  for (const auto& e : g.edges) {
    const auto u = edge_parameter(f, l, m.v[e[0]], m.v[e[1]]);
    if (!u) {
      if (why) *why = "does not meet an edge's line";
      return std::nullopt;
    }
    if (require_interior && (f.sign(*u) <= 0 || f.sign(f.sub(*u, QS{1, 0})) >= 0)) {
      if (why) *why = "meets an edge's line outside its relative interior";
      return std::nullopt;
    }
    const QS3 A = lift(m.v[e[0]]);
    pts.push_back(f.add(A, f.scale(*u, f.sub(lift(m.v[e[1]]), A))));
  }
  return pts;
}

// Does the open segment (x, y) meet closed triangle t?
bool open_segment_meets(const Field& f, const QS3& x, const QS3& y, const V3& a0, const V3& b0, const V3& c0) {
  const QS3 a = lift(a0), b = lift(b0), c = lift(c0);
  const QS3 n = f.cross(f.sub(b, a), f.sub(c, a));
  const QS3 dir = f.sub(y, x);
  const QS h0 = f.dot(n, f.sub(x, a)), h1 = f.dot(n, dir);
  const QS3* v[3] = {&a, &b, &c};
  if (!f.zero(h1)) {
    const QS lam = f.div(QS{-h0.a, -h0.b}, h1);
    if (f.sign(lam) <= 0 || f.sign(f.sub(lam, QS{1, 0})) >= 0) return false;
    const QS3 p = f.add(x, f.scale(lam, dir));
    for (int k = 0; k < 3; ++k)
      if (f.sign(f.dot(f.cross(f.sub(*v[(k + 1) % 3], *v[k]), f.sub(p, *v[k])), n)) < 0) return false;
    return true;
  }
  if (!f.zero(h0)) return false;
  // Coplanar: {lam : g_k(lam) >= 0} as [lo, hi], then against (0, 1).
  std::optional<QS> lo, hi;
  for (int k = 0; k < 3; ++k) {
    const QS3 e = f.sub(*v[(k + 1) % 3], *v[k]);
    const QS g0 = f.dot(f.cross(e, f.sub(x, *v[k])), n), g1 = f.dot(f.cross(e, dir), n);
    if (f.zero(g1)) {
      if (f.sign(g0) < 0) return false;
      continue;
    }
    const QS root = f.div(QS{-g0.a, -g0.b}, g1);
    if (f.sign(g1) > 0) {
      if (!lo || f.sign(f.sub(root, *lo)) > 0) lo = root;
    } else if (!hi || f.sign(f.sub(root, *hi)) < 0) {
      hi = root;
    }
  }
  if (lo && hi && f.sign(f.sub(*hi, *lo)) < 0) return false;
  if (lo && f.sign(f.sub(*lo, QS{1, 0})) >= 0) return false;
  if (hi && f.sign(*hi) <= 0) return false;
  return true;
}

// Parity of crossings of the ray x + lam r (lam > 0) with the infinite cones (v; a, b) of `tris`; nullopt
// when the ray touches a cone's boundary (choose another r).
std::optional<int> cone_parity(const Field& f, const Mesh& m, int v, const std::vector<int>& tris, const QS3& x,
                               const V3& r0) {
  const QS3 V = lift(m.v[v]), r = lift(r0);
  int parity = 0;
  for (int ti : tris) {
    const auto& t = m.t[ti];
    int k = 0;
    while (t[k] != v) ++k;
    const QS3 a = f.sub(lift(m.v[t[(k + 1) % 3]]), V), b = f.sub(lift(m.v[t[(k + 2) % 3]]), V);
    // x + lam r = V + s a + u b  <=>  lam r - s a - u b = V - x
    const QS3 rhs = f.sub(V, x);
    const QS3 na{QS{-a[0].a, 0}, QS{-a[1].a, 0}, QS{-a[2].a, 0}}, nb{QS{-b[0].a, 0}, QS{-b[1].a, 0}, QS{-b[2].a, 0}};
    const QS det = f.det(r, na, nb);
    if (f.zero(det)) {
      // r parallel to the cone's plane: a crossing is impossible unless x is in that plane.
      if (f.zero(f.det(a, b, f.sub(x, V)))) return std::nullopt;
      continue;
    }
    const QS lam = f.div(f.det(rhs, na, nb), det), s = f.div(f.det(r, rhs, nb), det), u = f.div(f.det(r, na, rhs), det);
    const int sl = f.sign(lam), ss = f.sign(s), su = f.sign(u);
    if (sl < 0 || ss < 0 || su < 0) continue;
    if (sl == 0 || ss == 0 || su == 0) return std::nullopt;
    parity ^= 1;
  }
  return parity;
}

bool vertex_rule(const Field& f, const Mesh& m, int v, const QS3& d, std::string* why) {
  std::vector<int> fan;
  for (std::size_t i = 0; i < m.t.size(); ++i)
    if (has_corner(m.t[i], v)) fan.push_back(static_cast<int>(i));
  const QS3 V = lift(m.v[v]);
  // (a)
  for (int ti : fan) {
    const auto& t = m.t[ti];
    int k = 0;
    while (t[k] != v) ++k;
    const QS3 a = f.sub(lift(m.v[t[(k + 1) % 3]]), V), b = f.sub(lift(m.v[t[(k + 2) % 3]]), V);
    const QS3 n = f.cross(a, b);
    if (!f.zero(f.dot(n, d))) continue;
    const int alpha = f.sign(f.dot(f.cross(d, b), n)), beta = f.sign(f.dot(f.cross(a, d), n));
    if ((alpha >= 0 && beta >= 0) || (alpha <= 0 && beta <= 0)) {
      if (why) *why = "vertex rule (a) fails at vertex " + std::to_string(v);
      return false;
    }
  }
  // (b): link graph; all degrees 2 -> cycles -> parity test per cycle.
  std::map<int, std::vector<int>> link;  // link vertex -> fan triangles using it
  for (int ti : fan)
    for (int c : m.t[ti])
      if (c != v) link[c].push_back(ti);
  for (const auto& [w, ts] : link)
    if (ts.size() != 2) return true;  // open or non-manifold fan: rule (a) only
  std::set<int> seen;
  for (int start : fan) {
    if (seen.count(start)) continue;
    std::vector<int> comp, stack{start};
    seen.insert(start);
    while (!stack.empty()) {
      const int ti = stack.back();
      stack.pop_back();
      comp.push_back(ti);
      for (int c : m.t[ti])
        if (c != v)
          for (int o : link[c])
            if (!seen.count(o)) seen.insert(o), stack.push_back(o);
    }
    const V3 rays[] = {{1, 2, 3}, {3, -1, 7}, {-2, 5, 1}, {7, 3, -4}, {1, -5, 2}, {-3, -7, 11}, {13, 2, 5}, {2, 11, -9}};
    bool decided = false;
    for (const V3& r : rays) {
      const auto p1 = cone_parity(f, m, v, comp, f.add(V, d), r);
      const auto p2 = cone_parity(f, m, v, comp, f.sub(V, d), r);
      if (!p1 || !p2) continue;
      decided = true;
      if (*p1 != *p2) {
        if (why) *why = "vertex rule (b): the line enters the solid at vertex " + std::to_string(v);
        return false;
      }
      break;
    }
    if (!decided) throw std::runtime_error("oracle: no generic reference ray for the cone parity");
  }
  return true;
}

std::string key_of(const std::string& kind, std::vector<int> vs, std::vector<std::array<int, 2>> es) {
  std::sort(vs.begin(), vs.end());
  std::sort(es.begin(), es.end());
  std::ostringstream os;
  os << kind;
  for (int v : vs) os << " " << v;
  for (const auto& e : es) os << " " << e[0] << " " << e[1];
  return os.str();
}

}  // namespace

bool passes_through(const Line& l, const std::array<Q, 3>& x) {
  const Field f{l.r};
  return f.zero(f.cross(f.sub(lift(x), l.p), l.d));
}

bool lies_in_plane(const Mesh& m, const Line& l, int triangle) {
  const Field f{l.r};
  const auto& t = m.t[triangle];
  const QS3 a = lift(m.v[t[0]]);
  const QS3 n = f.cross(f.sub(lift(m.v[t[1]]), a), f.sub(lift(m.v[t[2]]), a));
  return f.zero(f.dot(n, l.d)) && f.zero(f.dot(n, f.sub(l.p, a)));
}

bool meets_edge_interior(const Mesh& m, const Line& l, const std::array<int, 2>& e) {
  const Field f{l.r};
  const auto u = edge_parameter(f, l, m.v[e[0]], m.v[e[1]]);
  return u && f.sign(*u) > 0 && f.sign(f.sub(*u, QS{1, 0})) < 0;
}

bool segment_free(const Mesh& m, const Generators& g, const Line& l, std::string* why) {
  const Field f{l.r};
  const auto pts = generator_points(f, m, g, l, false, why);
  if (!pts || pts->empty()) return false;
  std::size_t lo = 0, hi = 0;
  std::vector<QS> s;
  for (const auto& p : *pts) s.push_back(f.dot(f.sub(p, l.p), l.d));
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (f.sign(f.sub(s[i], s[lo])) < 0) lo = i;
    if (f.sign(f.sub(s[i], s[hi])) > 0) hi = i;
  }
  for (std::size_t ti = 0; ti < m.t.size(); ++ti) {
    const auto& t = m.t[ti];
    bool incident = false;
    for (int v : g.vertices) incident = incident || has_corner(t, v);
    for (const auto& e : g.edges) incident = incident || has_edge(t, e);
    for (int f : g.faces)
      for (int c : m.t[f]) incident = incident || has_corner(t, c);
    if (incident) continue;
    if (open_segment_meets(f, (*pts)[lo], (*pts)[hi], m.v[t[0]], m.v[t[1]], m.v[t[2]])) {
      if (why) *why = "the spanned segment meets triangle " + std::to_string(ti);
      return false;
    }
  }
  return true;
}

bool valid_line(const Mesh& m, const Generators& g, const Line& l, std::string* why) {
  const Field f{l.r};
  if (f.zero(l.d)) {
    if (why) *why = "zero direction";
    return false;
  }
  for (int v : g.vertices)
    if (!passes_through(l, m.v[v])) {
      if (why) *why = "does not pass through vertex " + std::to_string(v);
      return false;
    }
  const auto pts = generator_points(f, m, g, l, true, why);
  if (!pts) return false;
  // Edge rule: with Y a point of the line off the edge's line, all orient(A, B, Y, W) of one strict sign.
  for (std::size_t i = 0; i < g.edges.size(); ++i) {
    const auto& e = g.edges[i];
    const QS3 A = lift(m.v[e[0]]), B = lift(m.v[e[1]]);
    const QS3 Y = f.add((*pts)[g.vertices.size() + i], l.d);
    int side = 0;
    bool any = false;
    for (const auto& t : m.t) {
      if (!has_edge(t, e)) continue;
      int w = t[0];
      for (int c : t)
        if (c != e[0] && c != e[1]) w = c;
      const int s = f.sign(f.det(f.sub(B, A), f.sub(Y, A), f.sub(lift(m.v[w]), A)));
      if (s == 0 || (any && s != side)) {
        if (why) *why = "edge rule fails at edge " + std::to_string(e[0]) + "-" + std::to_string(e[1]);
        return false;
      }
      side = s, any = true;
    }
  }
  for (int v : g.vertices)
    if (!vertex_rule(f, m, v, l.d, why)) return false;
  return segment_free(m, g, l, why);
}

Result valid_nodes(const Mesh& m, bool with_vv, bool with_vee, bool with_eeee) {
  Result res;
  std::set<int> used;
  std::set<std::array<int, 2>> edge_set;
  for (const auto& t : m.t)
    for (int k = 0; k < 3; ++k) {
      used.insert(t[k]);
      const int a = t[k], b = t[(k + 1) % 3];
      edge_set.insert({std::min(a, b), std::max(a, b)});
    }
  const std::vector<int> verts(used.begin(), used.end());
  const std::vector<std::array<int, 2>> edges(edge_set.begin(), edge_set.end());
  const Field f0{0};
  auto disjoint = [](const std::array<int, 2>& a, const std::array<int, 2>& b) {
    return a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1];
  };
  if (with_vv)
    for (std::size_t i = 0; i < verts.size(); ++i)
      for (std::size_t j = i + 1; j < verts.size(); ++j) {
        Line l{lift(m.v[verts[i]]), f0.sub(lift(m.v[verts[j]]), lift(m.v[verts[i]])), 0};
        if (f0.zero(l.d)) continue;
        if (valid_line(m, {{verts[i], verts[j]}, {}}, l)) ++res.nodes[key_of("VV", {verts[i], verts[j]}, {})];
      }
  if (with_vee)
    for (int v : verts)
      for (std::size_t i = 0; i < edges.size(); ++i)
        for (std::size_t j = i + 1; j < edges.size(); ++j) {
          const auto &e1 = edges[i], &e2 = edges[j];
          if (e1[0] == v || e1[1] == v || e2[0] == v || e2[1] == v || !disjoint(e1, e2)) continue;
          const QS3 V = lift(m.v[v]);
          const QS3 n1 = f0.cross(f0.sub(lift(m.v[e1[0]]), V), f0.sub(lift(m.v[e1[1]]), V));
          const QS3 n2 = f0.cross(f0.sub(lift(m.v[e2[0]]), V), f0.sub(lift(m.v[e2[1]]), V));
          const QS3 d = f0.cross(n1, n2);
          if (f0.zero(n1) || f0.zero(n2) || f0.zero(d)) {
            ++res.skipped_degenerate;
            continue;
          }
          if (valid_line(m, {{v}, {e1, e2}}, Line{V, d, 0})) ++res.nodes[key_of("VEE", {v}, {e1, e2})];
        }
  if (with_eeee) {
    const std::size_t n = edges.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        if (!disjoint(edges[i], edges[j])) continue;
        for (std::size_t k = j + 1; k < n; ++k) {
          if (!disjoint(edges[i], edges[k]) || !disjoint(edges[j], edges[k])) continue;
          for (std::size_t q = k + 1; q < n; ++q) {
            if (!disjoint(edges[i], edges[q]) || !disjoint(edges[j], edges[q]) || !disjoint(edges[k], edges[q])) continue;
            const std::array<std::array<int, 2>, 4> es{edges[i], edges[j], edges[k], edges[q]};
            // Lines p + s d; choose three pairwise skew ones, the fourth is cut with their quadric.
            std::array<V3, 4> p, d;
            for (int a = 0; a < 4; ++a) {
              p[a] = m.v[es[a][0]];
              for (int c = 0; c < 3; ++c) d[a][c] = m.v[es[a][1]][c] - p[a][c];
            }
            auto skew = [&](int a, int b) {
              const QS3 w = f0.sub(lift(p[b]), lift(p[a]));
              return !f0.zero(f0.det(lift(d[a]), lift(d[b]), w));
            };
            int last = -1;
            for (int cand = 3; cand >= 0 && last < 0; --cand) {
              int o[3], c = 0;
              for (int a = 0; a < 4; ++a)
                if (a != cand) o[c++] = a;
              if (skew(o[0], o[1]) && skew(o[0], o[2]) && skew(o[1], o[2])) last = cand;
            }
            if (last < 0) {
              ++res.skipped_degenerate;
              continue;
            }
            int o[3], c = 0;
            for (int a = 0; a < 4; ++a)
              if (a != last) o[c++] = a;
            // F(u) = det[(X(u) - p_i) x d_i], X(u) = p_last + u d_last: a polynomial of degree <= 3, found
            // from its values at u = 0, 1, 2, 3 (finite differences).
            auto F = [&](const Q& u) {
              std::array<QS3, 3> rows;
              for (int r = 0; r < 3; ++r) {
                QS3 x;
                for (int cc = 0; cc < 3; ++cc) x[cc] = QS{p[last][cc] + u * d[last][cc] - p[o[r]][cc], 0};
                rows[r] = f0.cross(x, lift(d[o[r]]));
              }
              return f0.det(rows[0], rows[1], rows[2]).a;
            };
            const Q f0v = F(0), f1 = F(1), f2 = F(2), f3 = F(3);
            const Q d1 = f1 - f0v, d2 = f2 - 2 * f1 + f0v, d3 = f3 - 3 * f2 + 3 * f1 - f0v;
            // Newton form -> coefficients: F = c3 u^3 + c2 u^2 + c1 u + c0.
            const Q c3 = d3 / 6, c2 = d2 / 2 - d3 / 2, c1 = d1 - d2 / 2 + d3 / 3, c0 = f0v;
            if (c3 != 0) throw std::runtime_error("oracle: quadric restriction is cubic");
            std::vector<std::pair<QS, Q>> roots;  // (u, r)
            if (c2 == 0 && c1 == 0) {
              if (c0 == 0) ++res.skipped_degenerate;  // the fourth line lies on the quadric
              continue;
            }
            if (c2 == 0) {
              roots.push_back({QS{-c0 / c1, 0}, 0});
            } else {
              const Q disc = c1 * c1 - 4 * c2 * c0;
              if (disc < 0) continue;
              const bool square = mpz_perfect_square_p(disc.get_num_mpz_t()) && mpz_perfect_square_p(disc.get_den_mpz_t());
              if (disc == 0) {
                roots.push_back({QS{-c1 / (2 * c2), 0}, 0});
              } else if (square) {
                // A rational square root: both roots rational (keeps the field a true extension elsewhere).
                mpz_class rn, rd;
                mpz_sqrt(rn.get_mpz_t(), disc.get_num_mpz_t());
                mpz_sqrt(rd.get_mpz_t(), disc.get_den_mpz_t());
                const Q sq(rn, rd);
                roots.push_back({QS{(-c1 + sq) / (2 * c2), 0}, 0});
                roots.push_back({QS{(-c1 - sq) / (2 * c2), 0}, 0});
              } else {
                // (-c1 +- sqrt(disc)) / (2 c2) in Q(sqrt disc).
                roots.push_back({QS{-c1 / (2 * c2), Q(1) / (2 * c2)}, disc});
                roots.push_back({QS{-c1 / (2 * c2), Q(-1) / (2 * c2)}, disc});
              }
            }
            for (const auto& [u, r] : roots) {
              const Field f{r};
              if (f.sign(u) <= 0 || f.sign(f.sub(u, QS{1, 0})) >= 0) continue;
              const QS3 X = f.add(lift(p[last]), f.scale(u, lift(d[last])));
              const QS3 n1 = f.cross(f.sub(X, lift(p[o[0]])), lift(d[o[0]]));
              const QS3 n2 = f.cross(f.sub(X, lift(p[o[1]])), lift(d[o[1]]));
              const QS3 dir = f.cross(n1, n2);
              if (f.zero(dir)) {
                ++res.skipped_degenerate;
                continue;
              }
              const Line l{X, dir, r};
              std::vector<std::array<int, 2>> ev(es.begin(), es.end());
              if (valid_line(m, {{}, ev}, l)) ++res.nodes[key_of("EEEE", {}, ev)];
            }
          }
        }
      }
  }
  return res;
}

}  // namespace skeleton_oracle
