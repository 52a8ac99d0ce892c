#include "oracles/visibility2d_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

namespace oracle2d {

bool operator==(const Pt& a, const Pt& b) { return a.x == b.x && a.y == b.y; }
bool operator<(const Pt& a, const Pt& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

namespace {

int orient(const Pt& a, const Pt& b, const Pt& c) {
  const mpq_class v = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return mpq_sgn(v.get_mpq_t());
}
mpq_class dot(const Pt& a, const Pt& b, const Pt& c, const Pt& d) {
  return (b.x - a.x) * (d.x - c.x) + (b.y - a.y) * (d.y - c.y);
}

// Flattened scene: vertices with ring neighbours, object on the left of every edge.
struct Flat {
  std::vector<Pt> p;
  std::vector<int> next, prev, object;
};

Flat flatten(const std::vector<Polygon>& scene) {
  Flat f;
  for (std::size_t o = 0; o < scene.size(); ++o)
    for (std::size_t r = 0; r < scene[o].rings.size(); ++r) {
      const Ring& ring = scene[o].rings[r];
      std::vector<Pt> pts;
      for (const auto& q : ring) pts.push_back({mpq_class(q[0]), mpq_class(q[1])});
      mpq_class area = 0;
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const Pt &a = pts[i], &b = pts[(i + 1) % pts.size()];
        area += a.x * b.y - a.y * b.x;
      }
      const bool want_ccw = r == 0;
      if ((area > 0) != want_ccw) std::reverse(pts.begin(), pts.end());
      const int first = static_cast<int>(f.p.size()), m = static_cast<int>(pts.size());
      for (int i = 0; i < m; ++i) {
        f.p.push_back(pts[i]);
        f.next.push_back(first + (i + 1) % m);
        f.prev.push_back(first + (i + m - 1) % m);
        f.object.push_back(static_cast<int>(o));
      }
    }
  return f;
}

bool point_on_segment(const Pt& a, const Pt& b, const Pt& p) {
  return orient(a, b, p) == 0 && dot(p, a, p, b) <= 0;
}

// closed segments intersect
bool closed_intersect(const Pt& a, const Pt& b, const Pt& c, const Pt& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 == 0 && o2 == 0)
    return point_on_segment(a, b, c) || point_on_segment(a, b, d) || point_on_segment(c, d, a) ||
           point_on_segment(c, d, b);
  return o1 * o2 <= 0 && o3 * o4 <= 0;
}

bool inside_flat(const Flat& f, const Pt& p) {
  bool in = false;
  for (std::size_t v = 0; v < f.p.size(); ++v) {
    const Pt &a = f.p[v], &b = f.p[f.next[v]];
    if ((a.y > p.y) != (b.y > p.y)) {
      const mpq_class x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (x > p.x) in = !in;
    }
  }
  return in;
}

bool on_flat_boundary(const Flat& f, const Pt& p) {
  for (std::size_t v = 0; v < f.p.size(); ++v)
    if (point_on_segment(f.p[v], f.p[f.next[v]], p)) return true;
  return false;
}

// The open segment (p, q) between vertices p != q meets a boundary point?
bool open_segment_touches(const Flat& f, int p, int q) {
  const Pt &P = f.p[p], &Q = f.p[q];
  for (std::size_t v = 0; v < f.p.size(); ++v) {
    const int a = static_cast<int>(v), b = f.next[v];
    if ((a == p && b == q) || (a == q && b == p)) return true;  // the segment is a ring edge
    if (a == p || b == p || a == q || b == q) {
      // shares an endpoint: meets the open segment only if collinear and overlapping
      const int shared = (a == p || b == p) ? p : q;
      const int other = (a == shared) ? b : a;
      const int far = shared == p ? q : p;
      if (orient(f.p[shared], f.p[far], f.p[other]) == 0 && dot(f.p[shared], f.p[far], f.p[shared], f.p[other]) > 0)
        return true;
      continue;
    }
    if (closed_intersect(P, Q, f.p[a], f.p[b])) return true;
  }
  return false;
}

bool convex_vertex(const Flat& f, int v) { return orient(f.p[f.prev[v]], f.p[v], f.p[f.next[v]]) > 0; }

// object at v lies in a closed half-plane of line(p, q) (v on the line)
bool tangent(const Flat& f, int v, const Pt& p, const Pt& q) {
  if (!convex_vertex(f, v)) return false;
  return orient(p, q, f.p[f.prev[v]]) * orient(p, q, f.p[f.next[v]]) >= 0;
}

char side(const Flat& f, int v, const Pt& p, const Pt& q) {
  int o = orient(p, q, f.p[f.prev[v]]);
  if (o == 0) o = orient(p, q, f.p[f.next[v]]);
  return o > 0 ? 'L' : 'R';
}

// First boundary point on the ray from vertex `from` (exclusive) in direction from - toward... i.e. beyond
// `from` away from `toward`. Returns nullopt at infinity.
std::optional<Pt> first_contact_beyond(const Flat& f, int from, int toward_back) {
  const Pt& o = f.p[from];
  const Pt d{o.x - f.p[toward_back].x, o.y - f.p[toward_back].y};
  // an edge of `from` along the ray: the extension is empty
  for (int u : {f.next[from], f.prev[from]}) {
    const Pt du{f.p[u].x - o.x, f.p[u].y - o.y};
    if (d.x * du.y - d.y * du.x == 0 && d.x * du.x + d.y * du.y > 0) return o;
  }
  std::optional<mpq_class> best;
  for (std::size_t v = 0; v < f.p.size(); ++v) {
    const Pt &a = f.p[v], &b = f.p[f.next[v]];
    if (static_cast<int>(v) == from || f.next[v] == from) continue;  // touches the ray only at `from`
    const Pt e{b.x - a.x, b.y - a.y};
    const mpq_class den = d.x * e.y - d.y * e.x;
    const Pt ao{a.x - o.x, a.y - o.y};
    if (den == 0) {
      if (ao.x * d.y - ao.y * d.x != 0) continue;  // parallel, not collinear
      for (const Pt* q : {&a, &b}) {               // collinear: nearest endpoint ahead
        const mpq_class t = ((q->x - o.x) * d.x + (q->y - o.y) * d.y) / (d.x * d.x + d.y * d.y);
        if (t > 0 && (!best || t < *best)) best = t;
      }
      continue;
    }
    const mpq_class t = (ao.x * e.y - ao.y * e.x) / den;
    const mpq_class s = (ao.x * d.y - ao.y * d.x) / den;
    if (t > 0 && s >= 0 && s <= 1 && (!best || t < *best)) best = t;
  }
  if (!best) return std::nullopt;
  return Pt{o.x + *best * d.x, o.y + *best * d.y};
}

}  // namespace

