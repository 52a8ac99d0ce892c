#include "aspect/great_circle_arrangement.hpp"

#include "kernel/filtered_predicate.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

namespace exactvis {

namespace {

PredicateCounter orientation_counter("great_circle_orientation");

bool is_zero(const Vec3<Exact>& v) { return v.x == 0 && v.y == 0 && v.z == 0; }


using IVec = Vec3<ExactInt>;

// The primitive integer vector with the direction of v (a positive multiple of it).
IVec primitive(const IVec& v) {
  ExactInt g;
  mpz_gcd(g.mpz(), v.x.mpz(), v.y.mpz());
  mpz_gcd(g.mpz(), g.mpz(), v.z.mpz());
  if (g == 0 || g == 1) return v;
  return {v.x / g, v.y / g, v.z / g};
}
IVec integral(const Vec3<Exact>& v) {
  ExactInt l(1);
  for (int i = 0; i < 3; ++i) mpz_lcm(l.mpz(), l.mpz(), v[i].denominator().mpz());
  IVec r;
  for (int i = 0; i < 3; ++i) r[i] = v[i].numerator() * (l / v[i].denominator());
  return primitive(r);
}
Vec3<Exact> rational(const IVec& v) { return {Exact(v.x), Exact(v.y), Exact(v.z)}; }

// An exact integer vector with its interval enclosure, for the filter.
struct Filtered {
  IVec exact;
  Vec3<Interval> box;
  Filtered() = default;
  explicit Filtered(IVec v) : exact(std::move(v)) {
    for (int i = 0; i < 3; ++i) box[i] = Interval(CGAL::to_interval(exact[i]));
  }
};

// sign(a . (b x c)), filtered (interval, then exact).
Sign orientation(const Filtered& a, const Filtered& b, const Filtered& c) {
  return filtered_sign_with<ExactInt>(orientation_counter, [] { return std::optional<Sign>{}; }, [&](auto nt) {
    using NT = typename decltype(nt)::type;
    if constexpr (std::is_same_v<NT, Interval>) return dot(a.box, cross(b.box, c.box));
    else return NT(dot(a.exact, cross(b.exact, c.exact)));
  });
}

// Sorts vectors orthogonal to `axis` counter-clockwise about it, starting at the first one (exact).
template <class Key>
void sort_about(const Filtered& axis, std::vector<std::pair<Filtered, Key>>& items) {
  if (items.size() < 2) return;
  const Filtered ref = items.front().first;
  // Half 0: angle in [0, pi) from ref; half 1: [pi, 2 pi).
  const auto half = [&](const Filtered& v) {
    const Sign s = orientation(axis, ref, v);
    if (s == Sign::Positive) return 0;
    if (s == Sign::Negative) return 1;
    return CGAL::sign(dot(ref.exact, v.exact)) > 0 ? 0 : 1;
  };
  std::vector<std::pair<int, std::size_t>> order;
  for (std::size_t i = 0; i < items.size(); ++i) order.push_back({half(items[i].first), i});
  std::sort(order.begin(), order.end(), [&](const auto& p, const auto& q) {
    if (p.first != q.first) return p.first < q.first;
    return orientation(axis, items[p.second].first, items[q.second].first) == Sign::Positive;
  });
  std::vector<std::pair<Filtered, Key>> sorted;
  sorted.reserve(items.size());
  for (const auto& [h, i] : order) sorted.push_back(std::move(items[i]));
  items = std::move(sorted);
}

}  // namespace

Vec3<Exact> scaled_to_unit_max(const Vec3<Exact>& v) {
  Exact big(0);
  for (int i = 0; i < 3; ++i) big = std::max(big, CGAL::abs(v[i]));
  return {v.x / big, v.y / big, v.z / big};
}

GreatCircleArrangement great_circle_arrangement(const std::vector<Vec3<Exact>>& normals) {
  const int m = static_cast<int>(normals.size());
  // Integer normals (positive multiples), so that every construction below is in integers.
  std::vector<IVec> in(m);
  for (int k = 0; k < m; ++k) {
    if (is_zero(normals[k])) throw std::invalid_argument("great_circle_arrangement: a zero normal");
    in[k] = integral(normals[k]);
  }
  bool spans = false;
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j) {
      const IVec c = cross(in[i], in[j]);
      if (c.x == 0 && c.y == 0 && c.z == 0) throw std::invalid_argument("great_circle_arrangement: two equal circles");
      for (int k = j + 1; k < m && !spans; ++k) spans = dot(c, in[k]) != 0;
    }
  if (!spans) throw std::invalid_argument("great_circle_arrangement: the normals do not span R^3");

