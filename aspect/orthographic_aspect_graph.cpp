#include "aspect/orthographic_aspect_graph.hpp"

#include "aspect/aspect_regions.hpp"
#include "aspect/front_part_hull.hpp"
#include "aspect/great_circle_arrangement.hpp"
#include "kernel/predicates.hpp"

#include <tbb/parallel_for.h>

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

// The circle of normal v: v scaled so that its first largest |component| is +1.
ExactKey canonical(const Vec3<Exact>& v) {
  int a = 0;
  for (int i = 1; i < 3; ++i)
    if (CGAL::abs(v[i]) > CGAL::abs(v[a])) a = i;
  const Exact s = v[a];
  return {v.x / s, v.y / s, v.z / s};
}

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
        const int side = supporting_side(nv, P[i], P);
        if (side != 0 && CGAL::sign(dot(nv, a - P[i])) == -side) return false;
      }
  return true;
}

std::vector<std::pair<std::size_t, std::size_t>> all_pairs(std::size_t m) {
  std::vector<std::pair<std::size_t, std::size_t>> r;
  for (std::size_t u = 0; u < m; ++u)
    for (std::size_t w = u + 1; w < m; ++w) r.push_back({u, w});
  return r;
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
  const SceneEdgeTable table = scene_edge_table(scene);
  const std::vector<std::array<int, 2>>& edges = table.edges;
  const std::vector<Vec3<Exact>>& vx = table.vx;

  // Per triangle, in parallel: its hidden cone's constraints (after pruning), each with the scene edge naming
  // its circle (for the first constraint of each circle and corner). Then, in triangle order, the circles.
  struct Cone {
    bool always_hidden = false, never_hidden = false;
    std::vector<RawConstraint> raw;
    std::vector<std::array<int, 2>> name;  // per raw constraint: the naming edge, {-2, -2} = already named
  };
  std::vector<Cone> cones(n);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    const auto& t = scene.triangles[i];
    const auto& P = fronts.fronts[i].points;
    if (P.empty()) return;
    Cone& cone = cones[i];
    std::vector<RawConstraint>& raw = cone.raw;
    std::set<std::tuple<ExactKey, int, int>> unique_halfspaces;
    bool free_corner = false;
    const FrontHull hull = front_hull(P);
    for (int k = 0; k < 3; ++k) {
      const Vec3<Exact>& a = vx[t.v[k]];
      // The line through a meets P_t at a itself: this corner is in the closed shadow for every d.
      if (hull.full ? hull.contains(a) : in_hull(a, P)) continue;
      free_corner = true;
      // The candidate pairs: the hull's edges (every facet of cone(P_t - a) is spanned by a and a hull
      // edge, theory 10.5), or all pairs when P_t is flat.
      for (const auto& [u, w] : hull.full ? hull.edges : all_pairs(P.size())) {
        const Vec3<Exact> nv = cross(P[u] - a, P[w] - a);
        if (nv.x == 0 && nv.y == 0 && nv.z == 0) continue;
        // Supporting: all of P on one closed side of the plane through a, u, w.
        const int side = supporting_side(nv, a, P);
        if (side == 0) continue;
        // One constraint per half-space (normal up to positive scaling, and side) and corner.
        int m = 0;
        for (int c = 1; c < 3; ++c)
          if (CGAL::abs(nv[c]) > CGAL::abs(nv[m])) m = c;
        const Exact sc = CGAL::abs(nv[m]);
        if (unique_halfspaces.insert({ExactKey{nv.x / sc, nv.y / sc, nv.z / sc}, side, k}).second)
          raw.push_back({nv, side, k, u, w});
      }
    }
    if (!free_corner) {
      cone.always_hidden = true;
      return;
    }
    if (prune_to_facets(raw)) {
      cone.never_hidden = true;
      return;
    }
    std::set<std::pair<ExactKey, int>> named;  // (circle, corner vertex)
    for (const RawConstraint& rc : raw) {
      const int vtx = t.v[rc.corner];
      if (!named.insert({canonical(rc.normal), vtx}).second) {
        cone.name.push_back({-2, -2});
        continue;
      }
      // Name the circle by an edge in the plane through a (not through a), preferring one on the line uw.
      const std::array<int, 2> edge = ev_plane_edge(rc.normal, vtx, P[rc.u], P[rc.w], edges, vx);
      cone.name.push_back(edge);
    }
  });

  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = scene.triangles[i];
    const auto [fp, fo] = s.circles.add(fronts.fronts[i].outward);
    s.front_face[i] = {fp, char_of(1, fo)};
    s.circles.generators[fp].push_back(
        {static_cast<int>(i), t.v[0], {std::min(t.v[1], t.v[2]), std::max(t.v[1], t.v[2])}});
    s.has_front[i] = !fronts.fronts[i].points.empty();
    s.always_hidden[i] = cones[i].always_hidden;
    s.never_hidden[i] = cones[i].never_hidden;
    std::set<std::pair<int, char>> seen;
    for (std::size_t r = 0; r < cones[i].raw.size() && !cones[i].always_hidden && !cones[i].never_hidden; ++r) {
      const RawConstraint& rc = cones[i].raw[r];
      const auto [pl, o] = s.circles.add(rc.normal);
      const char forbidden = char_of(-rc.side, o);
      if (seen.insert({pl, forbidden}).second) s.hidden_cone[i].push_back({pl, forbidden});
      if (cones[i].name[r][0] != -2)
        s.circles.generators[pl].push_back({static_cast<int>(i), t.v[rc.corner], cones[i].name[r]});
    }
  }
  return s;
}

