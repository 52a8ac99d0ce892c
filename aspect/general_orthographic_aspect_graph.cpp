#include "aspect/general_orthographic_aspect_graph.hpp"

#include "aspect/aspect_regions.hpp"
#include "aspect/direction_aspect.hpp"
#include "aspect/direction_event_arcs.hpp"
#include "aspect/eee_arc_insertion.hpp"
#include "aspect/eee_crossing_point.hpp"
#include "aspect/eee_crossings.hpp"
#include "aspect/eee_face_split.hpp"
#include "aspect/great_circle_arrangement.hpp"
#include "kernel/predicates.hpp"
#include "kernel/rational_between.hpp"
#include "kernel/triangle_index.hpp"
#include "util/for_each_index.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace exactvis {
namespace {

using V3 = Vec3<Exact>;


// The representative of the line through n: n divided by its first non-zero component (so equal circles get
// equal keys whatever the scale or sign of their normals).
V3 circle_key(const V3& n) {
  for (int k = 0; k < 3; ++k)
    if (CGAL::sign(n[k]) != 0) {
      const Exact s = n[k];
      return {n.x / s, n.y / s, n.z / s};
    }
  return n;
}

bool same_direction(const V3& a, const V3& b) {
  const V3 c = cross(a, b);
  return CGAL::sign(c.x) == 0 && CGAL::sign(c.y) == 0 && CGAL::sign(c.z) == 0 && CGAL::sign(dot(a, b)) > 0;
}


// One free EV arc as the set {o (A - V + t (B - A)) : t in [t0, t1]} of directions, for membership tests.
struct EvArc {
  int index = 0;  // into DirectionEventArcs::arcs
  V3 av, ba, n;   // A - V, B - A, their cross product (the circle's normal)
  int o = 1;
  Exact t0, t1;
};

// Is direction s (on the arc's circle) in the closed arc? o s = alpha (A - V) + beta (B - A) with alpha > 0
// and beta / alpha in [t0, t1] (both coefficients exact, from the plane's cross products).
bool on_arc(const EvArc& a, const V3& s) {
  const V3 os = a.o > 0 ? s : -s;
  const Exact alpha = dot(cross(os, a.ba), a.n), beta = dot(cross(a.av, os), a.n);  // both times |n|^2 > 0
  if (CGAL::sign(alpha) <= 0) return false;
  const Exact t = beta / alpha;
  return !(t < a.t0) && !(a.t1 < t);
}

// A cell of the split partition.
struct Cell {
  int dimension = 0;
  V3 sample;
  std::vector<int> circles;  // circles holding it
  std::vector<int> facets;
  int neighbour_face = -1;   // a face in whose closure it lies (cell index)
  bool rational = true;      // false: an EEE cut point at an irrational position (no sample)
  std::vector<int> eee;      // the free EEE arcs holding it (indices into DirectionEventArcs::arcs)
};

// A free EEE arc lying on a great circle (its three edges parallel to one plane: the cone of 10.7 degenerates
// and the transversals' directions sweep a plane, the rulings of a hyperbolic paraboloid), handled like an EV
// arc: the closed arc of its circle from a = o f(t0) through m = o f(t_s) to b = o f(t1) (t rational).
struct CircleEeeArc {
  int index = 0;  // into DirectionEventArcs::arcs
  V3 n, a, m, b;  // n oriented so that m lies counter-clockwise between a and b
};

// The angle of x from a, counter-clockwise about n, compared: bucket 0 (x = a), 1 (below a half turn), 2 (the
// half turn), 3 (beyond), then by orientation.
int angle_bucket(const V3& n, const V3& a, const V3& x) {
  const int h = CGAL::sign(dot(n, cross(a, x)));
  if (h > 0) return 1;
  if (h < 0) return 3;
  return CGAL::sign(dot(a, x)) > 0 ? 0 : 2;
}
bool angle_less(const V3& n, const V3& a, const V3& x, const V3& y) {
  const int bx = angle_bucket(n, a, x), by = angle_bucket(n, a, y);
  if (bx != by) return bx < by;
  return (bx == 1 || bx == 3) && CGAL::sign(dot(n, cross(x, y))) > 0;
}
bool on_circle_eee(const CircleEeeArc& c, const V3& s) {
  if (CGAL::sign(dot(c.n, s)) != 0 || (CGAL::sign(s.x) == 0 && CGAL::sign(s.y) == 0 && CGAL::sign(s.z) == 0)) return false;
  return !angle_less(c.n, c.a, c.b, s);
}

char sign_char(int s) { return s > 0 ? '+' : (s < 0 ? '-' : '0'); }

}  // namespace