bool inside_object(const std::vector<Polygon>& scene, const Pt& p) {
  const Flat f = flatten(scene);
  return !on_flat_boundary(f, p) && inside_flat(f, p);
}

bool on_boundary(const std::vector<Polygon>& scene, const Pt& p) { return on_flat_boundary(flatten(scene), p); }

std::vector<Bitangent> brute_force_bitangents(const std::vector<Polygon>& scene) {
  const Flat f = flatten(scene);
  const int n = static_cast<int>(f.p.size());
  std::vector<Bitangent> out;
  for (int p = 0; p < n; ++p)
    for (int q = 0; q < n; ++q) {
      if (!(f.p[p] < f.p[q])) continue;
      const Pt &P = f.p[p], &Q = f.p[q];
      if (!tangent(f, p, P, Q) || !tangent(f, q, P, Q)) continue;
      if (open_segment_touches(f, p, q)) continue;
      const Pt mid{(P.x + Q.x) / 2, (P.y + Q.y) / 2};
      if (inside_flat(f, mid)) continue;
      Bitangent b;
      b.a = P;
      b.b = Q;
      b.object_a = f.object[p];
      b.object_b = f.object[q];
      b.kind = {side(f, p, P, Q), side(f, q, P, Q)};
      const auto ea = first_contact_beyond(f, p, q), eb = first_contact_beyond(f, q, p);
      b.end_a_infinite = !ea;
      b.end_b_infinite = !eb;
      if (ea) b.end_a = *ea;
      if (eb) b.end_b = *eb;
      out.push_back(b);
    }
  return out;
}

