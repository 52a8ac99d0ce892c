#include "skeleton/rotational_visibility_2d.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <set>
#include <stdexcept>

#include <tbb/parallel_invoke.h>

namespace exactvis {
namespace {

// A direction as the vector to - from (never zero), with its class in the order of a sweep that starts
// just after direction (1, 0) (half 0) or (-1, 0) (half 1): class 0 for the first half-turn (0, pi]
// (resp. (pi, 2pi]), class 1 for the open second half-turn, class 2 for the start direction itself, which
// comes last. Within a class, the cross product orders the directions.
struct Dir {
  const Point2* from = nullptr;
  const Point2* to = nullptr;
  int cls = 0;
};

Dir make_dir(const Point2& from, const Point2& to, int half) {
  Sign sy = dy_sign(from, to);
  if (half) sy = -sy;
  int cls = 0;
  if (sy == Sign::Negative) {
    cls = 1;
  } else if (sy == Sign::Zero) {
    Sign sx = dx_sign(from, to);
    if (half) sx = -sx;
    cls = sx == Sign::Positive ? 2 : 0;
  }
  return {&from, &to, cls};
}

// -1, 0, +1: u before, with, after v in the sweep. Within one class the cross product decides.
int sweep_compare(const Dir& u, const Dir& v) {
  if (u.cls != v.cls) return u.cls < v.cls ? -1 : 1;
  if (u.cls == 2 || (u.from == v.from && u.to == v.to)) return 0;
  const Sign s = cross_sign(*u.from, *u.to, *v.from, *v.to);
  return s == Sign::Positive ? -1 : (s == Sign::Negative ? 1 : 0);
}

// q - p has the direction d.
bool same_direction(const Dir& d, const Point2& p, const Point2& q) {
  if (d.from == &p && d.to == &q) return true;
  return cross_sign(*d.from, *d.to, p, q) == Sign::Zero && dot_sign(*d.from, *d.to, p, q) == Sign::Positive;
}

constexpr int kOwn = -2;  // view: the ray runs inside the vertex's own object

// Order of the viewers of one edge (or of infinity) across the rays of direction theta+ (theta turned
// counterclockwise by an infinitesimal): by the offset cross(d, p), smaller first; on one line of
// direction d, the vertex further along d first (turning the rays counterclockwise moves the one behind
// to the left). Equal to the order of the hit points along the viewed edge.
struct ViewerLess {
  const std::vector<Point2>* P;
  const Dir* d;
  bool operator()(int p, int q) const {
    if (p == q) return false;
    const Point2 &a = (*P)[p], &b = (*P)[q];
    const bool on_d = (&a == d->from && &b == d->to) || (&a == d->to && &b == d->from);
    const Sign c = on_d ? Sign::Zero : cross_sign(*d->from, *d->to, b, a);  // cross(d, a - b)
    if (c != Sign::Zero) return c == Sign::Negative;
    return dot_sign(*d->from, *d->to, b, a) == Sign::Positive;
  }
};

// Views at the start direction (1, 0)+ = (1, eps): a plane sweep across the rays, in the order of the
// offset k(v) = y - eps x, keeping the edges crossed by the current ray ordered along it. For the start
// direction (-1, 0)+ the same sweep runs on the scene turned by pi (p -> -p), which keeps every
// orientation and reverses the offset order.
struct StartQuery {
  int v;
};

struct StartSweep {
  const Scene2D& s;
  const std::vector<Point2>& P;  // scene vertices, then free points (ids >= s.num_vertices())
  bool turned = false;      // start direction (-1, 0) instead of (1, 0)
  std::vector<int> lo, hi;  // per edge: endpoint with the smaller / larger offset

  // u before v in the offset order: y ascending, then x descending (for the turned scene: reversed).
  bool offset_less(int u, int v) const {
    if (turned) std::swap(u, v);
    const Sign sy = dy_sign(P[u], P[v]);
    if (sy != Sign::Zero) return sy == Sign::Positive;
    return dx_sign(P[u], P[v]) == Sign::Negative;
  }

