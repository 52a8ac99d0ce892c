#include "aspect/orthographic_aspect_graph.hpp"

#include "aspect/aspect_regions.hpp"
#include "aspect/plane_arrangement_3.hpp"
#include "kernel/predicates.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <stdexcept>
#include <unordered_map>

namespace exactvis {

namespace {

using ExactKey = std::array<Exact, 3>;

// The EV generator naming a circle for one triangle: a vertex and an edge (scene vertex ids) whose lines
// sweep the plane, and the triangle whose visibility the circle bounds.
struct Generator {
  int triangle = 0;  // index into scene.triangles
  int vertex = -1;
  std::array<int, 2> edge{-1, -1};
};

// A corner's cone K_a: d is in K_a iff no constraint sees its forbidden sign.
struct Constraint {
  int plane = 0;
  char forbidden = '+';
};

struct Circles {
  std::map<ExactKey, int> index;
  std::vector<Vec3<Exact>> normals;  // canonical: the first largest-|.| component is +1
  std::vector<std::vector<Generator>> generators;
  // Plane id of v . d = 0 and the sign of v against the canonical normal (v . d = o * |v_a| * (c . d)).
  std::pair<int, int> add(const Vec3<Exact>& v) {
    int a = 0;
    for (int i = 1; i < 3; ++i)
      if (CGAL::abs(v[i]) > CGAL::abs(v[a])) a = i;
    const Exact s = v[a];
    const Vec3<Exact> c{v.x / s, v.y / s, v.z / s};
    auto [it, fresh] = index.emplace(ExactKey{c.x, c.y, c.z}, static_cast<int>(normals.size()));
    if (fresh) normals.push_back(c), generators.emplace_back();
    return {it->second, CGAL::sign(s) > 0 ? 1 : -1};
  }
};

struct Edge {
  int a, b;
};

// The sign chars of a cell that mean "v . d has sign s" for v = o * canonical.
char char_of(int s, int o) { return s * o > 0 ? '+' : '-'; }

struct Setup {
  Circles circles;
  std::vector<std::pair<int, char>> front_face;             // per triangle: plane, the char of "outer side"
  std::vector<bool> has_front;                              // per triangle: P_t non-empty
  // Per triangle: t is hidden from a d on its outer side iff d is in the cone K = the intersection of its
  // corners' cones K_a (corners in P_t excluded: their line always meets P_t), i.e. iff no constraint of
  // `hidden_cone` sees its forbidden sign; `always_hidden`: every corner lies in P_t; `never_hidden`: K = {0}.
  std::vector<std::vector<Constraint>> hidden_cone;
  std::vector<bool> always_hidden, never_hidden;
};

// A supporting plane through a corner a of t: d in K_a needs sign(normal . d) in {side, 0}.
struct RawConstraint {
  Vec3<Exact> normal;
  int side = 0;
  int corner = 0;
  std::size_t u = 0, w = 0;  // the two points of V_t spanning it with a
};

// The constraints that hold a facet of K = {d : sign(c.normal . d) in {c.side, 0} for all c} (those whose
// plane contains an extreme ray of K: K is their intersection, the rest are redundant), all of them when K
// has no extreme ray but is not {0} (a line or more of lineality), none when K = {0} (returns true then).
// Extreme rays are among +-(n_i x n_j). Cost O(C^3) exact signs for C constraints.
bool prune_to_facets(std::vector<RawConstraint>& cs) {
  const auto inside = [&](const Vec3<Exact>& d) {
    for (const auto& c : cs)
      if (CGAL::sign(dot(c.normal, d)) == -c.side) return false;
    return true;
  };
  std::vector<Vec3<Exact>> rays;
  bool independent_pair = false;
  for (std::size_t i = 0; i < cs.size(); ++i)
    for (std::size_t j = i + 1; j < cs.size(); ++j) {
      const Vec3<Exact> r = cross(cs[i].normal, cs[j].normal);
      if (r.x == 0 && r.y == 0 && r.z == 0) continue;
      independent_pair = true;
      if (inside(r)) rays.push_back(r);
      if (inside(-r)) rays.push_back(-r);
    }
  if (!independent_pair) return false;  // one plane (a half-space or the plane itself): keep all
  if (rays.empty()) return cs.clear(), true;
  std::vector<RawConstraint> kept;
  for (const auto& c : cs)
    if (std::any_of(rays.begin(), rays.end(), [&](const Vec3<Exact>& r) { return dot(c.normal, r) == 0; }))
      kept.push_back(c);
  cs = std::move(kept);
  return false;
}

// Is a in conv(P)? (P spans 3D.) Exactly: a is on the inner closed side of every plane through three points
// of P that has all of P on one closed side (those planes include the facets). Cost O(|P|^4), |P| small.
bool in_hull(const Vec3<Exact>& a, const std::vector<Vec3<Exact>>& P) {
  const std::size_t m = P.size();
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j)
      for (std::size_t k = j + 1; k < m; ++k) {
        const Vec3<Exact> nv = cross(P[j] - P[i], P[k] - P[i]);
        if (nv.x == 0 && nv.y == 0 && nv.z == 0) continue;
        int side = 0;
        bool supporting = true;
        for (const auto& p : P) {
          const int sp = CGAL::sign(dot(nv, p - P[i]));
          if (sp == 0) continue;
          if (side == 0) side = sp;
          else if (sp != side) { supporting = false; break; }
        }
        if (supporting && side != 0 && CGAL::sign(dot(nv, a - P[i])) == -side) return false;
      }
  return true;
}

Setup setup(const Scene& scene, const ClosedSolidFronts& fronts) {
  if (!fronts.ok) throw std::invalid_argument("orthographic_aspect_graph: the fronts were rejected: " + fronts.problem);
  const std::size_t n = scene.triangles.size();
  Setup s;
  s.front_face.resize(n);
  s.has_front.resize(n);
  s.hidden_cone.resize(n);
  s.always_hidden.assign(n, false);
  s.never_hidden.assign(n, false);
  std::set<std::pair<int, int>> edge_set;
  for (const auto& t : scene.triangles)
    for (int k = 0; k < 3; ++k) edge_set.insert(std::minmax(t.v[k], t.v[(k + 1) % 3]));
  std::vector<Edge> edges;
  for (const auto& [a, b] : edge_set) edges.push_back({a, b});
  std::vector<Vec3<Exact>> vx(scene.vertices.size());
  for (std::size_t i = 0; i < vx.size(); ++i) vx[i] = to_rational(scene.vertices[i]);

  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = scene.triangles[i];
    const auto [fp, fo] = s.circles.add(fronts.fronts[i].outward);
    s.front_face[i] = {fp, char_of(1, fo)};
    s.circles.generators[fp].push_back(
        {static_cast<int>(i), t.v[0], {std::min(t.v[1], t.v[2]), std::max(t.v[1], t.v[2])}});
    const auto& P = fronts.fronts[i].points;
    s.has_front[i] = !P.empty();
    if (P.empty()) continue;
    std::vector<RawConstraint> raw;
    std::set<std::tuple<ExactKey, int, int>> unique_halfspaces;
    bool free_corner = false;
    for (int k = 0; k < 3; ++k) {
      const Vec3<Exact>& a = vx[t.v[k]];
      // The line through a meets P_t at a itself: this corner is in the closed shadow for every d.
      if (in_hull(a, P)) continue;
      free_corner = true;
      for (std::size_t u = 0; u < P.size(); ++u)
        for (std::size_t w = u + 1; w < P.size(); ++w) {
          const Vec3<Exact> nv = cross(P[u] - a, P[w] - a);
          if (nv.x == 0 && nv.y == 0 && nv.z == 0) continue;
          // Supporting: all of P on one closed side of the plane through a, u, w.
          int side = 0;
          bool supporting = true;
          for (const auto& p : P) {
            const int sp = CGAL::sign(dot(nv, p - a));
            if (sp == 0) continue;
            if (side == 0) side = sp;
            else if (sp != side) { supporting = false; break; }
          }
          if (!supporting || side == 0) continue;
          // One constraint per half-space (normal up to positive scaling, and side) and corner.
          int m = 0;
          for (int c = 1; c < 3; ++c)
            if (CGAL::abs(nv[c]) > CGAL::abs(nv[m])) m = c;
          const Exact sc = CGAL::abs(nv[m]);
          const int hs = side;
          if (unique_halfspaces.insert({ExactKey{nv.x / sc, nv.y / sc, nv.z / sc}, hs, k}).second)
            raw.push_back({nv, side, k, u, w});
        }
    }
    if (!free_corner) {
      s.always_hidden[i] = true;
      continue;
    }
    if (prune_to_facets(raw)) {
      s.never_hidden[i] = true;
      continue;
    }
    std::set<std::pair<int, char>> seen;
    std::set<std::pair<int, int>> named;  // (plane, corner vertex)
    for (const RawConstraint& rc : raw) {
      const auto [pl, o] = s.circles.add(rc.normal);
      const char forbidden = char_of(-rc.side, o);
      if (seen.insert({pl, forbidden}).second) s.hidden_cone[i].push_back({pl, forbidden});
      const int vtx = t.v[rc.corner];
      if (!named.insert({pl, vtx}).second) continue;
      // Name the circle by an edge in the plane through a (not through a), preferring one on the line uw.
      const Vec3<Exact>& a = vx[vtx];
      Generator g{static_cast<int>(i), vtx, {-1, -1}};
      bool on_line = false;
      for (const Edge& e : edges) {
        if (e.a == vtx || e.b == vtx) continue;
        const Vec3<Exact>& A = vx[e.a];
        const Vec3<Exact>& B = vx[e.b];
        if (dot(rc.normal, A - a) != 0 || dot(rc.normal, B - a) != 0) continue;
        const Vec3<Exact> c = cross(B - A, a - A);
        if (c.x == 0 && c.y == 0 && c.z == 0) continue;  // a on the edge's line: no EV set
        const Vec3<Exact> d1 = cross(P[rc.w] - P[rc.u], A - P[rc.u]), d2 = cross(P[rc.w] - P[rc.u], B - P[rc.u]);
        const bool collinear_uw = d1.x == 0 && d1.y == 0 && d1.z == 0 && d2.x == 0 && d2.y == 0 && d2.z == 0;
        if (g.edge[0] < 0 || (collinear_uw && !on_line)) g.edge = {e.a, e.b}, on_line = collinear_uw;
        if (on_line) break;
      }
      s.circles.generators[pl].push_back(g);
    }
  }
  return s;
}

