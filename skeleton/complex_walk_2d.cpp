#include "skeleton/complex_walk_2d.hpp"

#include "skeleton/angular_sweep_2d.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <exception>
#include <tuple>
#include <limits>
#include <stdexcept>

namespace exactvis {
namespace {

// 0 for directions in [0, pi) (dy > 0, or dy = 0 and dx > 0), 1 for [pi, 2pi).
int half_of(const Point2& from, const Point2& to) {
  const Sign sy = dy_sign(from, to);
  if (sy != Sign::Zero) return sy == Sign::Positive ? 0 : 1;
  return dx_sign(from, to) == Sign::Positive ? 0 : 1;
}

// The bounding box of the interval enclosures of some points: a point whose enclosure misses it is certainly
// outside their convex hull (exact comparisons of doubles).
struct EnclosureBox {
  double lo_x = std::numeric_limits<double>::infinity(), hi_x = -std::numeric_limits<double>::infinity();
  double lo_y = std::numeric_limits<double>::infinity(), hi_y = -std::numeric_limits<double>::infinity();
  void add(const Point2& p) {
    lo_x = std::min(lo_x, p.ix.inf()), hi_x = std::max(hi_x, p.ix.sup());
    lo_y = std::min(lo_y, p.iy.inf()), hi_y = std::max(hi_y, p.iy.sup());
  }
  bool meets(const Point2& p) const {
    return p.ix.sup() >= lo_x && p.ix.inf() <= hi_x && p.iy.sup() >= lo_y && p.iy.inf() <= hi_y;
  }
};

// A direction given by two points (vector to - from), never constructed.
struct Dir {
  const Point2* from = nullptr;
  const Point2* to = nullptr;
  Dir reversed() const { return {to, from}; }
};

// The line direction of p - q taken in [0, pi).
Dir line_dir(const Point2& q, const Point2& p) { return half_of(q, p) == 0 ? Dir{&q, &p} : Dir{&p, &q}; }

// Sign of cross(u.to - u.from, v.to - v.from), the walk's direction comparison, through the three layers
// (counter "walk_cross2"). Directions spanned by the same two points (in either order) are parallel: 0
// without evaluating (an exact zero that no filter can certify when the coordinates' products are not
// representable, so it would take the exact path). `doubles`: every coordinate involved is a double (known
// for a whole query), so layer 1 is the kernel's semi-static filter without per-call tests.
Sign cross_dir(const Dir& u, const Dir& v, bool doubles) {
  if ((u.from == v.from && u.to == v.to) || (u.from == v.to && u.to == v.from)) return Sign::Zero;
  static PredicateCounter counter("walk_cross2");
  const Point2 &u0 = *u.from, &u1 = *u.to, &v0 = *v.from, &v1 = *v.to;
  auto expr = [&](auto nt) {
    using NT = typename decltype(nt)::type;
    return (px<NT>(u1) - px<NT>(u0)) * (py<NT>(v1) - py<NT>(v0)) - (py<NT>(u1) - py<NT>(u0)) * (px<NT>(v1) - px<NT>(v0));
  };
  return filtered_sign_with(counter, [&]() -> std::optional<Sign> {
    if (doubles) return cross2d_semi_static(u0.ax, u0.ay, u1.ax, u1.ay, v0.ax, v0.ay, v1.ax, v1.ay);
    return expr(NumberTag<BoundedDouble>{}).certified_sign();
  }, expr);
}

// The point's coordinates are doubles (point enclosures; then ax, ay are them).
bool double_coordinates(const Point2& p) { return p.ix.inf() == p.ix.sup() && p.iy.inf() == p.iy.sup(); }

// Order of two line directions taken in [0, pi) (as line_dir gives them): one cross product decides.
int compare_dir(const Dir& u, const Dir& v, bool doubles) {
  const Sign c = cross_dir(u, v, doubles);
  return c == Sign::Positive ? -1 : (c == Sign::Negative ? 1 : 0);
}

// Is the oriented direction t within the closed range of tangent directions of convex vertex v, oriented
// as in the complex's construction: from prev v - v to v - next v, counterclockwise (< pi)? The sample
// direction of a complex edge is oriented this way, so its end_objects[1] lies ahead along such a t.
bool in_tangent_range(const Scene2D& s, int v, const Dir& t, bool doubles) {
  const auto& P = s.points;
  return cross_dir(Dir{&P[v], &P[s.prev[v]]}, t, doubles) != Sign::Negative &&
         cross_dir(t, Dir{&P[s.next[v]], &P[v]}, doubles) != Sign::Negative;
}

// Oriented tangent direction at v of bitangent i (within v's range), as the vertex pair (from, to).
std::pair<int, int> bitangent_dir_at(const Scene2D& s, const VisibilityComplex2D& cx, int v, int i) {
  const Bitangent2D& b = cx.graph.bitangents[i];
  const int w = b.a == v ? b.b : b.a;
  return in_tangent_range(s, v, Dir{&s.points[v], &s.points[w]}, false) ? std::pair{v, w} : std::pair{w, v};
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
    for (auto& x : list) x.half = half_of(P[v], P[x.vertex]);
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
      if (!pe.empty() && pe.back().edge == static_cast<int>(j)) continue;
      ComplexWalkIndex2D::PivotEdge p;
      p.edge = static_cast<int>(j);
      auto at_v = [&](int t) { return t >= 0 && (B[t].a == v || B[t].b == v); };
      if (at_v(e.vertices[0])) std::tie(p.start_from, p.start_to) = bitangent_dir_at(scene, cx, v, e.vertices[0]);
      if (at_v(e.vertices[1])) std::tie(p.end_from, p.end_to) = bitangent_dir_at(scene, cx, v, e.vertices[1]);
      if (p.start_from >= 0 && p.end_from >= 0)
        p.narrow = cross_dir(Dir{&P[p.start_from], &P[p.start_to]}, Dir{&P[p.end_from], &P[p.end_to]}, false) ==
                   Sign::Positive;
      pe.push_back(p);
    }
  }
  for (auto& [pair, cand] : ix.candidates) {
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  }
  ix.object_edges.resize(scene.num_objects);
  for (int e = 0; e < n; ++e) ix.object_edges[scene.object_of(e)].push_back(e);
  ix.location = point_location_2d(scene);
  ix.double_coordinates = std::all_of(P.begin(), P.end(), double_coordinates);
  return ix;
}