std::vector<std::array<Pt, 2>> brute_force_visible_edges(const std::vector<Polygon>& scene, const Pt& c) {
  const Flat f = flatten(scene);
  const int n = static_cast<int>(f.p.size());
  // directions to all vertices, sorted by angle (half-plane, then cross product)
  struct Dir {
    mpq_class x, y;
  };
  std::vector<Dir> dirs;
  for (int v = 0; v < n; ++v) dirs.push_back({f.p[v].x - c.x, f.p[v].y - c.y});
  auto half = [](const Dir& d) { return (d.y > 0 || (d.y == 0 && d.x > 0)) ? 0 : 1; };
  std::sort(dirs.begin(), dirs.end(), [&](const Dir& a, const Dir& b) {
    if (half(a) != half(b)) return half(a) < half(b);
    return a.x * b.y - a.y * b.x > 0;
  });
  std::vector<std::array<Pt, 2>> seen;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const Dir& u = dirs[i];
    const Dir& w = dirs[(i + 1) % dirs.size()];
    const mpq_class cr = u.x * w.y - u.y * w.x;
    Dir m;
    if (cr > 0) m = {u.x + w.x, u.y + w.y};
    else if (cr == 0 && u.x * w.x + u.y * w.y > 0) {
      if (dirs.size() > 1 && i + 1 < dirs.size()) continue;  // same direction: no gap
      m = {-u.y, u.x};                                      // single direction: any other
    } else if (cr == 0) m = {-u.y, u.x};
    else m = {-(u.x + w.x), -(u.y + w.y)};
    // nearest edge crossing the ray c + t m (no vertex lies on it)
    std::optional<mpq_class> best;
    int best_edge = -1;
    for (int v = 0; v < n; ++v) {
      const Pt &a = f.p[v], &b = f.p[f.next[v]];
      const mpq_class ex = b.x - a.x, ey = b.y - a.y;
      const mpq_class den = m.x * ey - m.y * ex;
      if (den == 0) continue;
      const mpq_class ax = a.x - c.x, ay = a.y - c.y;
      const mpq_class t = (ax * ey - ay * ex) / den;
      const mpq_class s = (ax * m.y - ay * m.x) / den;
      if (t > 0 && s > 0 && s < 1 && (!best || t < *best)) {
        best = t;
        best_edge = v;
      }
    }
    if (best_edge < 0) continue;
    Pt a = f.p[best_edge], b = f.p[f.next[best_edge]];
    if (b < a) std::swap(a, b);
    seen.push_back({a, b});
  }
  std::sort(seen.begin(), seen.end(), [](const auto& x, const auto& y) {
    return x[0] < y[0] || (x[0] == y[0] && x[1] < y[1]);
  });
  seen.erase(std::unique(seen.begin(), seen.end(), [](const auto& x, const auto& y) {
               return x[0] == y[0] && x[1] == y[1];
             }), seen.end());
  return seen;
}

std::vector<std::array<int, 2>> free_segment_end_pairs(const std::vector<Polygon>& scene, const Pt& p, const Pt& q) {
  const Flat f = flatten(scene);
  const Pt d{q.x - p.x, q.y - p.y};
  std::vector<std::pair<mpq_class, int>> hits;  // parameter along the line, object
  for (std::size_t v = 0; v < f.p.size(); ++v) {
    const Pt &a = f.p[v], &b = f.p[f.next[v]];
    const mpq_class ex = b.x - a.x, ey = b.y - a.y, den = d.x * ey - d.y * ex;
    if (den == 0) continue;
    const mpq_class ax = a.x - p.x, ay = a.y - p.y;
    const mpq_class s = (ax * d.y - ay * d.x) / den;
    if (s > 0 && s < 1) hits.emplace_back((ax * ey - ay * ex) / den, f.object[v]);
  }
  std::sort(hits.begin(), hits.end());
  std::vector<std::array<int, 2>> out;
  // pieces: (-inf, h0), (h0, h1), ..., (h_last, +inf); free ones alternate with object interiors
  for (std::size_t i = 0; i <= hits.size(); ++i) {
    mpq_class t;
    if (hits.empty()) t = 0;
    else if (i == 0) t = hits[0].first - 1;
    else if (i == hits.size()) t = hits.back().first + 1;
    else t = (hits[i - 1].first + hits[i].first) / 2;
    if (inside_flat(f, {p.x + t * d.x, p.y + t * d.y})) continue;
    const int lo = i == 0 ? -1 : hits[i - 1].second, hi = i == hits.size() ? -1 : hits[i].second;
    out.push_back({std::min(lo, hi), std::max(lo, hi)});
  }
  return out;
}