  struct Less {
    const StartSweep* sw;
    using is_transparent = void;
    // Two edges crossed by one ray, disjoint: e1 nearer along the ray. Ahead of an edge directed from
    // lo to hi is its right side.
    bool operator()(int e1, int e2) const {
      if (e1 == e2) return false;
      const auto& P = sw->P;
      const Point2 &a1 = P[sw->lo[e1]], &b1 = P[sw->hi[e1]], &a2 = P[sw->lo[e2]], &b2 = P[sw->hi[e2]];
      const Sign o1 = orientation2(a1, b1, a2), o2 = orientation2(a1, b1, b2);
      if (o1 != Sign::Positive && o2 != Sign::Positive) return true;    // e2 ahead of line(e1)
      if (o1 != Sign::Negative && o2 != Sign::Negative) return false;  // e2 behind
      const Sign p1 = orientation2(a2, b2, a1), p2 = orientation2(a2, b2, b1);
      return p1 != Sign::Negative && p2 != Sign::Negative;  // e1 behind line(e2)
    }
    // edge before the query vertex: the vertex lies ahead of it
    bool operator()(int e, StartQuery q) const {
      const auto& P = sw->P;
      return orientation2(P[sw->lo[e]], P[sw->hi[e]], P[q.v]) == Sign::Negative;
    }
    bool operator()(StartQuery q, int e) const {
      const auto& P = sw->P;
      return orientation2(P[sw->lo[e]], P[sw->hi[e]], P[q.v]) == Sign::Positive;
    }
  };

  // view[v] for every vertex whose start ray is free (others keep their value): edge id or -1. Free
  // points that lie on a boundary or inside an object get bad[v] = 1.
  void run(std::vector<int>& view, const std::vector<char>& own, std::vector<char>& bad) {
    const int n = s.num_vertices(), N = static_cast<int>(P.size());
    lo.resize(n);
    hi.resize(n);
    std::vector<std::vector<int>> starting(N), ending(N);
    for (int e = 0; e < n; ++e) {
      int a = e, b = s.next[e];
      if (offset_less(b, a)) std::swap(a, b);
      lo[e] = a;
      hi[e] = b;
      starting[a].push_back(e);
      ending[b].push_back(e);
    }
    std::vector<int> order(N);
    for (int v = 0; v < N; ++v) order[v] = v;
    std::sort(order.begin(), order.end(), [&](int u, int v) { return offset_less(u, v); });
    for (int i = 0; i + 1 < N; ++i)  // a free point on a scene vertex
      if (P[order[i]] == P[order[i + 1]] && (order[i] >= n || order[i + 1] >= n)) {
        if (order[i] >= n) bad[order[i]] = 1;
        if (order[i + 1] >= n) bad[order[i + 1]] = 1;
      }
    std::set<int, Less> status(Less{this});
    std::vector<std::set<int, Less>::iterator> where(n, status.end());
    for (int v : order) {
      for (int e : ending[v]) {
        status.erase(where[e]);
        where[e] = status.end();
      }
      if (!own[v]) {
        const auto it = status.lower_bound(StartQuery{v});
        view[v] = it == status.end() ? -1 : *it;
        // a free point sees the free side (right) of the first edge ahead, never its line
        if (v >= n && (it == status.end() || orientation2(P[*it], P[s.next[*it]], P[v]) != Sign::Negative))
          bad[v] = 1;
      }
      for (int e : starting[v]) where[e] = status.insert(e).first;
    }
  }
};

// The direction theta+ lies in the open counterclockwise sector from a to b iff theta is in [a, b).
bool after_in_sector(const Dir& d, const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1) {
  if (cross_sign(*d.from, *d.to, a0, a1) == Sign::Zero && dot_sign(*d.from, *d.to, a0, a1) == Sign::Positive)
    return true;
  return in_open_ccw_sector(*d.from, *d.to, a0, a1, b0, b1);
}

struct Sweep {
  const Scene2D& s;
  const std::vector<Point2>& P;  // scene vertices, then free points (visibility polygon queries)
  int n;                         // scene vertices
  int N;                         // scene vertices and free points
  int half = 0;            // this sweep covers the directions (0, pi] (half 0) or (pi, 2pi] (half 1)
  Dir cur;                 // current direction; the lists are ordered for cur+
  bool started = false;    // false before the first event: every candidate lies ahead
  std::vector<int> view;   // kOwn, -1 (infinity) or edge id; the state at cur+
  std::vector<std::set<int, ViewerLess>> lists;  // per edge, and lists[n] for infinity
  std::vector<std::set<int, ViewerLess>::iterator> where;
  std::vector<int> version;

  struct Entry {
    Dir d;
    int v;
    int version;  // -1: ray query number v
  };
  const std::vector<RayQuery2D>* queries = nullptr;
  std::vector<SegmentEnd2D> answers;
  std::vector<char> answered;
  struct Later {
    bool operator()(const Entry& x, const Entry& y) const { return sweep_compare(x.d, y.d) > 0; }
  };
  std::priority_queue<Entry, std::vector<Entry>, Later> heap;

