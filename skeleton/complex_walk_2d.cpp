#include "skeleton/complex_walk_2d.hpp"

#include "skeleton/angular_sweep_2d.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <exception>
#include <stdexcept>

namespace exactvis {
namespace {

// 0 for directions in [0, pi) (dy > 0, or dy = 0 and dx > 0), 1 for [pi, 2pi).
int half_of(const Point2& from, const Point2& to) {
  const Sign sy = dy_sign(from, to);
  if (sy != Sign::Zero) return sy == Sign::Positive ? 0 : 1;
  return dx_sign(from, to) == Sign::Positive ? 0 : 1;
}

// A direction given by two points (vector to - from), never constructed.
struct Dir {
  const Point2* from = nullptr;
  const Point2* to = nullptr;
  Dir reversed() const { return {to, from}; }
};

// The line direction of p - q taken in [0, pi).
Dir line_dir(const Point2& q, const Point2& p) { return half_of(q, p) == 0 ? Dir{&q, &p} : Dir{&p, &q}; }

// Order of two line directions taken in [0, pi) (as line_dir gives them): one cross product decides.
int compare_dir(const Dir& u, const Dir& v) {
  const Sign c = cross_sign(*u.from, *u.to, *v.from, *v.to);
  return c == Sign::Positive ? -1 : (c == Sign::Negative ? 1 : 0);
}

}  // namespace

ComplexWalkIndex2D complex_walk_index(const Scene2D& scene, const VisibilityComplex2D& cx) {
  ComplexWalkIndex2D ix;
  ix.scene = &scene;
  ix.complex = &cx;
  const int n = scene.num_vertices();
  const auto& P = scene.points;
  const auto& B = cx.graph.bitangents;
  ix.neighbours.resize(n);
  auto bitangent_of = [&](int a, int b) {
    if (a > b) std::swap(a, b);
    const auto it = std::lower_bound(B.begin(), B.end(), std::pair<int, int>{a, b},
                                     [](const Bitangent2D& t, const std::pair<int, int>& k) {
                                       return std::pair<int, int>{t.a, t.b} < k;
                                     });
    return it != B.end() && it->a == a && it->b == b ? static_cast<int>(it - B.begin()) : -1;
  };
  for (const auto& [a, b] : cx.graph.strict_pairs) {
    const int t = bitangent_of(a, b);
    ix.neighbours[a].push_back({b, t});
    ix.neighbours[b].push_back({a, t});
  }
  for (int v = 0; v < n; ++v) {
    ix.neighbours[v].push_back({scene.next[v], -1});
    ix.neighbours[v].push_back({scene.prev[v], -1});
  }
  for (int v = 0; v < n; ++v) {
    auto& list = ix.neighbours[v];
    std::sort(list.begin(), list.end(), [&](const auto& x, const auto& y) {
      const int c = compare_angle(P[v], P[x.vertex], P[v], P[y.vertex]);
      if (c != 0) return c < 0;
      return dot_sign(P[x.vertex], P[y.vertex], P[v], P[x.vertex]) == Sign::Positive;  // x nearer
    });
    list.erase(std::unique(list.begin(), list.end(), [](const auto& x, const auto& y) { return x.vertex == y.vertex; }),
               list.end());
  }
  ix.pivot_edges.resize(n);
  for (std::size_t j = 0; j < cx.edges.size(); ++j) {
    const ComplexEdge2D& e = cx.edges[j];
    if (e.degenerate) continue;
    std::array<int, 2> pair = e.end_objects;
    if (pair[0] > pair[1]) std::swap(pair[0], pair[1]);
    auto& cand = ix.candidates[pair];
    for (int v : e.pivots) {
      cand.push_back(v);
      auto& pe = ix.pivot_edges[v];
      if (pe.empty() || pe.back() != static_cast<int>(j)) pe.push_back(static_cast<int>(j));
    }
  }
  for (auto& [pair, cand] : ix.candidates) {
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  }
  ix.object_edges.resize(scene.num_objects);
  for (int e = 0; e < n; ++e) ix.object_edges[scene.object_of(e)].push_back(e);
  return ix;
}

namespace {

struct Walk {
  const ComplexWalkIndex2D& ix;
  const Scene2D& s;  // framed
  const Point2& q;
  int n;             // vertices of the unframed scene; ids >= n are frame corners
  std::vector<int> frame_edges;

