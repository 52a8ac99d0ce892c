#include "skeleton/visibility_complex_2d.hpp"

#include "skeleton/angular_sweep_2d.hpp"
#include "skeleton/rotational_visibility_2d.hpp"
#include "util/union_find.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace exactvis {

SegmentEnd2D first_contact_feature(const Scene2D& s, int v, const Point2& d0, const Point2& d1,
                                   const std::vector<int>* edges) {
  // Candidates are compared by orientation tests only (no parameters along the ray): of two edges crossing
  // the ray, one lies on o's side of the other's line (scene edges are disjoint); a vertex on the ray comes
  // before an edge's crossing iff it lies on o's side of the edge's line.
  const auto& P = s.points;
  const Point2& o = P[v];
  SegmentEnd2D best;
  auto on_o_side = [&](int e, const Point2& p) {
    const Sign sp = orientation2(P[e], P[s.next[e]], p);
    return sp != Sign::Zero && sp == orientation2(P[e], P[s.next[e]], o);
  };
  auto nearer = [&](SegmentEnd2D::Kind kind, int id) {
    if (best.kind == SegmentEnd2D::Infinity) return true;
    if (kind == SegmentEnd2D::Vertex && best.kind == SegmentEnd2D::Vertex)
      return dot_sign(P[id], P[best.id], d0, d1) == Sign::Positive;
    if (kind == SegmentEnd2D::Vertex) return on_o_side(best.id, P[id]);
    if (best.kind == SegmentEnd2D::Vertex) return !on_o_side(id, P[best.id]);
    return edge_closer(s, o, id, best.id);
  };
  auto consider = [&](SegmentEnd2D::Kind kind, int id) {
    if (!nearer(kind, id)) return;
    best.kind = kind;
    best.id = id;
  };
  const int count = edges ? static_cast<int>(edges->size()) : s.num_vertices();
  for (int i = 0; i < count; ++i) {
    const int e = edges ? (*edges)[i] : i;
    const int a = e, b = s.next[e];
    if (a == v || b == v) continue;
    const Sign oa = cross_sign(d0, d1, o, P[a]), ob = cross_sign(d0, d1, o, P[b]);
    if (oa != Sign::Zero && oa == ob) continue;
    if (oa == Sign::Zero || ob == Sign::Zero) {  // an endpoint on the line (both: a collinear edge)
      for (int w : {a, b})
        if ((w == a ? oa : ob) == Sign::Zero && dot_sign(o, P[w], d0, d1) == Sign::Positive)
          consider(SegmentEnd2D::Vertex, w);
      continue;
    }
    // proper crossing of the line; ahead iff o lies on the side of e's line opposite to the direction
    if (cross_sign(o, P[a], P[a], P[b]) != cross_sign(d0, d1, P[a], P[b])) continue;
    consider(SegmentEnd2D::EdgeInterior, e);
  }
  if (best.kind != SegmentEnd2D::Infinity) best.object = s.object_of(best.id);
  return best;
}

SegmentEnd2D first_contact(const Scene2D& s, int v, const Point2& d0, const Point2& d1,
                           const std::vector<int>* edges) {
  SegmentEnd2D end = first_contact_feature(s, v, d0, d1, edges);
  const auto& P = s.points;
  if (end.kind == SegmentEnd2D::Vertex) end.point = P[end.id];
  if (end.kind == SegmentEnd2D::EdgeInterior) end.point = line_intersection(P[v], d0, d1, P[end.id], P[s.next[end.id]]);
  return end;
}

