#include "aspect/general_orthographic_aspect_graph.hpp"

#include "aspect/aspect_regions.hpp"
#include "aspect/direction_aspect.hpp"
#include "aspect/direction_event_arcs.hpp"
#include "aspect/great_circle_arrangement.hpp"
#include "kernel/triangle_index.hpp"
#include "util/for_each_index.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace exactvis {
namespace {

using V3 = Vec3<Exact>;

V3 ep(const Point3& p) { return {Exact(p.x), Exact(p.y), Exact(p.z)}; }

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

// Scaled so that the largest |component| is 1 (the output convention of AspectRegion3::sample).
V3 unit_max(const V3& v) {
  Exact m = CGAL::abs(v.x);
  if (CGAL::abs(v.y) > m) m = CGAL::abs(v.y);
  if (CGAL::abs(v.z) > m) m = CGAL::abs(v.z);
  return {v.x / m, v.y / m, v.z / m};
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

char sign_char(int s) { return s > 0 ? '+' : (s < 0 ? '-' : '0'); }

}  // namespace

GeneralOrthographicResult general_orthographic_aspect_graph(const Scene& scene, void (*progress)(double),
                                                            bool with_cells) {
  GeneralOrthographicResult out;
  const DirectionEventArcs events = direction_event_arcs(scene);
  if (progress) progress(0.2);
  for (const auto& a : events.arcs) (a.type == DirectionEventArc::Type::EV ? out.ev_arcs : out.eee_arcs)++;
  if (out.eee_arcs > 0) {
    // Name the first one's generators (EV arcs come first), so that a user can see which edges cause it.
    const auto& first = events.arcs[out.ev_arcs];
    std::string edges;
    for (int k = 0; k < 3; ++k)
      edges += std::string(k == 0 ? "" : (k == 1 ? ", " : " and ")) + std::to_string(first.edges[k][0]) + "-" +
               std::to_string(first.edges[k][1]);
    out.problem = std::to_string(out.eee_arcs) +
                  " free EEE event arcs (conics on the viewing sphere; the first of lines meeting the edges " + edges +
                  ", by vertex index) bound its aspects, and the orthographic aspect graph with EEE arcs is not "
                  "implemented yet";
    return out;
  }
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
    const V3 v = ep(scene.vertices[a.vertex]), p = ep(scene.vertices[a.edges[0][0]]),
             q = ep(scene.vertices[a.edges[0][1]]);
    EvArc e{static_cast<int>(i), p - v, q - p, cross(p - v, q - p), a.orientation, a.t0.a0(), a.t1.a0()};
    const int c = add_circle(e.n);
    if (static_cast<int>(arcs_on.size()) <= c) arcs_on.resize(c + 1);
    arcs_on[c].push_back(e);
    for (const Exact& t : {e.t0, e.t1}) ends.push_back({c, arc_direction(scene, a, t)});
  }
  out.circles = normals.size();
  const GreatCircleArrangement arr = great_circle_arrangement(normals);
  const int V = static_cast<int>(arr.vertices.size()), E = static_cast<int>(arr.arcs.size()),
            F = static_cast<int>(arr.faces.size());