namespace {

struct Walk {
  const ComplexWalkIndex2D& ix;
  const Scene2D& s;  // framed
  const Point2& q;
  int n;             // vertices of the unframed scene; ids >= n are frame corners
  std::vector<int> frame_edges;
  bool doubles = false;  // every coordinate (scene, frame, q) is a double: see cross_dir

  const std::vector<Point2>& P() const { return s.points; }
  int object_or_infinity(int e) const { return e >= n ? -1 : s.object_of(e); }

  // The frame edge hit by the ray from q in direction R = (+-1, 0) turned clockwise by an infinitesimal
  // angle (when the ray meets no scene edge).
  int frame_edge_hit_before(const Dir& R, bool east) const {
    int best = -1;
    for (int e : frame_edges) {
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
    if (cross_dir(R, Dir{&q, &a}, doubles) == Sign::Zero) return a;
    if (cross_dir(R, Dir{&q, &b}, doubles) == Sign::Zero) return b;
    return line_intersection(q, *R.from, *R.to, a, b);
  }

  // At vertex w on a ray of direction R, the edge of w that the ray meets once turned counterclockwise by
  // an infinitesimal (it then passes w on w's left): the edge of w going into the open left half-plane,
  // the one of larger angle from R if both do; -1 if none (the ray passes w).
  int blocking_edge(int w, const Dir& R) const {
    const int o1 = s.next[w], o2 = s.prev[w];
    const bool l1 = cross_dir(R, Dir{&P()[w], &P()[o1]}, doubles) == Sign::Positive;
    const bool l2 = cross_dir(R, Dir{&P()[w], &P()[o2]}, doubles) == Sign::Positive;
    if (l1 && l2) return cross_dir(Dir{&P()[w], &P()[o1]}, Dir{&P()[w], &P()[o2]}, doubles) == Sign::Positive ? o2 : w;
    if (l1) return w;
    if (l2) return o2;
    return -1;
  }

  // Neighbours of v (visibility graph and ring) in exactly direction R: [first, last) nearest first.
  std::pair<std::size_t, std::size_t> neighbours_in(int v, const Dir& R) const {
    const auto& list = ix.neighbours[v];
    const int hr = half_of(*R.from, *R.to);
    // compare_angle(v -> x, R) with the halves of the neighbours' directions stored in the index
    auto cmp = [&](const ComplexWalkIndex2D::Neighbour& x) {
      if (x.half != hr) return x.half < hr ? -1 : 1;
      const Sign c = cross_dir(Dir{&P()[v], &P()[x.vertex]}, R, doubles);
      return c == Sign::Positive ? -1 : (c == Sign::Negative ? 1 : 0);
    };
    std::size_t lo = 0, hi = list.size();
    while (lo < hi) {  // first with direction >= R
      const std::size_t mid = (lo + hi) / 2;
      if (cmp(list[mid]) < 0) lo = mid + 1; else hi = mid;
    }
    std::size_t end = lo;
    while (end < list.size() && cmp(list[end]) == 0) ++end;
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

  // Object met beyond silhouette vertex y along R (tangent at y, no visible vertex on the ray beyond y and
  // R not a bitangent direction at y): from the complex edge of y's tangent family holding R.
  int object_beyond(int y, const Dir& R) const {
    const bool forward = in_tangent_range(s, y, R, doubles);
    const Dir t = forward ? R : R.reversed();
    if (!forward && !in_tangent_range(s, y, t, doubles))
      throw std::logic_error("complex walk: silhouette vertex not tangent (bug)");
    for (const ComplexWalkIndex2D::PivotEdge& p : ix.pivot_edges[y]) {
      const ComplexEdge2D& e = ix.complex->edges[p.edge];
      bool ok = true;
      if (p.start_from >= 0 && p.end_from >= 0) {
        const bool after0 = cross_dir(Dir{&P()[p.start_from], &P()[p.start_to]}, t, doubles) == Sign::Positive;
        const bool before1 = cross_dir(t, Dir{&P()[p.end_from], &P()[p.end_to]}, doubles) == Sign::Positive;
        ok = p.narrow ? (after0 && before1) : (after0 || before1);
      } else if (p.start_from >= 0) {
        ok = cross_dir(Dir{&P()[p.start_from], &P()[p.start_to]}, t, doubles) == Sign::Positive;
      } else if (p.end_from >= 0) {
        ok = cross_dir(t, Dir{&P()[p.end_from], &P()[p.end_to]}, doubles) == Sign::Positive;
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
      // a bitangent through y with its other end behind y: its stored end beyond y (kind and id only: the
      // contact point is not needed, and a SegmentEnd2D would allocate its exact point)
      SegmentEnd2D::Kind kind = SegmentEnd2D::Infinity;
      int id = -1;
      bool have_end = false;
      const auto [blo, bhi] = neighbours_in(y, R.reversed());
      for (std::size_t k = blo; k < bhi && !have_end; ++k) {
        const int t = ix.neighbours[y][k].bitangent;
        if (t < 0) continue;
        const Bitangent2D& b = ix.complex->graph.bitangents[t];
        const SegmentEnd2D& end = b.a == y ? b.end_a : b.end_b;
        kind = end.kind, id = end.id;
        have_end = true;
      }
      if (!have_end) {
        const int obj = object_beyond(y, R);
        const SegmentEnd2D end =
            first_contact_feature(s, y, *R.from, *R.to, obj < 0 ? &frame_edges : &ix.object_edges[obj]);
        if (end.kind == SegmentEnd2D::Infinity)
          throw std::logic_error("complex walk: the ray misses the object the complex names (bug)");
        kind = end.kind, id = end.id;
      }
      if (kind == SegmentEnd2D::EdgeInterior) return id;
      if (kind == SegmentEnd2D::Vertex && id != y) {
        y = id;
        continue;
      }
      if (kind == SegmentEnd2D::Infinity) {
        const SegmentEnd2D end = first_contact_feature(s, y, *R.from, *R.to, &frame_edges);
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
  const Ring2D& frame = s.rings[s.frame_ring];
  const LocatedPoint2D at = locate_point(ix.location, q);
  if (on_ring(s.points, frame.first, frame.size, q) || at.on_boundary)
    throw std::invalid_argument("query point lies on a polygon boundary");
  if (!frame_contains(s, q) || at.inside_object)
    throw std::invalid_argument("query point lies inside an object or outside the frame");
  Walk W{ix, s, q, n, {n, n + 1, n + 2, n + 3}};
  W.doubles = ix.double_coordinates && double_coordinates(q) &&
              std::all_of(s.points.begin() + n, s.points.end(), double_coordinates);
  const auto& P = s.points;
  ComplexWalkStats2D st;
  // start: the line through q at direction 0 turned clockwise: front ray (1, -0), back ray (-1, +0); a
  // scene edge met is nearer than the frame, which encloses the scene
  auto frame_hit = [&](bool front) {
    const Point2 far(front ? q.x + 1 : q.x - 1, q.y);
    return W.frame_edge_hit_before(Dir{&q, &far}, front);
  };
  int edge[2] = {at.east >= 0 ? at.east : frame_hit(true), at.west >= 0 ? at.west : frame_hit(false)};  // front, back
  std::vector<Point2> out[2];
  std::vector<int> seen{edge[0], edge[1]};
  Dir current{};
  bool started = false;
  static const std::vector<int> none;
  std::vector<int> at_best;  // valid appearing vertices at direction `best`
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
    at_best.clear();
    auto later = [&](const Dir& d) { return !started || compare_dir(current, d, W.doubles) < 0; };
    EnclosureBox swept[2];  // per side: contains every point between q and the hit edge until its slide
    for (int side = 0; side < 2; ++side) {
      const int x = W.ccw_end(edge[side]);
      // the hit point moves along the edge towards its counterclockwise end x: the segment from q sweeps
      // the triangle (q, last hit point, x), within the triangle (q, edge) before the first event
      swept[side].add(q), swept[side].add(P[x]);
      if (out[side].empty()) swept[side].add(P[edge[side]]), swept[side].add(P[s.next[edge[side]]]);
      else swept[side].add(out[side].back());
      if (half_of(q, P[x]) != side) continue;  // reached only after this half-turn
      const Dir d = line_dir(q, P[x]);
      if (!later(d)) continue;
      const int c = have ? compare_dir(d, best, W.doubles) : -1;
      if (c < 0) {
        best = d, have = true;
        slide[0] = slide[1] = -1;
        at_best.clear();
      }
      if (c <= 0) slide[side] = x;
    }
    Sign q_side[2] = {Sign::Zero, Sign::Zero};  // orientation2(edge, q), computed when first needed
    for (int w : cands) {
      ++st.candidates;
      // an event vertex lies strictly between q and its side's hit edge, inside that side's swept triangle
      const bool in0 = swept[0].meets(P[w]), in1 = swept[1].meets(P[w]);
      if (!in0 && !in1) continue;
      const int side = half_of(q, P[w]);
      if (!(side == 0 ? in0 : in1)) continue;
      ++st.candidates_tested;
      const Dir d = side == 0 ? Dir{&q, &P[w]} : Dir{&P[w], &q};
      const int c = have ? compare_dir(d, best, W.doubles) : -1;
      if (c > 0) continue;
      if (!later(d)) continue;
      if (q_side[side] == Sign::Zero) q_side[side] = orientation2(P[edge[side]], P[s.next[edge[side]]], q);
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
        Point2 p = W.hit(e, R);
        if (out[side].empty() || out[side].back() != p) out[side].push_back(std::move(p));
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