namespace {

struct Event {
  int vertex;     // scene vertex (pivot)
  int bitangent;
  bool at_a;      // the pivot is endpoint a of the bitangent
  Point2 rep;     // representative direction point: pivot + rep direction (within the pivot's range)
};

// Object met by the segments near a bitangent's line beyond its endpoint a when the line continues along an
// edge of a (an empty extension), on the side where they miss a's object near a: they run along the
// collinear edges from a; at the last collinear vertex c they enter a's object if the ring turns towards
// them there, else they go on to the first contact beyond c (-1: infinity). d1 - d0 points away from b.
int object_beyond_empty_extension(const Scene2D& s, int a, const Point2& d0, const Point2& d1) {
  const auto& P = s.points;
  auto ahead = [&](int c, int m) {  // m - c has exactly the direction d
    return cross_sign(d0, d1, P[c], P[m]) == Sign::Zero && dot_sign(d0, d1, P[c], P[m]) == Sign::Positive;
  };
  // the object lies on the left of each ring edge vertex -> next
  const Sign object_side = ahead(a, s.next[a]) ? Sign::Positive : Sign::Negative;
  int c = a, from = -1;
  for (int guard = 0; guard < s.num_vertices(); ++guard) {
    const int n = s.next[c] != from && ahead(c, s.next[c]) ? s.next[c] : (s.prev[c] != from && ahead(c, s.prev[c]) ? s.prev[c] : -1);
    if (n < 0) break;
    from = c;
    c = n;
  }
  const int m = s.next[c] == from ? s.prev[c] : s.next[c];
  if (cross_sign(d0, d1, P[c], P[m]) != object_side) return s.object_of(a);
  const Point2 t(P[c].x + (d1.x - d0.x), P[c].y + (d1.y - d0.y));
  return first_contact_feature(s, c, P[c], t).object;
}

Point2 add_dirs(const Point2& o, const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1) {
  return Point2(o.x + (a1.x - a0.x) + (b1.x - b0.x), o.y + (a1.y - a0.y) + (b1.y - b0.y));
}

}  // namespace