  // Split points: the arc ends strictly inside an arc of the arrangement (an end on two circles is a vertex).
  std::vector<std::vector<int>> arcs_of_circle(normals.size());
  for (int a = 0; a < E; ++a) arcs_of_circle[arr.arcs[a].circle].push_back(a);
  std::vector<std::vector<V3>> splits(E);
  for (const auto& [c, d] : ends)
    for (int a : arcs_of_circle[c]) {
      const V3 &from = arr.vertices[arr.arcs[a].from], &to = arr.vertices[arr.arcs[a].to];
      const V3& n = normals[c];
      if (CGAL::sign(dot(n, cross(from, d))) > 0 && CGAL::sign(dot(n, cross(d, to))) > 0) {
        bool known = false;
        for (const V3& s : splits[a]) known |= same_direction(s, d);
        if (!known) splits[a].push_back(d);
        break;
      }
    }
  // Cells: vertices (arrangement, then split points), pieces of arcs, faces.
  struct Cell {
    int dimension = 0;
    V3 sample;
    std::vector<int> circles;  // circles holding it
    std::vector<int> facets;
    int neighbour_face = -1;   // a face in whose closure it lies (cell index)
  };
  std::vector<Cell> cells;
  for (int v = 0; v < V; ++v) cells.push_back({0, arr.vertices[v], arr.vertex_circles[v], {}, -1});
  std::vector<std::vector<int>> pieces_of_arc(E);
  for (int a = 0; a < E; ++a) {
    const auto& arc = arr.arcs[a];
    const V3& n = normals[arc.circle];
    auto& sp = splits[a];
    // Along the arc (<= a half circle) from `from`: p before q iff n . (p x q) > 0.
    std::sort(sp.begin(), sp.end(), [&](const V3& p, const V3& q) { return CGAL::sign(dot(n, cross(p, q))) > 0; });
    std::vector<int> chain{arc.from};
    for (const V3& s : sp) {
      chain.push_back(static_cast<int>(cells.size()));
      cells.push_back({0, unit_max(s), {arc.circle}, {}, -1});
    }
    chain.push_back(arc.to);
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      const V3 sample = sp.empty() ? arc_sample(arr, normals, a) : unit_max(cells[chain[k]].sample + cells[chain[k + 1]].sample);
      pieces_of_arc[a].push_back(static_cast<int>(cells.size()));
      cells.push_back({1, sample, {arc.circle}, {chain[k], chain[k + 1]}, -1});
    }
  }
  const int first_face = static_cast<int>(cells.size());
  for (int f = 0; f < F; ++f) {
    Cell c{2, face_sample(arr, f), {}, {}, -1};
    for (int h : arr.faces[f].halfedges)
      for (int p : pieces_of_arc[h / 2]) c.facets.push_back(p);
    cells.push_back(std::move(c));
  }
  for (int f = 0; f < F; ++f)
    for (int p : cells[first_face + f].facets) {
      if (cells[p].neighbour_face < 0) cells[p].neighbour_face = first_face + f;
      for (int v : cells[p].facets)
        if (cells[v].neighbour_face < 0) cells[v].neighbour_face = first_face + f;
    }
  const int nc = static_cast<int>(cells.size());

  // Which cells to evaluate: faces, and the lower cells on a free arc's closure.
  std::vector<char> evaluate(nc, 0);
  for (int c = 0; c < nc; ++c) {
    if (cells[c].dimension == 2) {
      evaluate[c] = 1;
      continue;
    }
    for (int k : cells[c].circles)
      if (k < static_cast<int>(arcs_on.size()))
        for (const EvArc& a : arcs_on[k])
          if (on_arc(a, cells[c].sample)) evaluate[c] = 1;
  }
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
  std::map<std::vector<std::int64_t>, int> aspect_id;
  std::vector<AspectCell> acells(nc);
  for (int c = 0; c < nc; ++c) {
    const int src = evaluate[c] ? c : cells[c].neighbour_face;
    if (!evaluate[c]) aspect[c] = aspect[src];
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
      std::string signs(normals.size(), '0');
      for (std::size_t k = 0; k < normals.size(); ++k) signs[k] = sign_char(CGAL::sign(dot(normals[k], cells[c].sample)));
      g.sampled_cells.push_back({regions.region_of[c], cells[c].dimension, cells[c].sample, std::move(signs)});
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
    for (int k : cells[adj.lower].circles) {
      if (k >= static_cast<int>(arcs_on.size())) continue;
      const DirectionEventArc* pick = nullptr;
      for (const EvArc& e : arcs_on[k]) {
        const auto& arc = events.arcs[e.index];
        if (!on_arc(e, cells[adj.lower].sample)) continue;
        const bool on_diff = diff_vertices.count(arc.vertex) && diff_vertices.count(arc.edges[0][0]) &&
                             diff_vertices.count(arc.edges[0][1]);
        if (!pick || (on_diff && !(diff_vertices.count(pick->vertex) && diff_vertices.count(pick->edges[0][0]) &&
                                   diff_vertices.count(pick->edges[0][1]))))
          pick = &arc;
      }
      if (!pick) continue;
      AspectEvent3 ev;
      ev.vertex = pick->vertex;
      ev.edge = pick->edges[0];
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