  const std::vector<Point2>& P() const { return s.points; }
  int object_or_infinity(int e) const { return e >= n ? -1 : s.object_of(e); }

  // The edge hit by the ray from q in direction R = (+-1, 0) turned clockwise by an infinitesimal angle:
  // O(n), edges whose y-range misses q's or lying wholly behind q rejected first from interval enclosures.
  int edge_hit_before(const Dir& R, bool east) const {
    int best = -1;
    for (int e = 0; e < s.num_vertices(); ++e) {
      int a = e, b = s.next[e];
      const Point2 &pa = P()[a], &pb = P()[b];
      if (std::max(pa.iy.sup(), pb.iy.sup()) < q.iy.inf() || std::min(pa.iy.inf(), pb.iy.inf()) > q.iy.sup()) continue;
      if (east ? std::max(pa.ix.sup(), pb.ix.sup()) < q.ix.inf() : std::min(pa.ix.inf(), pb.ix.inf()) > q.ix.sup())
        continue;
      const Sign o = orientation2(q, P()[a], P()[b]);
      if (o == Sign::Zero) continue;
      if (o == Sign::Negative) std::swap(a, b);
      // the open ray just clockwise of R crosses (a, b): a strictly clockwise of R, b counterclockwise or on it
      if (cross_sign(q, P()[a], *R.from, *R.to) != Sign::Positive) continue;
      if (cross_sign(*R.from, *R.to, q, P()[b]) == Sign::Negative) continue;
      if (best < 0 || edge_closer(s, q, e, best)) best = e;
    }
    if (best < 0) throw std::logic_error("complex walk: a ray from a point inside the frame meets nothing (bug)");
    return best;
  }

  // Counterclockwise end (seen from q) of edge e.
  int ccw_end(int e) const {
    return orientation2(q, P()[e], P()[s.next[e]]) == Sign::Positive ? s.next[e] : e;
  }

  // w strictly between q and the hit point of the ray on edge e (the line of e separates them); q_side is
  // orientation2(e, next e, q), computed once per step.
  bool before_edge(int w, int e, Sign q_side) const {
    return orientation2(P()[e], P()[s.next[e]], P()[w]) == q_side;
  }

  // Hit point of the line through q in direction R with edge e (an endpoint if it lies on the line).
  Point2 hit(int e, const Dir& R) const {
    const Point2 &a = P()[e], &b = P()[s.next[e]];
    if (cross_sign(*R.from, *R.to, q, a) == Sign::Zero) return a;
    if (cross_sign(*R.from, *R.to, q, b) == Sign::Zero) return b;
    return line_intersection(q, *R.from, *R.to, a, b);
  }

  // At vertex w on a ray of direction R, the edge of w that the ray meets once turned counterclockwise by
  // an infinitesimal (it then passes w on w's left): the edge of w going into the open left half-plane,
  // the one of larger angle from R if both do; -1 if none (the ray passes w).
  int blocking_edge(int w, const Dir& R) const {
    const int o1 = s.next[w], o2 = s.prev[w];
    const bool l1 = cross_sign(*R.from, *R.to, P()[w], P()[o1]) == Sign::Positive;
    const bool l2 = cross_sign(*R.from, *R.to, P()[w], P()[o2]) == Sign::Positive;
    if (l1 && l2) return cross_sign(P()[w], P()[o1], P()[w], P()[o2]) == Sign::Positive ? o2 : w;
    if (l1) return w;
    if (l2) return o2;
    return -1;
  }