  bool report_pairs = true;  // false when free points take part (their passes are no pairs)
  std::vector<char> bad;      // per free point: on a boundary or inside an object (from the start views)
  std::vector<std::vector<Point2>> polygon;  // per free point: visibility polygon vertices of this half-turn
  std::vector<std::vector<Point2>> polygon_front;  // ... those at direction (1, 0) (half 1), which come first

  Sweep(const Scene2D& scene, const std::vector<Point2>& points)
      : s(scene), P(points), n(scene.num_vertices()), N(static_cast<int>(points.size())) {}

  std::set<int, ViewerLess>& list_of(int v) { return lists[view[v] < 0 ? n : view[v]]; }

  // The next event of v after cur (v's state at cur+), pushed with a fresh version.
  void schedule(int v) {
    const int ver = ++version[v];
    Dir best;
    bool have = false;
    auto consider = [&](int to) {
      const Dir d = make_dir(P[v], P[to], half);
      if (started && sweep_compare(d, cur) <= 0) return;  // wraps past the end of the turn
      if (!have || sweep_compare(d, best) < 0) best = d, have = true;
    };
    if (view[v] == kOwn) {
      consider(s.prev[v]);  // the ray leaves the object along edge (v, prev v)
    } else {
      if (v < n) consider(s.next[v]);  // the ray enters the object along edge (v, next v)
      const auto it = std::next(where[v]);
      if (it != list_of(v).end()) consider(*it);  // the left neighbour: v's ray will pass it
      if (view[v] >= 0) {
        const int a = view[v], b = s.next[a];
        consider(orientation2(P[v], P[a], P[b]) == Sign::Positive ? b : a);  // counterclockwise end
      }
    }
    if (have) heap.push({best, v, ver});
  }

  void insert(int v) {
    if (view[v] == kOwn) return;
    where[v] = list_of(v).insert(v).first;
  }

  // New view of a ray of direction cur+ that passes vertex q on its left (q's view at cur+ is final).
  int pass(int q) const {
    if (q >= n) return view[q];  // a free point blocks nothing
    const Point2& c = P[q];
    const int u1 = s.next[q], u2 = s.prev[q];
    const bool l1 = cross_sign(*cur.from, *cur.to, c, P[u1]) == Sign::Positive;
    const bool l2 = cross_sign(*cur.from, *cur.to, c, P[u2]) == Sign::Positive;
    if (l1 && l2) return cross_sign(c, P[u1], c, P[u2]) == Sign::Negative ? q : u2;  // larger angle first
    if (l1) return q;
    if (l2) return u2;
    if (view[q] == kOwn) throw std::logic_error("rotational_visible_pairs: inherited an own-object view (bug)");
    return view[q];
  }

  // The visible edge of free point p changes at direction d from edge e1 to e2: the polygon gets the two
  // points of the ray hit on them (an endpoint on the ray exactly, else the exact intersection).
  void record_polygon(int p, const Dir& d, int e1, int e2) {
    if (e1 < 0 || e2 < 0) throw std::invalid_argument("visibility region is unbounded");
    const Point2& q = P[p];
    const Point2 r(q.x + (d.to->x - d.from->x), q.y + (d.to->y - d.from->y));
    auto& out = half == 1 && d.cls == 0 && is_positive_x(d) ? polygon_front[p - n] : polygon[p - n];
    for (const int e : {e1, e2}) {
      const Point2 &a = P[e], &b = P[s.next[e]];
      const Point2 h = orientation2(q, r, a) == Sign::Zero   ? a
                       : orientation2(q, r, b) == Sign::Zero ? b
                                                             : line_intersection(q, q, r, a, b);
      if (out.empty() || out.back() != h) out.push_back(h);
    }
  }

  static bool is_positive_x(const Dir& d) {
    return dy_sign(*d.from, *d.to) == Sign::Zero && dx_sign(*d.from, *d.to) == Sign::Positive;
  }

  struct Hit {
    enum Kind { None, EnterOwn, LeaveOwn, Vertex } kind = None;
    int q = -1;
  };

