#include "aspect/orthographic_aspect_graph.hpp"

#include "aspect/aspect_regions.hpp"
#include "aspect/plane_arrangement_3.hpp"
#include "kernel/predicates.hpp"

#include <algorithm>
#include <map>
#include <set>
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
  std::vector<std::array<std::vector<Constraint>, 3>> cones;  // per triangle, per corner
  std::vector<std::array<bool, 3>> corner_in_front;         // the corner lies in P_t: hidden for every d
};

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
  s.cones.resize(n);
  s.corner_in_front.assign(n, {false, false, false});
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
    for (int k = 0; k < 3; ++k) {
      const Vec3<Exact>& a = vx[t.v[k]];
      // The line through a meets P_t at a itself: this corner is in the closed shadow for every d.
      if (in_hull(a, P)) {
        s.corner_in_front[i][k] = true;
        continue;
      }
      std::set<std::pair<int, char>> seen;
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
          const auto [pl, o] = s.circles.add(nv);
          // d in K_a needs sign(nv . d) in {side, 0}: the opposite sign is forbidden.
          const char forbidden = char_of(-side, o);
          if (!seen.insert({pl, forbidden}).second) continue;
          s.cones[i][k].push_back({pl, forbidden});
          auto& gens = s.circles.generators[pl];
          const bool named = std::any_of(gens.begin(), gens.end(), [&](const Generator& g) {
            return g.triangle == static_cast<int>(i) && g.vertex == t.v[k];
          });
          if (named) continue;
          // Name the circle by an edge in the plane through a (not through a), preferring one on the line uw.
          Generator g{static_cast<int>(i), t.v[k], {-1, -1}};
          bool on_line = false;
          for (const Edge& e : edges) {
            if (e.a == t.v[k] || e.b == t.v[k]) continue;
            const Vec3<Exact>& A = vx[e.a];
            const Vec3<Exact>& B = vx[e.b];
            if (dot(nv, A - a) != 0 || dot(nv, B - a) != 0) continue;
            const Vec3<Exact> c = cross(B - A, a - A);
            if (c.x == 0 && c.y == 0 && c.z == 0) continue;  // a on the edge's line: no EV set
            const Vec3<Exact> d1 = cross(P[w] - P[u], A - P[u]), d2 = cross(P[w] - P[u], B - P[u]);
            const bool collinear_uw = d1.x == 0 && d1.y == 0 && d1.z == 0 && d2.x == 0 && d2.y == 0 && d2.z == 0;
            if (g.edge[0] < 0 || (collinear_uw && !on_line)) g.edge = {e.a, e.b}, on_line = collinear_uw;
            if (on_line) break;
          }
          gens.push_back(g);
        }
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
    bool seen = !s.has_front[i];
    for (int k = 0; k < 3 && !seen; ++k) {
      if (s.corner_in_front[i][k]) continue;
      bool inside = true;  // d in K_a: the corner's line meets the front part
      for (const Constraint& c : s.cones[i][k])
        if (signs[c.plane] == c.forbidden) { inside = false; break; }
      seen = !inside;
    }
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
  for (int c = 0; c < nc; ++c)
    if (keep[c]) {
      ++out.cells[cells[c].dimension];
      out.sampled_cells.push_back({regions.region_of[c], cells[c].dimension, scaled(arr.cells[c].sample)});
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