// The aspect (the set of triangles seen) of a sign vector that changes one circle at a time: only the
// triangles with a constraint on the changed circle are re-evaluated. Visible sets are bitsets; equal sets
// get one id (bucketed by a 64-bit XOR hash, compared exactly).
class AspectTracker {
 public:
  AspectTracker(const Setup& s, std::string signs) : s_(s), signs_(std::move(signs)) {
    const std::size_t n = s.front_face.size(), m = signs_.size();
    users_.resize(m);
    triangles_on_.resize(m);
    violated_.assign(n, 0);
    words_ = (n + 63) / 64;
    visible_.assign(words_, 0);
    zobrist_.resize(n);
    std::uint64_t x = 0x9e3779b97f4a7c15ULL;
    for (std::size_t i = 0; i < n; ++i) {  // splitmix64
      std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      zobrist_[i] = z ^ (z >> 31);
    }
    for (std::size_t i = 0; i < n; ++i) {
      const int t = static_cast<int>(i);
      triangles_on_[s.front_face[i].first].push_back(t);
      for (const Constraint& c : s.hidden_cone[i]) {
        users_[c.plane].push_back({t, c.forbidden});
        triangles_on_[c.plane].push_back(t);
        if (signs_[c.plane] == c.forbidden) ++violated_[i];
      }
    }
    for (auto& v : triangles_on_) {
      std::sort(v.begin(), v.end());
      v.erase(std::unique(v.begin(), v.end()), v.end());
    }
    for (std::size_t i = 0; i < n; ++i)
      if (seen(static_cast<int>(i))) toggle(static_cast<int>(i));
  }

  const std::string& signs() const { return signs_; }

  void set(int k, char c) {
    const char old = signs_[k];
    if (old == c) return;
    for (const auto& [t, forbidden] : users_[k]) {
      if (old == forbidden) --violated_[t];
      if (c == forbidden) ++violated_[t];
    }
    signs_[k] = c;
    for (int t : triangles_on_[k])
      if (seen(t) != bit(t)) toggle(t);
  }

  // The id of the current visible set (a new one when it was not seen before).
  int aspect_id() {
    auto& bucket = by_hash_[hash_];
    for (int id : bucket)
      if (aspects_[id] == visible_) return id;
    bucket.push_back(static_cast<int>(aspects_.size()));
    aspects_.push_back(visible_);
    return bucket.back();
  }
  static bool has(const std::vector<std::uint64_t>& set, std::size_t t) { return (set[t / 64] >> (t % 64)) & 1; }
  const std::vector<std::uint64_t>& aspect(int id) const { return aspects_[id]; }