bool open_segment_free(const std::vector<Polygon>& scene, const Pt& p, const Pt& q) {
  const Flat f = flatten(scene);
  for (std::size_t v = 0; v < f.p.size(); ++v)
    if (closed_intersect(p, q, f.p[v], f.p[f.next[v]])) return false;
  return !inside_flat(f, {(p.x + q.x) / 2, (p.y + q.y) / 2});
}

std::vector<Polygon> random_grid_scene(std::uint64_t seed, int cells, bool convex_only) {
  std::mt19937_64 rng(seed);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::vector<Polygon> scene;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      const double ox = 10.0 * i, oy = 10.0 * j;
      const int type = convex_only ? uni(0, 5) : uni(0, 9);
      if (type <= 1) continue;  // empty cell
      if (type <= 5) {          // convex: hull of random grid points in [1,9]^2
        std::vector<std::array<double, 2>> pts;
        const int k = uni(3, 7);
        for (int t = 0; t < k; ++t) pts.push_back({double(uni(1, 9)), double(uni(1, 9))});
        std::sort(pts.begin(), pts.end());
        pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
        if (pts.size() < 3) continue;
        auto cross = [](const auto& o, const auto& a, const auto& b) {
          return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
        };
        std::vector<std::array<double, 2>> hull(2 * pts.size());
        std::size_t h = 0;
        for (std::size_t t = 0; t < pts.size(); ++t) {
          while (h >= 2 && cross(hull[h - 2], hull[h - 1], pts[t]) <= 0) --h;
          hull[h++] = pts[t];
        }
        for (std::size_t t = pts.size() - 1, lo = h + 1; t-- > 0;) {
          while (h >= lo && cross(hull[h - 2], hull[h - 1], pts[t]) <= 0) --h;
          hull[h++] = pts[t];
        }
        hull.resize(h - 1);
        if (hull.size() < 3) continue;
        Ring r;
        for (auto& q : hull) r.push_back({ox + q[0], oy + q[1]});
        scene.push_back({{r}});
      } else if (type <= 8) {   // star-shaped around the cell centre, rounded to the grid
        const int k = uni(5, 9);
        std::vector<double> ang;
        for (int t = 0; t < k; ++t) ang.push_back(std::uniform_real_distribution<double>(0, 6.283185307179586)(rng));
        std::sort(ang.begin(), ang.end());
        Ring r;
        for (int t = 0; t < k; ++t) {
          const double rad = uni(1, 4);
          r.push_back({ox + 5 + std::round(rad * std::cos(ang[t])), oy + 5 + std::round(rad * std::sin(ang[t]))});
        }
        scene.push_back({{r}});
      } else {                  // square with a square hole, sometimes an island inside the hole
        const int a = uni(1, 2), b = uni(3, 4);
        Ring outer{{ox + a, oy + a}, {ox + 10 - a, oy + a}, {ox + 10 - a, oy + 10 - a}, {ox + a, oy + 10 - a}};
        Ring hole{{ox + b, oy + b}, {ox + 10 - b, oy + b}, {ox + 10 - b, oy + 10 - b}, {ox + b, oy + 10 - b}};
        scene.push_back({{outer, hole}});
        if (uni(0, 1)) scene.push_back({{Ring{{ox + 5, oy + 4.5}, {ox + 5.5, oy + 5}, {ox + 5, oy + 5.5}}}});
      }
    }
  return scene;
}

}  // namespace oracle2d