  // Neighbours of v (visibility graph and ring) in exactly direction R: [first, last) nearest first.
  std::pair<std::size_t, std::size_t> neighbours_in(int v, const Dir& R) const {
    const auto& list = ix.neighbours[v];
    auto cmp = [&](int x) { return compare_angle(P()[v], P()[x], *R.from, *R.to); };
    std::size_t lo = 0, hi = list.size();
    while (lo < hi) {  // first with direction >= R
      const std::size_t mid = (lo + hi) / 2;
      if (cmp(list[mid].vertex) < 0) lo = mid + 1; else hi = mid;
    }
    std::size_t end = lo;
    while (end < list.size() && cmp(list[end].vertex) == 0) ++end;
    return {lo, end};
  }

  // The nearest scene vertex to q on the open segment (q, w) of the ray, or w itself: the open segment
  // from a vertex to the next vertex on the line is free, so the next one towards q is a neighbour.
  int nearest_towards_q(int w) const {
    while (w < n) {
      const Dir back{&P()[w], &q};
      const auto [lo, hi] = neighbours_in(w, back);
      if (lo == hi) break;
      const int y = ix.neighbours[w][lo].vertex;
      if (dot_sign(P()[y], q, P()[y], P()[w]) != Sign::Negative) break;  // y not strictly between q and w
      w = y;
    }
    return w;
  }

  // Is the oriented direction t within the closed range of tangent directions of convex vertex v, oriented
  // as in the complex's construction: from prev v - v to v - next v, counterclockwise (< pi)? The sample
  // direction of a complex edge is oriented this way, so its end_objects[1] lies ahead along such a t.
  bool in_range(int v, const Dir& t) const {
    return cross_sign(P()[v], P()[s.prev[v]], *t.from, *t.to) != Sign::Negative &&
           cross_sign(*t.from, *t.to, P()[s.next[v]], P()[v]) != Sign::Negative;
  }

  // Oriented tangent direction at v of bitangent i (within v's range).
  Dir bitangent_dir(int v, int i) const {
    const Bitangent2D& b = ix.complex->graph.bitangents[i];
    const int w = b.a == v ? b.b : b.a;
    const Dir d{&P()[v], &P()[w]};
    return in_range(v, d) ? d : d.reversed();
  }

  // Object met beyond silhouette vertex y along R (tangent at y, no visible vertex on the ray beyond y and
  // R not a bitangent direction at y): from the complex edge of y's tangent family holding R.
  int object_beyond(int y, const Dir& R) const {
    const bool forward = in_range(y, R);
    const Dir t = forward ? R : R.reversed();
    if (!forward && !in_range(y, t)) throw std::logic_error("complex walk: silhouette vertex not tangent (bug)");
    for (int j : ix.pivot_edges[y]) {
      const ComplexEdge2D& e = ix.complex->edges[j];
      const auto& B = ix.complex->graph.bitangents;
      const bool s_at = e.vertices[0] >= 0 && (B[e.vertices[0]].a == y || B[e.vertices[0]].b == y);
      const bool e_at = e.vertices[1] >= 0 && (B[e.vertices[1]].a == y || B[e.vertices[1]].b == y);
      bool ok = true;
      if (s_at && e_at) {
        const Dir u0 = bitangent_dir(y, e.vertices[0]), u1 = bitangent_dir(y, e.vertices[1]);
        const bool after0 = cross_sign(*u0.from, *u0.to, *t.from, *t.to) == Sign::Positive;
        const bool before1 = cross_sign(*t.from, *t.to, *u1.from, *u1.to) == Sign::Positive;
        ok = cross_sign(*u0.from, *u0.to, *u1.from, *u1.to) == Sign::Positive ? (after0 && before1)
                                                                            : (after0 || before1);
      } else if (s_at) {
        const Dir u0 = bitangent_dir(y, e.vertices[0]);
        ok = cross_sign(*u0.from, *u0.to, *t.from, *t.to) == Sign::Positive;
      } else if (e_at) {
        const Dir u1 = bitangent_dir(y, e.vertices[1]);
        ok = cross_sign(*t.from, *t.to, *u1.from, *u1.to) == Sign::Positive;
      }
      if (ok) return e.end_objects[forward ? 1 : 0];
    }
    throw std::logic_error("complex walk: no complex edge holds a tangent line (bug)");
  }