// The aspect of a cell (per triangle index: seen or not) from its sign vector.
std::string aspect_key(const Setup& s, const std::string& signs) {
  const std::size_t n = s.front_face.size();
  std::string key(n, '0');
  for (std::size_t i = 0; i < n; ++i) {
    if (signs[s.front_face[i].first] != s.front_face[i].second) continue;  // inner side or edge-on
    bool seen = !s.has_front[i] || s.never_hidden[i];
    if (!seen && !s.always_hidden[i])
      for (const Constraint& c : s.hidden_cone[i])
        if (signs[c.plane] == c.forbidden) { seen = true; break; }  // d outside K: some corner's line is free
    if (seen) key[i] = '1';
  }
  return key;
}

}  // namespace

std::size_t orthographic_aspect_circles(const Scene& scene, const ClosedSolidFronts& fronts) {
  return setup(scene, fronts).circles.normals.size();
}

AspectGraph3 orthographic_aspect_graph(const Scene& scene, const ClosedSolidFronts& fronts,
                                       void (*progress)(double)) {
  const Setup s = setup(scene, fronts);
  std::vector<ArrangementPlane> planes;
  for (const auto& nrm : s.circles.normals) planes.push_back({nrm, Exact(0)});
  const PlaneArrangement arr = plane_arrangement(planes, progress);

  const int nc = static_cast<int>(arr.cells.size());
  std::vector<AspectCell> cells(nc);
  std::vector<bool> keep(nc, false);
  std::unordered_map<std::string, int> aspect_ids;
  std::vector<std::string> aspect_keys;
  for (int c = 0; c < nc; ++c) {
    const ArrangementCell& a = arr.cells[c];
    cells[c].dimension = a.dimension - 1;  // cone of dimension k + 1 = sphere cell of dimension k
    cells[c].facets = a.facets;
    keep[c] = a.dimension >= 1;            // the origin is not a direction
    if (!keep[c]) continue;
    auto [it, fresh] = aspect_ids.emplace(aspect_key(s, a.signs), static_cast<int>(aspect_keys.size()));
    if (fresh) aspect_keys.push_back(it->first);
    cells[c].aspect = it->second;
  }
  const AspectRegions regions = aspect_regions(cells, keep);

  const auto scaled = [](Vec3<Exact> v) {
    Exact big(0);
    for (int i = 0; i < 3; ++i) big = std::max(big, CGAL::abs(v[i]));
    for (int i = 0; i < 3; ++i) v[i] /= big;
    return v;
  };
  AspectGraph3 out;
  out.view = ViewModel::Orthographic;
  out.circles = s.circles.normals;
  for (int c = 0; c < nc; ++c)
    if (keep[c]) {
      ++out.cells[cells[c].dimension];
      out.sampled_cells.push_back(
          {regions.region_of[c], cells[c].dimension, scaled(arr.cells[c].sample), arr.cells[c].signs});
    }
  const std::size_t n = scene.triangles.size();
  for (std::size_t r = 0; r < regions.members.size(); ++r) {
    AspectRegion3 region;
    region.dimension = regions.dimension[r];
    int best = regions.members[r].front();
    for (int c : regions.members[r])
      if (cells[c].dimension > cells[best].dimension) best = c;
    const std::string& key = aspect_keys[cells[best].aspect];
    for (std::size_t i = 0; i < n; ++i)
      if (key[i] == '1') region.aspect.push_back(scene.triangles[i].id);
    region.sample = scaled(arr.cells[best].sample);
    out.regions.push_back(std::move(region));
  }
  for (const auto& adj : regions.adjacency) {
    AspectAdjacency3 a;
    a.a = adj.a;
    a.b = adj.b;
    const std::string& ka = aspect_keys[cells[adj.lower].aspect];
    const std::string& kb = aspect_keys[cells[adj.upper].aspect];
    // Generators of the circles holding the lower cell but not the upper one, for triangles that differ.
    std::map<std::pair<int, std::array<int, 2>>, std::set<std::int64_t>> events;
    const std::string& lo = arr.cells[adj.lower].signs;
    const std::string& up = arr.cells[adj.upper].signs;
    for (std::size_t p = 0; p < planes.size(); ++p) {
      if (lo[p] != '0' || up[p] == '0') continue;
      for (const Generator& g : s.circles.generators[p])
        if (ka[g.triangle] != kb[g.triangle]) events[{g.vertex, g.edge}].insert(scene.triangles[g.triangle].id);
    }
    for (const auto& [ve, tris] : events) {
      AspectEvent3 e;
      e.vertex = ve.first;
      e.edge = ve.second;
      e.triangles.assign(tris.begin(), tris.end());
      a.events.push_back(std::move(e));
    }
    out.adjacency.push_back(std::move(a));
  }
  return out;
}

}  // namespace exactvis