  std::vector<std::vector<VisibleFrom2D>> run(void (*progress)(double)) {
    std::vector<std::vector<VisibleFrom2D>> found(n);
    bad.assign(N, 0);
    polygon.assign(N - n, {});
    polygon_front.assign(N - n, {});
    static const Point2 origin(0.0, 0.0), unit_x(1.0, 0.0), minus_x(-1.0, 0.0);
    cur = make_dir(origin, half ? minus_x : unit_x, half);
    view.assign(N, -1);
    version.assign(N, 0);
    std::vector<char> own(N, 0);
    for (int v = 0; v < n; ++v) {
      own[v] = after_in_sector(cur, P[v], P[s.next[v]], P[v], P[s.prev[v]]);
      if (own[v]) view[v] = kOwn;
    }
    StartSweep{s, P, half == 1, {}, {}}.run(view, own, bad);
    lists.assign(n + 1, std::set<int, ViewerLess>(ViewerLess{&P, &cur}));
    for (int v = n; v < N; ++v)
      if (bad[v]) throw std::invalid_argument("query point lies on a polygon boundary, inside an object or outside the frame");
    where.resize(N);
    for (int v = 0; v < N; ++v) insert(v);
    for (int v = 0; v < N; ++v) schedule(v);
    if (queries) {
      answers.assign(queries->size(), {});
      answered.assign(queries->size(), 0);
      for (std::size_t i = 0; i < queries->size(); ++i)
        heap.push({make_dir(*(*queries)[i].from, *(*queries)[i].to, half), static_cast<int>(i), -1});
    }
    started = true;
    std::vector<int> asked;

    std::vector<int> S;
    std::vector<Hit> hit(N);
    std::vector<char> in_S(N, 0);
    std::vector<int> touched;
    std::size_t steps = 0;
    while (!heap.empty() && heap.top().d.cls == 0) {  // this sweep's half-turn only
      // all valid events at the next direction
      const Dir d = heap.top().d;
      S.clear();
      asked.clear();
      while (!heap.empty() && sweep_compare(heap.top().d, d) == 0) {
        const Entry e = heap.top();
        heap.pop();
        if (e.version < 0) {
          asked.push_back(e.v);
          continue;
        }
        if (e.version != version[e.v] || in_S[e.v]) continue;
        in_S[e.v] = 1;
        S.push_back(e.v);
      }
      if (S.empty() && asked.empty()) continue;
      // 1. what each ray meets first at exactly d, from the state at d- (lists not yet changed)
      for (int p : S) {
        Hit h;
        if (view[p] == kOwn) {
          if (same_direction(d, P[p], P[s.prev[p]])) h = {Hit::LeaveOwn, s.prev[p]};
        } else if (p < n && same_direction(d, P[p], P[s.next[p]])) {
          h = {Hit::EnterOwn, s.next[p]};
        } else {
          const auto it = std::next(where[p]);
          if (it != list_of(p).end() && same_direction(d, P[p], P[*it])) {
            h = {Hit::Vertex, *it};
          } else if (view[p] >= 0) {
            const int a = view[p], b = s.next[a];
            const int end = orientation2(P[p], P[a], P[b]) == Sign::Positive ? b : a;
            if (same_direction(d, P[p], P[end])) h = {Hit::Vertex, end};
          }
        }
        if (h.kind == Hit::None) throw std::logic_error("rotational_visible_pairs: empty event (bug)");
        hit[p] = h;
      }
      // ray queries: the first contact at exactly d (state at d-, events at d)
      for (int i : asked) {
        const int v = (*queries)[i].vertex;
        SegmentEnd2D& a = answers[i];
        answered[i] = 1;
        if (in_S[v] && hit[v].kind != Hit::None) {
          a = {SegmentEnd2D::Vertex, hit[v].q, s.object_of(hit[v].q), {}};
        } else if (view[v] >= 0) {
          a = {SegmentEnd2D::EdgeInterior, view[v], s.object_of(view[v]), {}};
        } else if (view[v] == kOwn) {
          throw std::logic_error("rotational_first_contacts: ray inside its own object");
        }
      }
      // 2. the strict pairs, with the maximal free segment's end beyond w for tangent ones
      for (int p : S) {
        if (!report_pairs || hit[p].kind != Hit::Vertex) continue;
        const int w = hit[p].q;
        if (!in_free_wedge(s, p, P[p], P[w]))
          throw std::logic_error("rotational_visible_pairs: visible vertex outside the free wedge (bug)");
        VisibleFrom2D f;
        f.w = w;
        f.tangent = !in_object_wedge(s, p, P[w], P[p]) && !in_object_wedge(s, w, P[p], P[w]);
        if (f.tangent) {
          const auto along = [&](int u) { return same_direction(d, P[w], P[u]); };
          if (along(s.next[w]) || along(s.prev[w])) {
            f.beyond = {SegmentEnd2D::Vertex, w, s.object_of(w), P[w]};
          } else if (in_S[w] && hit[w].kind == Hit::Vertex) {
            const int r = hit[w].q;
            f.beyond = {SegmentEnd2D::Vertex, r, s.object_of(r), P[r]};
          } else if (view[w] >= 0) {
            const int e = view[w];
            f.beyond = {SegmentEnd2D::EdgeInterior, e, s.object_of(e),
                        line_intersection(P[p], P[p], P[w], P[e], P[s.next[e]])};
          } else if (view[w] == kOwn) {
            throw std::logic_error("rotational_visible_pairs: tangent ray inside its object (bug)");
          }
        }
        found[p].push_back(std::move(f));
      }
      // 3. leave the lists (in the order at d-), then turn the order to d+ and enter the new views,
      //    further along d first: a ray passing q inherits q's view at d+
      touched.clear();
      for (int p : S) {
        if (view[p] == kOwn) continue;
        auto& L = list_of(p);
        if (where[p] != L.begin()) touched.push_back(*std::prev(where[p]));
        L.erase(where[p]);
      }
      cur = d;
      std::sort(S.begin(), S.end(), [&](int a, int b) { return dot_sign(*d.from, *d.to, P[b], P[a]) == Sign::Positive; });
      for (int p : S) {
        const int before = view[p];
        view[p] = hit[p].kind == Hit::EnterOwn ? kOwn : pass(hit[p].q);
        if (p >= n && view[p] != before) record_polygon(p, d, before, view[p]);
        insert(p);
        if (view[p] != kOwn && where[p] != list_of(p).begin()) touched.push_back(*std::prev(where[p]));
      }
      for (int p : S) in_S[p] = 0;
      for (int p : S) schedule(p);
      for (int v : touched) schedule(v);
      if (progress && (++steps % 4096 == 0)) {
        const double a = std::atan2(d.to->ay - d.from->ay, d.to->ax - d.from->ax);
        progress(std::clamp((a < 0 ? a + 6.283185307179586 : a) / 3.141592653589793 - half, 0.0, 1.0));
      }
    }
    if (progress) progress(1.0);
    return found;
  }
};

}  // namespace

// The turn is cut into the half-turns (0, pi] and (pi, 2pi], swept in parallel from their own start
// views; every direction belongs to exactly one of them, so each strict pair is still found once from
// each end and each query is answered once.
std::vector<std::vector<VisibleFrom2D>> rotational_visible_pairs(const Scene2D& scene, void (*progress)(double)) {
  Sweep first(scene, scene.points), second(scene, scene.points);
  first.half = 0;
  second.half = 1;
  std::vector<std::vector<VisibleFrom2D>> a, b;
  tbb::parallel_invoke([&] { a = first.run(progress); }, [&] { b = second.run(nullptr); });
  for (std::size_t v = 0; v < a.size(); ++v) a[v].insert(a[v].end(), b[v].begin(), b[v].end());
  return a;
}

std::vector<SegmentEnd2D> rotational_first_contacts(const Scene2D& scene, const std::vector<RayQuery2D>& queries) {
  Sweep first(scene, scene.points), second(scene, scene.points);
  first.half = 0;
  second.half = 1;
  first.queries = second.queries = &queries;
  tbb::parallel_invoke([&] { first.run(nullptr); }, [&] { second.run(nullptr); });
  // each query was answered by the sweep of its half-turn
  std::vector<SegmentEnd2D> out(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i)
    out[i] = first.answered[i] ? first.answers[i] : second.answers[i];
  return out;
}

}  // namespace exactvis