 private:
  // Triangle t is seen iff d is strictly on its outer side and outside its hidden cone (section 10.5).
  bool seen(int t) const {
    if (signs_[s_.front_face[t].first] != s_.front_face[t].second) return false;  // inner side or edge-on
    if (!s_.has_front[t] || s_.never_hidden[t]) return true;
    return !s_.always_hidden[t] && violated_[t] > 0;  // d outside K: some corner's line is free
  }
  bool bit(int t) const { return has(visible_, t); }
  void toggle(int t) {
    visible_[t / 64] ^= std::uint64_t(1) << (t % 64);
    hash_ ^= zobrist_[t];
  }

  const Setup& s_;
  std::string signs_;
  std::vector<std::vector<std::pair<int, char>>> users_;  // per circle: (triangle, forbidden sign)
  std::vector<std::vector<int>> triangles_on_;            // per circle: triangles with a constraint on it
  std::vector<int> violated_;                             // per triangle: constraints seeing their forbidden sign
  std::size_t words_ = 0;
  std::vector<std::uint64_t> visible_, zobrist_;
  std::uint64_t hash_ = 0;
  std::unordered_map<std::uint64_t, std::vector<int>> by_hash_;
  std::vector<std::vector<std::uint64_t>> aspects_;
};

char sign_char(int s) { return s > 0 ? '+' : (s < 0 ? '-' : '0'); }

}  // namespace

std::size_t orthographic_aspect_circles(const Scene& scene, const ClosedSolidFronts& fronts) {
  return setup(scene, fronts).circles.normals.size();
}