  // The edge met by the ray from q in direction R, turned counterclockwise by an infinitesimal, given that
  // the ray at R reaches vertex y with nothing before it.
  int resolve(int y, const Dir& R) const {
    for (int guard = 0; guard <= s.num_vertices(); ++guard) {
      const int e = blocking_edge(y, R);
      if (e >= 0) return e;
      if (y >= n) throw std::logic_error("complex walk: the ray passes a frame corner (bug)");
      // beyond y: a visible vertex (or ring neighbour) in direction R
      const auto [lo, hi] = neighbours_in(y, R);
      if (lo < hi) {
        y = ix.neighbours[y][lo].vertex;
        continue;
      }
      // a bitangent through y with its other end behind y: its stored end beyond y
      SegmentEnd2D end;
      bool have_end = false;
      const auto [blo, bhi] = neighbours_in(y, R.reversed());
      for (std::size_t k = blo; k < bhi && !have_end; ++k) {
        const int t = ix.neighbours[y][k].bitangent;
        if (t < 0) continue;
        const Bitangent2D& b = ix.complex->graph.bitangents[t];
        end = b.a == y ? b.end_a : b.end_b;
        have_end = true;
      }
      if (!have_end) {
        const int obj = object_beyond(y, R);
        end = first_contact_feature(s, y, *R.from, *R.to, obj < 0 ? &frame_edges : &ix.object_edges[obj]);
        if (end.kind == SegmentEnd2D::Infinity)
          throw std::logic_error("complex walk: the ray misses the object the complex names (bug)");
      }
      if (end.kind == SegmentEnd2D::EdgeInterior) return end.id;
      if (end.kind == SegmentEnd2D::Vertex && end.id != y) {
        y = end.id;
        continue;
      }
      if (end.kind == SegmentEnd2D::Infinity) {
        end = first_contact_feature(s, y, *R.from, *R.to, &frame_edges);
        if (end.kind == SegmentEnd2D::EdgeInterior) return end.id;
        if (end.kind == SegmentEnd2D::Vertex) {
          y = end.id;
          continue;
        }
      }
      throw std::logic_error("complex walk: no contact beyond a silhouette vertex (bug)");
    }
    throw std::logic_error("complex walk: endless ray (bug)");
  }
};

}  // namespace

VisibilityPolygon2D visibility_polygon_in_complex(const ComplexWalkIndex2D& ix, const Scene2D& s, const Point2& q,
                                                  ComplexWalkStats2D* stats, std::vector<int>* visible_edges) {
  const int n = ix.scene->num_vertices();
  if (s.frame_ring < 0 || s.num_vertices() != n + 4 || s.rings[s.frame_ring].first != n)
    throw std::invalid_argument("complex walk needs with_frame() of the scene the complex was built on");
  if (on_boundary(s, q)) throw std::invalid_argument("query point lies on a polygon boundary");
  if (inside_obstacle(s, q)) throw std::invalid_argument("query point lies inside an object or outside the frame");
  Walk W{ix, s, q, n, {n, n + 1, n + 2, n + 3}};
  const auto& P = s.points;
  ComplexWalkStats2D st;
  // start: the line through q at direction 0 turned clockwise: front ray (1, -0), back ray (-1, +0)
  const Point2 east(q.x + 1, q.y), west(q.x - 1, q.y);
  int edge[2] = {W.edge_hit_before(Dir{&q, &east}, true), W.edge_hit_before(Dir{&q, &west}, false)};  // front, back
  std::vector<Point2> out[2];
  std::vector<int> seen{edge[0], edge[1]};
  Dir current{};
  bool started = false;
  static const std::vector<int> none;
  for (;;) {
    ++st.faces;
    std::array<int, 2> pair{W.object_or_infinity(edge[0]), W.object_or_infinity(edge[1])};
    if (pair[0] > pair[1]) std::swap(pair[0], pair[1]);
    const auto found = ix.candidates.find(pair);
    const std::vector<int>& cands = found == ix.candidates.end() ? none : found->second;
    // next event: the smallest line direction after `current` among slides and valid appearances
    Dir best{};
    bool have = false;
    int slide[2] = {-1, -1};
    std::vector<int> at_best;  // valid appearing vertices at direction `best`
    auto later = [&](const Dir& d) { return !started || compare_dir(current, d) < 0; };
    for (int side = 0; side < 2; ++side) {
      const int x = W.ccw_end(edge[side]);
      if (half_of(q, P[x]) != side) continue;  // reached only after this half-turn
      const Dir d = line_dir(q, P[x]);
      if (!later(d)) continue;
      const int c = have ? compare_dir(d, best) : -1;
      if (c < 0) {
        best = d, have = true;
        slide[0] = slide[1] = -1;
        at_best.clear();
      }
      if (c <= 0) slide[side] = x;
    }
    const Sign q_side[2] = {orientation2(P[edge[0]], P[s.next[edge[0]]], q),
                            orientation2(P[edge[1]], P[s.next[edge[1]]], q)};
    for (int w : cands) {
      ++st.candidates;
      const int side = half_of(q, P[w]);
      const Dir d = side == 0 ? Dir{&q, &P[w]} : Dir{&P[w], &q};
      const int c = have ? compare_dir(d, best) : -1;
      if (c > 0) continue;
      if (!later(d)) continue;
      if (!W.before_edge(w, edge[side], q_side[side])) continue;
      if (c < 0) {
        best = d, have = true;
        slide[0] = slide[1] = -1;
        at_best.clear();
      }
      at_best.push_back(w);
    }
    if (!have) break;
    current = best;
    started = true;
    for (int side = 0; side < 2; ++side) {
      const Dir R = side == 0 ? best : best.reversed();
      int nearest = -1;
      for (int w : at_best)
        if (half_of(q, P[w]) == side && (nearest < 0 || dot_sign(P[w], P[nearest], *R.from, *R.to) == Sign::Positive))
          nearest = w;
      int next = edge[side];
      if (nearest >= 0) {
        next = W.blocking_edge(W.nearest_towards_q(nearest), R);
        if (next < 0) throw std::logic_error("complex walk: an appearing vertex does not block (bug)");
      } else if (slide[side] >= 0) {
        next = W.resolve(slide[side], R);
      }
      if (next == edge[side]) continue;
      ++st.events;
      for (int e : {edge[side], next}) {
        const Point2 p = W.hit(e, R);
        if (out[side].empty() || out[side].back() != p) out[side].push_back(p);
      }
      edge[side] = next;
      seen.push_back(next);
    }
  }
  VisibilityPolygon2D vp;
  for (int side = 0; side < 2; ++side)
    for (Point2& p : out[side])
      if (vp.vertices.empty() || vp.vertices.back() != p) vp.vertices.push_back(std::move(p));
  while (vp.vertices.size() > 1 && vp.vertices.back() == vp.vertices.front()) vp.vertices.pop_back();
  if (stats) *stats = st;
  if (visible_edges) {
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    *visible_edges = std::move(seen);
  }
  return vp;
}

std::vector<VisibilityPolygon2D> visibility_polygons_in_complex(const ComplexWalkIndex2D& index,
                                                                const Scene2D& framed,
                                                                const std::vector<Point2>& points) {
  std::vector<VisibilityPolygon2D> out(points.size());
  std::vector<std::exception_ptr> errors(points.size());
  tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
    try {
      out[i] = visibility_polygon_in_complex(index, framed, points[i]);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  });
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  return out;
}

}  // namespace exactvis