namespace exactvis {

std::vector<std::vector<Point2>> rotational_visibility_polygons(const Scene2D& scene, const std::vector<Point2>& points) {
  const int n = scene.num_vertices();
  // distinct points only (equal free points would be equal in the viewer order)
  std::vector<int> order(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) order[i] = static_cast<int>(i);
  auto less = [&](int a, int b) {
    const Sign sx = dx_sign(points[b], points[a]);
    if (sx != Sign::Zero) return sx == Sign::Negative;
    return dy_sign(points[b], points[a]) == Sign::Negative;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<int> slot(points.size());
  std::vector<Point2> all = scene.points;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || points[order[i]] != points[order[i - 1]]) all.push_back(points[order[i]]);
    slot[order[i]] = static_cast<int>(all.size()) - 1 - n;
  }
  Sweep first(scene, all), second(scene, all);
  first.half = 0;
  second.half = 1;
  first.report_pairs = second.report_pairs = false;
  tbb::parallel_invoke([&] { first.run(nullptr); }, [&] { second.run(nullptr); });
  std::vector<std::vector<Point2>> out(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const int k = slot[i];
    auto& poly = out[i];
    for (const auto* part : {&second.polygon_front[k], &first.polygon[k], &second.polygon[k]})
      for (const Point2& p : *part)
        if (poly.empty() || poly.back() != p) poly.push_back(p);
    while (poly.size() > 1 && poly.back() == poly.front()) poly.pop_back();
  }
  return out;
}

}  // namespace exactvis