GeneralOrthographicResult general_orthographic_aspect_graph(const Scene& scene, void (*progress)(double),
                                                            bool with_cells) {
  GeneralOrthographicResult out;
  const DirectionEventArcs events = direction_event_arcs(scene);
  if (progress) progress(0.2);
  for (const auto& a : events.arcs) (a.type == DirectionEventArc::Type::EV ? out.ev_arcs : out.eee_arcs)++;
  // Circles: the coordinate ones, then each free EV arc's plane.
  std::map<std::array<Exact, 3>, int> circle_of;
  std::vector<V3> normals;
  const auto add_circle = [&](const V3& n) {
    const V3 k = circle_key(n);
    const auto [it, fresh] = circle_of.insert({{k.x, k.y, k.z}, static_cast<int>(normals.size())});
    if (fresh) normals.push_back(k);
    return it->second;
  };
  for (int k = 0; k < 3; ++k) {
    V3 n;
    n[k] = Exact(1);
    add_circle(n);
  }
  std::vector<std::vector<EvArc>> arcs_on(3);
  std::vector<std::pair<int, V3>> ends;  // (circle, direction) of every free arc end
  for (std::size_t i = 0; i < events.arcs.size(); ++i) {
    const auto& a = events.arcs[i];
    if (a.type != DirectionEventArc::Type::EV) continue;
    const V3 v = to_rational(scene.vertices[a.vertex]), p = to_rational(scene.vertices[a.edges[0][0]]),
             q = to_rational(scene.vertices[a.edges[0][1]]);
    EvArc e{static_cast<int>(i), p - v, q - p, cross(p - v, q - p), a.orientation, a.t0.a0(), a.t1.a0()};
    const int c = add_circle(e.n);
    if (static_cast<int>(arcs_on.size()) <= c) arcs_on.resize(c + 1);
    arcs_on[c].push_back(e);
    for (const Exact& t : {e.t0, e.t1}) ends.push_back({c, arc_direction(scene, a, t)});
  }
  // Free EEE arcs lying on a great circle: circles and ends like EV arcs.
  std::vector<char> eee_on_circle(events.arcs.size(), 0);
  std::vector<std::vector<CircleEeeArc>> ceee_on(normals.size());
  for (std::size_t i = 0; i < events.arcs.size(); ++i) {
    const auto& a = events.arcs[i];
    if (a.type != DirectionEventArc::Type::EEE) continue;
    const V3 d0 = arc_direction(scene, a, Exact(0)), d1 = arc_direction(scene, a, Exact(1)),
             d2 = arc_direction(scene, a, Exact(2));
    const V3 c2 = Exact(1, 2) * (d2 - Exact(2) * d1 + d0), c1 = d1 - d0 - c2;
    V3 n = cross(d0, c1);
    if (n == V3()) n = cross(d0, c2);
    if (n == V3()) n = cross(c1, c2);
    if (n == V3() || CGAL::sign(dot(n, d0)) != 0 || CGAL::sign(dot(n, c1)) != 0 || CGAL::sign(dot(n, c2)) != 0) continue;
    Exact t0, t1;
    if (!root_number_rational(a.t0, &t0) || !root_number_rational(a.t1, &t1)) continue;  // refused later
    const V3 da = arc_direction(scene, a, t0), db = arc_direction(scene, a, t1),
             dm = arc_direction(scene, a, a.sample_t);
    if (da == V3() || db == V3() || dm == V3()) continue;
    eee_on_circle[i] = 1;
    const int c = add_circle(n);
    if (static_cast<int>(ceee_on.size()) <= c) ceee_on.resize(c + 1);
    CircleEeeArc ce{static_cast<int>(i), normals[c], da, dm, db};
    if (angle_less(ce.n, ce.a, ce.b, ce.m)) ce.n = -ce.n;
    ceee_on[c].push_back(ce);
    for (const V3& d : {da, db}) ends.push_back({c, d});
  }
  ceee_on.resize(normals.size());
  if (arcs_on.size() < normals.size()) arcs_on.resize(normals.size());
  out.circles = normals.size();
  const GreatCircleArrangement arr = great_circle_arrangement(normals);
  const int V = static_cast<int>(arr.vertices.size()), E = static_cast<int>(arr.arcs.size()),
            F = static_cast<int>(arr.faces.size());

  // The free EEE arcs cut at the circles (aspect/eee_arc_insertion), when there are any.
  EeeArcInsertion ins;
  EeeCrossings xs;
  if (out.eee_arcs > 0) {
    ins = insert_eee_arcs(scene, events, arr, normals, eee_on_circle);
    if (!ins.ok) {
      out.problem = std::to_string(out.eee_arcs) + " free EEE event arcs bound its aspects, and " + ins.problem;
      return out;
    }
    xs = find_eee_crossings(scene, events, arr, ins);
    if (!xs.ok) {
      out.problem = std::to_string(out.eee_arcs) + " free EEE event arcs bound its aspects, and " + xs.problem;
      return out;
    }
  }
  // Split points: the arc ends strictly inside an arc of the arrangement (an end on two circles is a vertex),
  // and the EEE arcs' cut points inside arcs; each at its position (1 - lambda) from + lambda to.
  struct Split {
    RootNumber lambda;
    bool rational = true;
    V3 d;                        // when rational
    std::vector<int> eee_points;  // indices into ins.points
  };
  std::vector<std::vector<int>> arcs_of_circle(normals.size());
  for (int a = 0; a < E; ++a) arcs_of_circle[arr.arcs[a].circle].push_back(a);
  std::vector<std::vector<Split>> splits(E);
  auto lambda_of = [&](int a, const V3& d) {
    const V3 &from = arr.vertices[arr.arcs[a].from], &to = arr.vertices[arr.arcs[a].to];
    const V3 c = cross(from, to);
    const Exact al = dot(c, cross(d, to)), be = dot(c, cross(from, d));
    return RootNumber(be / (al + be));
  };
  for (const auto& [c, d] : ends)
    for (int a : arcs_of_circle[c]) {
      const V3 &from = arr.vertices[arr.arcs[a].from], &to = arr.vertices[arr.arcs[a].to];
      const V3& n = normals[c];
      if (CGAL::sign(dot(n, cross(from, d))) > 0 && CGAL::sign(dot(n, cross(d, to))) > 0) {
        bool known = false;
        for (const Split& s : splits[a]) known |= same_direction(s.d, d);
        if (!known) splits[a].push_back({lambda_of(a, d), true, d, {}});
        break;
      }
    }
  for (std::size_t i = 0; i < ins.points.size(); ++i) {
    const EeeArcPoint& p = ins.points[i];
    if (p.gc_arc < 0) continue;
    bool known = false;
    for (Split& s : splits[p.gc_arc])
      if (s.lambda == p.lambda) {
        s.eee_points.push_back(static_cast<int>(i));
        known = true;
      }
    if (!known) splits[p.gc_arc].push_back({p.lambda, p.rational, p.direction, {static_cast<int>(i)}});
  }
  // Cells: vertices (arrangement, then split points), pieces of arcs, EEE cells, faces.
  std::vector<Cell> cells;
  std::vector<int> point_cell(ins.points.size(), -1);
  for (int v = 0; v < V; ++v) cells.push_back({0, arr.vertices[v], arr.vertex_circles[v], {}, -1, true, {}});
  for (std::size_t i = 0; i < ins.points.size(); ++i)
    if (ins.points[i].gc_vertex >= 0) {
      point_cell[i] = ins.points[i].gc_vertex;
      cells[ins.points[i].gc_vertex].eee.push_back(ins.points[i].arc);
    }
  std::vector<std::vector<int>> pieces_of_arc(E), chain_of_arc(E);
  for (int a = 0; a < E; ++a) {
    const auto& arc = arr.arcs[a];
    auto& sp = splits[a];
    std::sort(sp.begin(), sp.end(), [](const Split& p, const Split& q) { return p.lambda < q.lambda; });
    std::vector<int> chain{arc.from};
    std::vector<RootNumber> lambdas{RootNumber(0)};
    for (const Split& s : sp) {
      chain.push_back(static_cast<int>(cells.size()));
      lambdas.push_back(s.lambda);
      Cell c{0, s.rational ? scaled_to_unit_max(s.d) : V3(), {arc.circle}, {}, -1, s.rational, {}};
      for (int i : s.eee_points) {
        point_cell[i] = chain.back();
        c.eee.push_back(ins.points[i].arc);
      }
      cells.push_back(std::move(c));
    }
    chain.push_back(arc.to);
    lambdas.push_back(RootNumber(1));
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      V3 sample;
      if (sp.empty()) sample = arc_sample(arr, normals, a);
      else if (cells[chain[k]].rational && cells[chain[k + 1]].rational)
        sample = scaled_to_unit_max(cells[chain[k]].sample + cells[chain[k + 1]].sample);
      else {
        const Exact l = rational_strictly_between(lambdas[k], lambdas[k + 1]);
        sample = scaled_to_unit_max((Exact(1) - l) * arr.vertices[arc.from] + l * arr.vertices[arc.to]);
      }
      pieces_of_arc[a].push_back(static_cast<int>(cells.size()));
      chain_of_arc[a].push_back(chain[k]);
      chain_of_arc[a].push_back(static_cast<int>(cells.size()));
      cells.push_back({1, sample, {arc.circle}, {chain[k], chain[k + 1]}, -1, true, {}});
    }
    chain_of_arc[a].push_back(arc.to);
  }
  // EEE arc ends inside faces, then the sub-arcs.
  for (std::size_t i = 0; i < ins.points.size(); ++i)
    if (ins.points[i].circle < 0) {
      point_cell[i] = static_cast<int>(cells.size());
      cells.push_back({0, ins.points[i].direction, {}, {}, -1, true, {ins.points[i].arc}});
    }
  // Crossings of two free EEE arcs (cells of their own, no rational sample), then each sub-arc's segments
  // between its cut points and crossings (docs/theory.md 10.11, "EEE x EEE crossings").
  std::vector<int> crossing_cell(xs.crossings.size());
  for (std::size_t x = 0; x < xs.crossings.size(); ++x) {
    crossing_cell[x] = static_cast<int>(cells.size());
    const auto& cx = xs.crossings[x];
    cells.push_back({0, V3(), {}, {}, -1, false, {ins.subarcs[cx.subarc[0]].arc, ins.subarcs[cx.subarc[1]].arc}});
  }
  std::vector<EeeFaceSegment> segments;
  std::vector<std::vector<int>> segments_of_subarc(ins.subarcs.size());
  for (std::size_t i = 0; i < ins.subarcs.size(); ++i) {
    const EeeSubArc& s = ins.subarcs[i];
    const auto& on = xs.of_subarc.empty() ? std::vector<std::array<int, 2>>{} : xs.of_subarc[i];
    std::vector<int> nodes{point_cell[s.first]};
    for (const auto& [x, side] : on) nodes.push_back(crossing_cell[x]);
    nodes.push_back(point_cell[s.second]);
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
      Exact t = s.t;
      if (!on.empty()) {
        const RootNumber lo = k == 0 ? ins.points[s.first].t : RootNumber(xs.crossings[on[k - 1][0]].t[on[k - 1][1]].hi);
        const RootNumber hi = k + 1 == on.size() + 1 ? ins.points[s.second].t : RootNumber(xs.crossings[on[k][0]].t[on[k][1]].lo);
        t = rational_strictly_between(lo, hi);
      }
      const V3 sample = on.empty() ? s.sample : scaled_to_unit_max(arc_direction(scene, events.arcs[s.arc], t));
      segments_of_subarc[i].push_back(static_cast<int>(segments.size()));
      segments.push_back({static_cast<int>(i), static_cast<int>(cells.size()), nodes[k], nodes[k + 1], t});
      cells.push_back({1, sample, {}, {nodes[k], nodes[k + 1]}, -1, true, {s.arc}});
    }
  }
  const int first_face = static_cast<int>(cells.size());
  for (int f = 0; f < F; ++f) {
    if (ins.subarcs_of_face.empty() || ins.subarcs_of_face[f].empty()) {
      Cell c{2, face_sample(arr, f), {}, {}, -1, true, {}};
      for (int h : arr.faces[f].halfedges)
        for (int p : pieces_of_arc[h / 2]) c.facets.push_back(p);
      cells.push_back(std::move(c));
      continue;
    }
    std::vector<int> ring;  // boundary cells in order: vertex, piece, vertex, ...
    for (int h : arr.faces[f].halfedges) {
      const auto& ch = chain_of_arc[h / 2];
      if (h % 2 == 0) ring.insert(ring.end(), ch.begin(), ch.end() - 1);
      else ring.insert(ring.end(), ch.rbegin(), ch.rend() - 1);
    }
    std::vector<V3> ring_samples;
    for (int c : ring) ring_samples.push_back(cells[c].sample);
    const EeeFaceSplit split = split_eee_face(scene, events, arr, normals, ins, xs, f, ring, ring_samples, segments,
                                              segments_of_subarc, point_cell, crossing_cell);
    if (!split.problem.empty()) {
      out.problem = std::to_string(out.eee_arcs) + " free EEE event arcs bound its aspects, and " + split.problem;
      return out;
    }
    for (const EeeFaceComponent& k : split.components) cells.push_back({2, k.sample, {}, k.facets, -1, true, {}});
  }
  for (int f = first_face; f < static_cast<int>(cells.size()); ++f)
    for (int p : cells[f].facets) {
      if (cells[p].neighbour_face < 0) cells[p].neighbour_face = f;
      for (int v : cells[p].facets)
        if (cells[v].neighbour_face < 0) cells[v].neighbour_face = f;
    }
  const int nc = static_cast<int>(cells.size());

  // Which cells to evaluate: every cell with a rational sample (faces and lower cells alike). A triangle seen
  // edge-on from the blocked part of its plane's circle leaves the aspect there although no free arc holds it
  // (docs/theory.md 10.11), so a lower cell's aspect is not always a neighbouring face's.
  std::vector<char> evaluate(nc, 0);
  for (int c = 0; c < nc; ++c) evaluate[c] = cells[c].dimension == 2 || cells[c].rational;
  // An irrational cut point of an EEE arc (on one circle, strictly inside an arrangement arc) takes the aspect
  // of the EEE sub-arc through it, unless a free arc of its circle holds it too (a crossing of two free arcs):
  // then the intersection of the aspects of the circle's two pieces next to it, when the EEE line there meets
  // no fourth edge (docs/theory.md 10.11, "Irrational crossings"; else refused).
  std::vector<std::vector<int>> meet_of(nc);  // per irrational crossing: the two circle pieces next to it
  std::vector<int> crossing_point(nc, -1);     // and its cut point (index into ins.points)
  for (int c = 0; c < nc; ++c) {
    if (cells[c].rational) continue;
    for (int k : cells[c].circles) {
      if (k >= static_cast<int>(arcs_on.size())) continue;
      std::vector<int> next;
      bool on_free = false;
      for (int p = 0; p < nc; ++p)
        if (cells[p].dimension == 1 && !cells[p].circles.empty() && cells[p].circles[0] == k &&
            std::count(cells[p].facets.begin(), cells[p].facets.end(), c)) {
          next.push_back(p);
          on_free |= std::any_of(arcs_on[k].begin(), arcs_on[k].end(), [&](const EvArc& e) { return on_arc(e, cells[p].sample); }) ||
                     std::any_of(ceee_on[k].begin(), ceee_on[k].end(), [&](const CircleEeeArc& e) { return on_circle_eee(e, cells[p].sample); });
        }
      if (!on_free) continue;
      std::string why = next.size() == 2 ? std::string() : std::string("an irrational crossing is no interior point of one arc");
      for (std::size_t i = 0; i < ins.points.size() && why.empty(); ++i)
        if (point_cell[i] == c) {
          why = eee_line_meets_only_its_edges(scene, events.arcs[ins.points[i].arc], ins.points[i].t);
          crossing_point[c] = static_cast<int>(i);
        }
      if (!why.empty()) {
        out.problem = std::to_string(out.eee_arcs) + " free EEE event arcs bound its aspects, and " + why +
                      ", outside the subset the orthographic aspect graph handles (docs/theory.md 10.11)";
        return out;
      }
      meet_of[c] = next;
    }
  }
  std::vector<int> copy_from(nc, -1);
  for (int c = 0; c < nc; ++c)
    if (cells[c].dimension == 1 && cells[c].circles.empty())
      for (int v : cells[c].facets)
        if (!cells[v].rational && copy_from[v] < 0) copy_from[v] = c;
  if (progress) progress(0.3);
  const TriangleIndex index(scene);
  std::vector<std::vector<std::int64_t>> aspect(nc);
  std::vector<int> todo;
  for (int c = 0; c < nc; ++c)
    if (evaluate[c]) todo.push_back(c);
  out.evaluated_cells = todo.size();
  for_each_index(todo.size(), true, 4, [&](std::size_t i) {
    aspect[todo[i]] = direction_aspect(scene, cells[todo[i]].sample, &index).aspect;
  });
  if (progress) progress(0.9);
  for (int c = 0; c < nc; ++c)
    if (meet_of[c].size() == 2) {
      const auto &x = aspect[meet_of[c][0]], &y = aspect[meet_of[c][1]];
      aspect[c].clear();
      std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(aspect[c]));
      const EeeArcPoint& pt = ins.points[crossing_point[c]];
      out.irrational_crossings.push_back({eee_direction_approx(scene, events.arcs[pt.arc], pt.t), aspect[c]});
    }
  // A crossing of two free EEE arcs: the intersection of the aspects of the two segments of either arc next to
  // it (docs/theory.md 10.11, "EEE x EEE crossings"; the two arcs must give the same set).
  std::vector<char> fixed(nc, 0);
  for (std::size_t x = 0; x < xs.crossings.size(); ++x) {
    const int c = crossing_cell[x];
    std::array<std::vector<std::int64_t>, 2> meet;
    for (int side = 0; side < 2; ++side) {
      std::vector<int> next;
      for (int g : segments_of_subarc[xs.crossings[x].subarc[side]])
        if (segments[g].from == c || segments[g].to == c) next.push_back(segments[g].cell);
      if (next.size() != 2) throw std::logic_error("general_orthographic_aspect_graph: a crossing without two segments");
      const auto &a = aspect[next[0]], &b = aspect[next[1]];
      std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(meet[side]));
    }
    if (meet[0] != meet[1]) {
      out.problem = std::to_string(out.eee_arcs) +
                    " free EEE event arcs bound its aspects, and the two free EEE arcs through a crossing give it different "
                    "aspects, outside the subset the orthographic aspect graph handles (docs/theory.md 10.11)";
      return out;
    }
    aspect[c] = meet[0];
    fixed[c] = 1;
    out.eee_crossings.push_back({xs.crossings[x].direction, aspect[c]});
  }
  std::map<std::vector<std::int64_t>, int> aspect_id;
  std::vector<AspectCell> acells(nc);
  for (int c = 0; c < nc; ++c) {
    const int src = evaluate[c] ? c : (copy_from[c] >= 0 ? copy_from[c] : cells[c].neighbour_face);
    if (!evaluate[c] && meet_of[c].empty() && !fixed[c]) aspect[c] = aspect[src];
    acells[c].dimension = cells[c].dimension;
    acells[c].aspect = aspect_id.insert({aspect[c], static_cast<int>(aspect_id.size())}).first->second;
    acells[c].facets = cells[c].facets;
  }
  const AspectRegions regions = aspect_regions(acells, std::vector<bool>(nc, true));

  AspectGraph3& g = out.graph;
  g.view = ViewModel::Orthographic;
  g.circles = normals;
  for (int c = 0; c < nc; ++c) ++g.cells[cells[c].dimension];
  if (with_cells)
    for (int c = 0; c < nc; ++c) {
      if (!cells[c].rational) continue;  // no exact rational sample (its aspect is its EEE sub-arc's)
      std::string signs(normals.size(), '0');
      for (std::size_t k = 0; k < normals.size(); ++k) signs[k] = sign_char(CGAL::sign(dot(normals[k], cells[c].sample)));
      g.sampled_cells.push_back({regions.region_of[c], cells[c].dimension, cells[c].sample, std::move(signs)});
    }
  for (std::size_t r = 0; r < regions.members.size(); ++r)
    if (!cells[region_sample_cell(regions, r, cells)].rational) {
      out.problem = std::to_string(out.eee_arcs) +
                    " free EEE event arcs bound its aspects, and an irrational crossing of two free arcs is a region of its "
                    "own (no rational sample), outside the subset the orthographic aspect graph handles (docs/theory.md 10.11)";
      return out;
    }
  for (std::size_t r = 0; r < regions.members.size(); ++r) {
    const int best = region_sample_cell(regions, r, cells);
    g.regions.push_back({regions.dimension[r], aspect[best], cells[best].sample});
  }
  // Events of an adjacency: per circle holding the lower cell, one free EV arc through it (its aspect differs
  // from the upper cell's only on free arcs), preferring a generator on a triangle whose visibility differs,
  // each with the triangles whose visibility differs between the two regions. (Many coplanar families share a
  // circle, e.g. a face plane of several bodies: one name per circle keeps the JSON small.)
  std::map<std::int64_t, int> index_of_id;
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) index_of_id[scene.triangles[i].id] = static_cast<int>(i);
  for (const auto& adj : regions.adjacency) {
    AspectAdjacency3 a;
    a.a = adj.a;
    a.b = adj.b;
    const auto& la = aspect[adj.lower];
    const auto& ua = aspect[adj.upper];
    std::vector<std::int64_t> diff;
    std::set_symmetric_difference(la.begin(), la.end(), ua.begin(), ua.end(), std::back_inserter(diff));
    std::set<int> diff_vertices;
    for (std::int64_t id : diff)
      for (int v : scene.triangles[index_of_id[id]].v) diff_vertices.insert(v);
    // An irrational crossing has no sample: its circle's free arcs are those of the pieces next to it.
    const V3& probe = meet_of[adj.lower].empty() ? cells[adj.lower].sample : cells[meet_of[adj.lower][0]].sample;
    for (int k : cells[adj.lower].circles) {
      const DirectionEventArc* pick = nullptr;
      for (const EvArc& e : arcs_on[k]) {
        const auto& arc = events.arcs[e.index];
        if (!on_arc(e, probe)) continue;
        const bool on_diff = diff_vertices.count(arc.vertex) && diff_vertices.count(arc.edges[0][0]) &&
                             diff_vertices.count(arc.edges[0][1]);
        if (!pick || (on_diff && !(diff_vertices.count(pick->vertex) && diff_vertices.count(pick->edges[0][0]) &&
                                   diff_vertices.count(pick->edges[0][1]))))
          pick = &arc;
      }
      if (!pick) {
        // No free arc holds it: a triangle of the difference seen edge-on, its plane the circle's, named as a
        // face circle (first vertex, opposite edge).
        for (std::int64_t id : diff) {
          const auto& t = scene.triangles[index_of_id[id]];
          const V3 p0 = to_rational(scene.corner(t, 0));
          const V3 n = cross(to_rational(scene.corner(t, 1)) - p0, to_rational(scene.corner(t, 2)) - p0);
          if (!(circle_key(n) == normals[k])) continue;
          AspectEvent3 ev;
          ev.vertex = t.v[0];
          ev.edge = {std::min(t.v[1], t.v[2]), std::max(t.v[1], t.v[2])};
          ev.triangles = diff;
          a.events.push_back(std::move(ev));
          break;
        }
        continue;
      }
      AspectEvent3 ev;
      ev.vertex = pick->vertex;
      ev.edge = pick->edges[0];
      ev.triangles = diff;
      a.events.push_back(std::move(ev));
    }
    for (int k : cells[adj.lower].circles)
      for (const CircleEeeArc& ce : ceee_on[k])
        if (cells[adj.lower].rational && on_circle_eee(ce, cells[adj.lower].sample)) {
          AspectEvent3 ev;
          ev.type = "EEE";
          ev.edges = events.arcs[ce.index].edges;
          ev.triangles = diff;
          a.events.push_back(std::move(ev));
          break;
        }
    for (int e : cells[adj.lower].eee) {
      AspectEvent3 ev;
      ev.type = "EEE";
      ev.edges = events.arcs[e].edges;
      ev.triangles = diff;
      a.events.push_back(std::move(ev));
    }
    g.adjacency.push_back(std::move(a));
  }
  if (progress) progress(1);
  out.ok = true;
  return out;
}

}  // namespace exactvis