VisibilityComplex2D visibility_complex(const Scene2D& s, void (*progress)(double), VisibilityGraphMethod method) {
  VisibilityComplex2D cx;
  cx.graph = visibility_graph(s, progress, method);
  const auto& P = s.points;
  const auto& B = cx.graph.bitangents;
  const int n = s.num_vertices();
  std::vector<Sign> turn(n);
  for (int v = 0; v < n; ++v) turn[v] = orientation2(P[s.prev[v]], P[v], P[s.next[v]]);
  // range of v (convex): directions from S = prev - v to E = v - next, counterclockwise, < pi
  auto range_start = [&](int v, Point2& d0, Point2& d1) { d0 = P[v]; d1 = P[s.prev[v]]; };
  auto range_end = [&](int v, Point2& d0, Point2& d1) { d0 = P[s.next[v]]; d1 = P[v]; };
  // events per vertex, sorted along its range
  std::vector<std::vector<Event>> events(n);
  for (int i = 0; i < static_cast<int>(B.size()); ++i)
    for (int end = 0; end < 2; ++end) {
      const int v = end == 0 ? B[i].a : B[i].b, w = end == 0 ? B[i].b : B[i].a;
      Point2 s0, s1;
      range_start(v, s0, s1);
      // w - v lies in the closed range, or its opposite does
      const bool forward = cross_sign(s0, s1, P[v], P[w]) != Sign::Negative &&
                           cross_sign(P[v], P[w], P[s.next[v]], P[v]) != Sign::Negative;
      const Point2 rep = forward ? P[w] : Point2(P[v].x + P[v].x - P[w].x, P[v].y + P[v].y - P[w].y);
      events[v].push_back({v, i, end == 0, rep});
    }
  for (int v = 0; v < n; ++v)
    std::sort(events[v].begin(), events[v].end(), [&](const Event& x, const Event& y) {
      const Sign c = cross_sign(P[v], x.rep, P[v], y.rep);
      if (c != Sign::Zero) return c == Sign::Positive;
      return x.bitangent < y.bitangent;
    });
  cx.vertices.resize(B.size());
  for (std::size_t i = 0; i < B.size(); ++i) cx.vertices[i].bitangent = static_cast<int>(i);
  // chains: maximal runs of non-reflex vertices along each ring
  for (const Ring2D& R : s.rings) {
    std::vector<std::vector<int>> chains;
    int reflex = -1;
    for (int i = 0; i < R.size; ++i)
      if (turn[R.first + i] == Sign::Negative) reflex = R.first + i;
    bool closed = reflex < 0;
    if (closed) {
      chains.push_back({});
      for (int i = 0; i < R.size; ++i) chains.back().push_back(R.first + i);
    } else {
      // start after a reflex vertex and walk once around
      int v = s.next[reflex];
      for (int k = 0; k < R.size; ++k, v = s.next[v]) {
        if (turn[v] == Sign::Negative) { chains.push_back({}); continue; }
        if (chains.empty()) chains.push_back({});
        chains.back().push_back(v);
      }
    }
    for (const auto& chain : chains) {
      if (std::none_of(chain.begin(), chain.end(), [&](int v) { return turn[v] == Sign::Positive; })) continue;
      const int chain_id = cx.chains++;
      // event sequence along the chain
      std::vector<const Event*> seq;
      for (int v : chain)
        for (const Event& e : events[v]) seq.push_back(&e);
      // sample direction for the piece between `from` (event or chain start) and `to` (event or chain end)
      auto make_edge = [&](const Event* from, const Event* to, std::size_t from_pos, std::size_t to_pos, bool wraps) {
        ComplexEdge2D edge;
        edge.object = R.object;
        edge.chain = chain_id;
        edge.vertices = {from ? from->bitangent : -1, to ? to->bitangent : -1};
        // candidate sub-ranges in chain order: (vertex, lower bound, upper bound)
        const std::size_t first = from ? from_pos : 0, last = to ? to_pos : chain.size() - 1;
        bool found = false;
        auto try_range = [&](int v, const Point2& lo0, const Point2& lo1, const Point2& hi0, const Point2& hi1) {
          if (turn[v] != Sign::Positive) return;
          if (cross_sign(lo0, lo1, hi0, hi1) != Sign::Positive) return;  // empty sub-range
          edge.pivots.push_back(v);
          if (found) return;
          edge.pivot = v;
          edge.sample_from = P[v];
          edge.sample_to = add_dirs(P[v], lo0, lo1, hi0, hi1);
          found = true;
        };
        const std::size_t span = wraps ? last + chain.size() - first : last - first;
        for (std::size_t k = 0; k <= span; ++k) {
          const int v = chain[(first + k) % chain.size()];
          Point2 lo0, lo1, hi0, hi1;
          range_start(v, lo0, lo1);
          range_end(v, hi0, hi1);
          if (k == 0 && from) lo0 = P[v], lo1 = from->rep;
          if (k == span && to) hi0 = P[v], hi1 = to->rep;
          try_range(v, lo0, lo1, hi0, hi1);
        }
        if (!found) {
          edge.degenerate = true;
          const Event* e = from ? from : to;
          edge.pivot = e->vertex;
          edge.sample_from = P[e->vertex];
          edge.sample_to = e->rep;
        }
        cx.edges.push_back(edge);
        return static_cast<int>(cx.edges.size()) - 1;
      };
      // positions of events in the chain
      std::vector<std::size_t> pos;
      for (std::size_t k = 0; k < chain.size(); ++k)
        for (std::size_t j = 0; j < events[chain[k]].size(); ++j) pos.push_back(k);
      auto attach = [&](const Event* e, int edge_id, bool after) {
        ComplexVertex2D& cv = cx.vertices[e->bitangent];
        cv.edges[(e->at_a ? 0 : 2) + (after ? 1 : 0)] = edge_id;
      };
      if (seq.empty()) {
        make_edge(nullptr, nullptr, 0, 0, false);
        continue;
      }
      if (!closed) {
        attach(seq.front(), make_edge(nullptr, seq.front(), 0, pos.front(), false), false);
        attach(seq.back(), make_edge(seq.back(), nullptr, pos.back(), 0, false), true);
      }
      const std::size_t m = seq.size();
      for (std::size_t j = 0; j + 1 < m + (closed ? 1 : 0); ++j) {
        const Event* from = seq[j];
        const Event* to = seq[(j + 1) % m];
        const int id = make_edge(from, to, pos[j], pos[(j + 1) % m], j + 1 == m);  // closing edge wraps
        attach(from, id, true);
        attach(to, id, false);
      }
    }
  }
  // end objects of each edge's sample line, backwards and forwards: with the rotational method all rays
  // are answered by one more sweep, O((n + k + edges) log n); otherwise two exact O(n) ray shots per edge.
  if (method == VisibilityGraphMethod::RotationalSweep) {
    std::vector<Point2> backs(cx.edges.size());
    std::vector<RayQuery2D> queries;
    std::vector<std::size_t> asked;
    for (std::size_t j = 0; j < cx.edges.size(); ++j) {
      const ComplexEdge2D& edge = cx.edges[j];
      if (edge.degenerate) continue;
      backs[j] = Point2(edge.sample_from.x + edge.sample_from.x - edge.sample_to.x,
                        edge.sample_from.y + edge.sample_from.y - edge.sample_to.y);
      queries.push_back({edge.pivot, &edge.sample_from, &backs[j]});
      queries.push_back({edge.pivot, &edge.sample_from, &edge.sample_to});
      asked.push_back(j);
    }
    const std::vector<SegmentEnd2D> ends = rotational_first_contacts(s, queries);
    for (std::size_t i = 0; i < asked.size(); ++i)
      cx.edges[asked[i]].end_objects = {ends[2 * i].object, ends[2 * i + 1].object};
  } else {
    tbb::parallel_for(std::size_t(0), cx.edges.size(), [&](std::size_t j) {
      ComplexEdge2D& edge = cx.edges[j];
      if (edge.degenerate) return;
      const Point2 back(edge.sample_from.x + edge.sample_from.x - edge.sample_to.x,
                        edge.sample_from.y + edge.sample_from.y - edge.sample_to.y);
      edge.end_objects = {first_contact_feature(s, edge.pivot, edge.sample_from, back).object,
                          first_contact_feature(s, edge.pivot, edge.sample_from, edge.sample_to).object};
    });
  }
  // faces: union-find over vertex slots (6 each) and edge slots (3 each)
  UnionFind uf;
  std::vector<std::array<int, 6>> vslot(B.size());
  std::vector<std::array<int, 3>> eslot(cx.edges.size());
  for (auto& a : vslot) for (int& x : a) x = uf.add();
  for (auto& a : eslot) for (int& x : a) x = uf.add();
  enum { A_Oa, A_Ob, A_B, Oa_Ob, Oa_B, Ob_B };
  for (std::size_t i = 0; i < B.size(); ++i) {
    const Bitangent2D& b = B[i];
    ComplexVertex2D& cv = cx.vertices[i];
    for (int k = 0; k < 4; ++k)
      if (cv.edges[k] < 0) throw std::logic_error("visibility_complex: bitangent without 4 edges (bug)");
    for (int k = 0; k < 4; ++k) {
      const bool at_a = k < 2, after = k % 2 == 1;
      const ComplexEdge2D& e = cx.edges[cv.edges[k]];
      const auto& es = eslot[cv.edges[k]];
      // is the far endpoint ahead (+rep) of the pivot on this chain?
      const int v = at_a ? b.a : b.b, w = at_a ? b.b : b.a;
      const Event* ev = nullptr;
      for (const Event& x : events[v])
        if (x.bitangent == static_cast<int>(i) && x.at_a == at_a) ev = &x;
      const bool ahead = ev->rep == P[w];
      // rotating counterclockwise (after) moves the ray towards w to the left of v->w
      int s_to_w, s_pivot_far, s_near_far;  // vertex slots: (near, pivot), (pivot, toward-w end), (near, that end)
      if (at_a) {
        const bool hits = after ? (b.side_b == 'L') : (b.side_b == 'R');
        s_to_w = A_Oa;
        s_pivot_far = hits ? Oa_Ob : Oa_B;
        s_near_far = hits ? A_Ob : A_B;
      } else {
        // ray from b towards a; left of b->a is right of a->b
        const bool hits = after ? (b.side_a == 'R') : (b.side_a == 'L');
        s_to_w = Ob_B;
        s_pivot_far = hits ? Oa_Ob : A_Ob;
        s_near_far = hits ? Oa_B : A_B;
      }
      // edge slots: 0 = (back end, pivot), 1 = (pivot, front end), 2 = (back, front); w is front iff ahead
      uf.unite(es[ahead ? 0 : 1], vslot[i][s_to_w]);
      uf.unite(es[ahead ? 1 : 0], vslot[i][s_pivot_far]);
      uf.unite(es[2], vslot[i][s_near_far]);
      (void)e;
    }
  }
  // Each slot carries the (sorted) pair of objects at the ends of its segments: vertex slots from the
  // bitangent's line (A, Oa, Ob, B), edge slots from their sample segment. Glued slots must agree.
  std::vector<std::optional<std::array<int, 2>>> pair_of(uf.size());
  auto sorted = [](int x, int y) { return x < y ? std::array<int, 2>{x, y} : std::array<int, 2>{y, x}; };
  for (std::size_t i = 0; i < B.size(); ++i) {
    // an empty extension (the line continues along an edge of the endpoint) does not name the object
    // beyond: it is the object met by the nearby segments that miss the endpoint's object
    const bool empty_a = B[i].end_a.kind == SegmentEnd2D::Vertex && B[i].end_a.id == B[i].a;
    const bool empty_b = B[i].end_b.kind == SegmentEnd2D::Vertex && B[i].end_b.id == B[i].b;
    const int A = empty_a ? object_beyond_empty_extension(s, B[i].a, P[B[i].b], P[B[i].a]) : B[i].end_a.object;
    const int Bo = empty_b ? object_beyond_empty_extension(s, B[i].b, P[B[i].a], P[B[i].b]) : B[i].end_b.object;
    const int Oa = B[i].object_a, Ob = B[i].object_b;
    const std::array<std::array<int, 2>, 6> pairs{sorted(A, Oa), sorted(A, Ob), sorted(A, Bo),
                                                  sorted(Oa, Ob), sorted(Oa, Bo), sorted(Ob, Bo)};
    for (int k = 0; k < 6; ++k) pair_of[vslot[i][k]] = pairs[k];
  }
  for (std::size_t j = 0; j < cx.edges.size(); ++j) {
    const ComplexEdge2D& e = cx.edges[j];
    if (e.degenerate) continue;
    pair_of[eslot[j][0]] = sorted(e.end_objects[0], e.object);
    pair_of[eslot[j][1]] = sorted(e.object, e.end_objects[1]);
    pair_of[eslot[j][2]] = sorted(e.end_objects[0], e.end_objects[1]);
  }
  std::map<int, std::array<int, 2>> pair_of_root;
  cx.gluing_consistent = true;
  for (std::size_t x = 0; x < pair_of.size(); ++x) {
    if (!pair_of[x]) continue;
    const auto [it, fresh] = pair_of_root.emplace(uf.find(static_cast<int>(x)), *pair_of[x]);
    if (!fresh && it->second != *pair_of[x]) cx.gluing_consistent = false;
  }
  // faces: maximal free segments grouped by the pair of objects at their ends. Pairs come from the slots;
  // an object with a reflex vertex (holes included) also has short chords across that corner, {O, O}.
  std::map<std::array<int, 2>, int> face_of_pair;
  for (const auto& pr : pair_of)
    if (pr) face_of_pair.emplace(*pr, 0);
  for (int v = 0; v < n; ++v)
    if (turn[v] == Sign::Negative) face_of_pair.emplace(std::array<int, 2>{s.object_of(v), s.object_of(v)}, 0);
  for (auto& [pr, id] : face_of_pair) {
    id = static_cast<int>(cx.faces.size());
    cx.faces.push_back({pr});
  }
  auto face_id = [&](int slot) {
    if (pair_of[slot]) return face_of_pair.at(*pair_of[slot]);
    return face_of_pair.at(pair_of_root.at(uf.find(slot)));
  };
  for (std::size_t i = 0; i < B.size(); ++i)
    for (int k = 0; k < 6; ++k) cx.vertices[i].faces[k] = face_id(vslot[i][k]);
  for (std::size_t j = 0; j < cx.edges.size(); ++j)
    for (int k = 0; k < 3; ++k) cx.edges[j].faces[k] = face_id(eslot[j][k]);
  return cx;
}

}  // namespace exactvis