  GreatCircleArrangement A;
  // Vertices: +-(n_i x n_j), merged by their primitive integer vectors (several circles through one point).
  std::map<std::array<ExactInt, 3>, int> index;
  std::vector<IVec> iv;
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j) {
      const IVec c = primitive(cross(in[i], in[j]));
      for (const IVec& v : {c, -c}) {
        const auto [it, fresh] = index.emplace(std::array<ExactInt, 3>{v.x, v.y, v.z}, static_cast<int>(iv.size()));
        if (fresh) iv.push_back(v), A.vertex_circles.emplace_back();
        A.vertex_circles[it->second].push_back(i);
        A.vertex_circles[it->second].push_back(j);
      }
    }
  const int V = static_cast<int>(iv.size());
  std::vector<std::vector<int>> on_circle(m);
  for (int v = 0; v < V; ++v) {
    auto& cs = A.vertex_circles[v];
    std::sort(cs.begin(), cs.end());
    cs.erase(std::unique(cs.begin(), cs.end()), cs.end());
    for (int k : cs) on_circle[k].push_back(v);
  }
  std::vector<Filtered> fv(V), fn(m);
  A.vertices.resize(V);
  tbb::parallel_for(0, V, [&](int v) {
    fv[v] = Filtered(iv[v]);
    A.vertices[v] = scaled_to_unit_max(rational(iv[v]));
  });
  for (int k = 0; k < m; ++k) fn[k] = Filtered(in[k]);

  // Arcs: each circle's vertices in counter-clockwise order about its normal, consecutive pairs.
  std::vector<std::vector<int>> circle_order(m);
  tbb::parallel_for(0, m, [&](int k) {
    std::vector<std::pair<Filtered, int>> items;
    for (int v : on_circle[k]) items.push_back({fv[v], v});
    sort_about(fn[k], items);
    for (const auto& it : items) circle_order[k].push_back(it.second);
  });
  for (int k = 0; k < m; ++k) {
    const auto& w = circle_order[k];
    for (std::size_t i = 0; i < w.size(); ++i)
      A.arcs.push_back({k, w[i], w[(i + 1) % w.size()], -1, -1});
  }
  const int E = static_cast<int>(A.arcs.size());

  // Outgoing halfedges of each vertex, counter-clockwise about the vertex (seen from outside). Halfedge 2a
  // leaves `from` along n x from; 2a + 1 leaves `to` along to x n.
  std::vector<std::vector<int>> outgoing(V);
  for (int a = 0; a < E; ++a) {
    outgoing[A.arcs[a].from].push_back(2 * a);
    outgoing[A.arcs[a].to].push_back(2 * a + 1);
  }
  std::vector<int> position(2 * E, -1);
  tbb::parallel_for(0, V, [&](int v) {
    std::vector<std::pair<Filtered, int>> items;
    for (int h : outgoing[v]) {
      const IVec& n = in[A.arcs[h / 2].circle];
      items.push_back({Filtered(h % 2 == 0 ? cross(n, iv[v]) : cross(iv[v], n)), h});
    }
    sort_about(fv[v], items);
    for (std::size_t i = 0; i < items.size(); ++i) {
      outgoing[v][i] = items[i].second;
      position[items[i].second] = static_cast<int>(i);
    }
  });
  // The face left of h (u -> v) continues with the outgoing halfedge of v just clockwise of h's twin.
  const auto target = [&](int h) { return h % 2 == 0 ? A.arcs[h / 2].to : A.arcs[h / 2].from; };
  const auto next = [&](int h) {
    const int v = target(h);
    const auto& out = outgoing[v];
    const int p = position[h ^ 1];
    return out[(p + static_cast<int>(out.size()) - 1) % out.size()];
  };
  std::vector<int> face_of(2 * E, -1);
  for (int h0 = 0; h0 < 2 * E; ++h0) {
    if (face_of[h0] >= 0) continue;
    const int f = static_cast<int>(A.faces.size());
    A.faces.emplace_back();
    for (int h = h0; face_of[h] < 0; h = next(h)) {
      face_of[h] = f;
      A.faces[f].halfedges.push_back(h);
    }
  }
  for (int a = 0; a < E; ++a) A.arcs[a].left = face_of[2 * a], A.arcs[a].right = face_of[2 * a + 1];
  if (V - E + static_cast<int>(A.faces.size()) != 2)
    throw std::logic_error("great_circle_arrangement: V - E + F != 2");
  return A;
}

Vec3<Exact> face_sample(const GreatCircleArrangement& arr, int face) {
  Vec3<Exact> s{Exact(0), Exact(0), Exact(0)};
  for (int h : arr.faces[face].halfedges) {
    const auto& a = arr.arcs[h / 2];
    s = s + arr.vertices[h % 2 == 0 ? a.from : a.to];
  }
  return scaled_to_unit_max(s);
}

Vec3<Exact> arc_sample(const GreatCircleArrangement& arr, const std::vector<Vec3<Exact>>& normals, int arc) {
  const auto& a = arr.arcs[arc];
  const Vec3<Exact>& u = arr.vertices[a.from];
  const Vec3<Exact>& v = arr.vertices[a.to];
  const Exact o = dot(normals[a.circle], cross(u, v));
  if (o > 0) return scaled_to_unit_max(u + v);
  if (o == 0) return scaled_to_unit_max(cross(normals[a.circle], u));  // a half circle (its ends antipodal)
  return scaled_to_unit_max(-(u + v));                                   // more than half a circle (not met: ends come in pairs)
}

}  // namespace exactvis