AspectGraph3 orthographic_aspect_graph(const Scene& scene, const ClosedSolidFronts& fronts,
                                       void (*progress)(double), bool with_cells) {
  const Setup s = setup(scene, fronts);
  const std::vector<Vec3<Exact>>& normals = s.circles.normals;
  const GreatCircleArrangement arr = great_circle_arrangement(normals);
  if (progress) progress(0.3);
  const int V = static_cast<int>(arr.vertices.size()), E = static_cast<int>(arr.arcs.size()),
            F = static_cast<int>(arr.faces.size());
  const int nc = V + E + F;  // cells: vertices, then arcs, then faces
  std::vector<AspectCell> cells(nc);
  for (int v = 0; v < V; ++v) cells[v].dimension = 0;
  for (int a = 0; a < E; ++a) cells[V + a] = {1, 0, {arr.arcs[a].from, arr.arcs[a].to}};
  for (int f = 0; f < F; ++f) {
    cells[V + E + f].dimension = 2;
    for (int h : arr.faces[f].halfedges) cells[V + E + f].facets.push_back(V + h / 2);
  }

  // Depth-first over the faces, crossing one arc (one circle's sign) at a time; each face's arcs and
  // vertices are read with their circles' signs set to 0 when first met.
  const Vec3<Exact> start = face_sample(arr, 0);
  std::string signs(normals.size(), '0');
  for (std::size_t k = 0; k < normals.size(); ++k) signs[k] = sign_char(CGAL::sign(dot(normals[k], start)));
  AspectTracker tracker(s, std::move(signs));
  std::vector<std::string> cell_signs(with_cells ? nc : 0);
  std::vector<char> done(nc, 0);
  const auto read = [&](int c) {
    cells[c].aspect = tracker.aspect_id();
    done[c] = 1;
    if (with_cells) cell_signs[c] = tracker.signs();
  };
  const auto visit = [&](int f) {
    read(V + E + f);
    for (int h : arr.faces[f].halfedges) {
      const int a = h / 2, k = arr.arcs[a].circle;
      if (!done[V + a]) {
        const char old = tracker.signs()[k];
        tracker.set(k, '0');
        read(V + a);
        tracker.set(k, old);
      }
      const int v = h % 2 == 0 ? arr.arcs[a].from : arr.arcs[a].to;
      if (!done[v]) {
        std::vector<char> old;
        for (int c : arr.vertex_circles[v]) old.push_back(tracker.signs()[c]), tracker.set(c, '0');
        read(v);
        for (std::size_t i = 0; i < old.size(); ++i) tracker.set(arr.vertex_circles[v][i], old[i]);
      }
    }
  };
  struct Frame {
    int face;
    std::size_t next;
    int via;     // the circle crossed to enter (-1 for the first face)
    char back;   // its sign in the parent face
  };
  std::vector<Frame> stack{{0, 0, -1, '0'}};
  visit(0);
  int visited = 1;
  while (!stack.empty()) {
    Frame& top = stack.back();
    const auto& hs = arr.faces[top.face].halfedges;
    if (top.next == hs.size()) {
      if (top.via >= 0) tracker.set(top.via, top.back);
      stack.pop_back();
      continue;
    }
    const int a = hs[top.next++] / 2;
    const auto& arc = arr.arcs[a];
    const int g = arc.left == top.face ? arc.right : arc.left;
    if (done[V + E + g]) continue;
    const char old = tracker.signs()[arc.circle];
    tracker.set(arc.circle, old == '+' ? '-' : '+');
    stack.push_back({g, 0, arc.circle, old});
    visit(g);
    if (progress && (++visited & 1023) == 0) progress(0.3 + 0.6 * visited / F);
  }
  std::vector<bool> keep(nc, true);
  const AspectRegions regions = aspect_regions(cells, keep);

  const auto sample = [&](int c) {
    if (c < V) return arr.vertices[c];
    if (c < V + E) return arc_sample(arr, normals, c - V);
    return face_sample(arr, c - V - E);
  };
  // The circles holding a cell: a vertex's circles, an arc's circle, none for a face.
  const auto holding = [&](int c) {
    if (c < V) return arr.vertex_circles[c];
    if (c < V + E) return std::vector<int>{arr.arcs[c - V].circle};
    return std::vector<int>{};
  };
  AspectGraph3 out;
  out.view = ViewModel::Orthographic;
  out.circles = normals;
  for (int c = 0; c < nc; ++c) ++out.cells[cells[c].dimension];
  if (with_cells)
    for (int c = 0; c < nc; ++c)
      out.sampled_cells.push_back({regions.region_of[c], cells[c].dimension, sample(c), std::move(cell_signs[c])});
  const std::size_t n = scene.triangles.size();
  for (std::size_t r = 0; r < regions.members.size(); ++r) {
    AspectRegion3 region;
    region.dimension = regions.dimension[r];
    const int best = region_sample_cell(regions, r, cells);
    const auto& key = tracker.aspect(cells[best].aspect);
    for (std::size_t i = 0; i < n; ++i)
      if (AspectTracker::has(key, i)) region.aspect.push_back(scene.triangles[i].id);
    region.sample = sample(best);
    out.regions.push_back(std::move(region));
  }
  for (const auto& adj : regions.adjacency) {
    AspectAdjacency3 a;
    a.a = adj.a;
    a.b = adj.b;
    const auto& ka = tracker.aspect(cells[adj.lower].aspect);
    const auto& kb = tracker.aspect(cells[adj.upper].aspect);
    // Generators of the circles holding the lower cell but not the upper one, for triangles that differ.
    std::map<std::pair<int, std::array<int, 2>>, std::set<std::int64_t>> events;
    const std::vector<int> up = holding(adj.upper);
    for (int p : holding(adj.lower)) {
      if (std::find(up.begin(), up.end(), p) != up.end()) continue;
      for (const Generator& g : s.circles.generators[p])
        if (AspectTracker::has(ka, g.triangle) != AspectTracker::has(kb, g.triangle))
          events[{g.vertex, g.edge}].insert(scene.triangles[g.triangle].id);
    }
    a.events = ev_events_of(events);
    out.adjacency.push_back(std::move(a));
  }
  if (progress) progress(1);
  return out;
}

}  // namespace exactvis
