#include "aspect/plane_aspect_graph.hpp"

#include "aspect/aspect_regions.hpp"
#include "aspect/front_part_hull.hpp"
#include "kernel/predicates.hpp"

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <unordered_map>

namespace exactvis {

namespace {

using ExactKey = std::array<Exact, 3>;

// A half-plane of Q: g(x, y) = A x + B y + C >= 0.
struct Half {
  Exact A, B, C;
};

// The chart of Q = {n . p = offset}: the parameters (x, y) are the coordinates i, j of p, the dominant axis
// k of n solved for (z = H: x, y themselves).
struct Chart {
  Vec3<Exact> n;
  Exact offset;
  int i = 0, j = 1, k = 2;
  Chart(const Vec3<Exact>& normal, const Exact& off) : n(normal), offset(off) {
    for (int c = 0; c < 3; ++c)
      if (CGAL::abs(n[c]) > CGAL::abs(n[k])) k = c;
    i = (k + 1) % 3, j = (k + 2) % 3;
    if (i > j) std::swap(i, j);
  }
  Vec3<Exact> point(const Exact& x, const Exact& y) const {
    Vec3<Exact> p(0, 0, 0);
    p[i] = x, p[j] = y, p[k] = (offset - n[i] * x - n[j] * y) / n[k];
    return p;
  }
  // The trace of alpha . p >= beta: alpha . point(x, y) - beta, affine in (x, y).
  Half trace(const Vec3<Exact>& alpha, const Exact& beta) const {
    const Exact r = alpha[k] / n[k];
    return {alpha[i] - r * n[i], alpha[j] - r * n[j], r * offset - beta};
  }
};
Exact value(const Half& g, const Exact& x, const Exact& y) { return g.A * x + g.B * y + g.C; }
bool constant(const Half& g) { return g.A == 0 && g.B == 0; }

// Where a constraint comes from: a cone plane (corner, hull edge u w) or a front facet of P_t (corner -1).
struct Origin {
  int corner = -1;
  std::size_t u = 0, w = 0;
  Vec3<Exact> normal;
};

// Does the line {g_i = 0} meet the polygon {g_j >= 0 for all j}, and in a segment of positive length?
// On the line p0 + s dir every g_j is affine in s: a bound on s, or a constant that must be >= 0.
std::pair<bool, bool> meets(const std::vector<Half>& cs, std::size_t i) {
  const Half& g = cs[i];
  const Exact nn = g.A * g.A + g.B * g.B;
  const Exact x0 = -g.A * g.C / nn, y0 = -g.B * g.C / nn;
  const Exact dx = -g.B, dy = g.A;
  bool has_lo = false, has_hi = false;
  Exact lo, hi;
  for (std::size_t j = 0; j < cs.size(); ++j) {
    if (j == i) continue;
    const Exact v = value(cs[j], x0, y0), w = cs[j].A * dx + cs[j].B * dy;
    if (w == 0) {
      if (v < 0) return {false, false};
      continue;
    }
    const Exact s = -v / w;
    if (w > 0) {
      if (!has_lo || s > lo) lo = s, has_lo = true;
    } else if (!has_hi || s < hi) {
      hi = s, has_hi = true;
    }
  }
  if (has_lo && has_hi && lo > hi) return {false, false};
  return {true, !(has_lo && has_hi && lo == hi)};
}

// The canonical line key of a non-constant half-plane (divided by A, or by B when A = 0) and the sign of the
// divisor (g = o * |divisor| * canonical).
std::pair<ExactKey, int> canonical(const Half& g) {
  const Exact& s = g.A != 0 ? g.A : g.B;
  return {{g.A / s, g.B / s, g.C / s}, CGAL::sign(s) > 0 ? 1 : -1};
}

// Theory §10.8: the polygon Pi = Q ∩ closure(H_t) ∩ U_t as the constraints that matter. Empty: t is hidden
// nowhere on Q; Plane: everywhere on its outer side; else `kept` (indices into cs) describe Pi exactly.
enum class PolygonKind { Empty, Plane, Kept };
PolygonKind prune(const std::vector<Half>& cs, std::vector<std::size_t>& kept) {
  std::vector<Half> live;
  std::vector<std::size_t> from;
  for (std::size_t i = 0; i < cs.size(); ++i) {
    if (constant(cs[i])) {
      if (cs[i].C < 0) return PolygonKind::Empty;
      continue;  // always satisfied
    }
    live.push_back(cs[i]);
    from.push_back(i);
  }
  if (live.empty()) return PolygonKind::Plane;
  std::vector<std::pair<bool, bool>> m(live.size());
  bool any = false, any_long = false;
  for (std::size_t i = 0; i < live.size(); ++i) {
    m[i] = meets(live, i);
    any |= m[i].first;
    any_long |= m[i].second && m[i].first;
  }
  // Pi non-empty and not the plane has a boundary point, on a constraint line that meets it.
  if (!any) return PolygonKind::Empty;
  // Pi lies in a line iff two meeting constraints are opposite on one line; it is a point iff no meeting line
  // holds a segment of it. Then every meeting line is kept (they bound it within its line); else the lines
  // holding its edges suffice (a 2D convex polygon is the intersection of its edges' half-planes).
  bool flat = !any_long;
  std::map<ExactKey, int> orientation;
  for (std::size_t i = 0; i < live.size() && !flat; ++i) {
    if (!m[i].first) continue;
    const auto [key, o] = canonical(live[i]);
    const auto [it, fresh] = orientation.emplace(key, o);
    if (!fresh && it->second != o) flat = true;
  }
  for (std::size_t i = 0; i < live.size(); ++i)
    if (m[i].first && (flat || m[i].second)) kept.push_back(from[i]);
  return PolygonKind::Kept;
}

struct Generator {
  int triangle = 0;
  int vertex = -1;
  std::array<int, 2> edge{-1, -1};
};

// One triangle's visibility on Q as a function of line signs: seen iff the face line has sign `face_o`
// (or, for a face plane parallel to Q, iff face_constant > 0), the kind allows it, and some kept constraint
// (line, o) sees the sign -o (p outside Pi).
enum class Kind { Plain, Never, Occludable };
struct Rule {
  Kind kind = Kind::Plain;
  int face_line = -1, face_o = 1, face_constant = 0;
  std::vector<std::pair<int, int>> hidden;
};

struct PerTriangle {
  Kind kind = Kind::Plain;
  Half face;
  std::vector<Half> kept;
  std::vector<Generator> generators;  // per kept constraint (vertex -1: no generator of its own)
};

struct Setup {
  std::vector<Rule> rules;
  std::map<ExactKey, int> index;
  std::vector<ExactKey> lines;
  std::vector<std::vector<Generator>> generators;
  std::pair<int, int> add(const Half& g) {
    const auto [key, o] = canonical(g);
    const auto [it, fresh] = index.emplace(key, static_cast<int>(lines.size()));
    if (fresh) lines.push_back(key), generators.emplace_back();
    return {it->second, o};
  }
};

Setup setup(const Scene& scene, const ClosedSolidFronts& fronts, const Chart& Q) {
  if (!fronts.ok) throw std::invalid_argument("plane_aspect_graph: the fronts were rejected: " + fronts.problem);
  const std::size_t n = scene.triangles.size();
  const SceneEdgeTable table = scene_edge_table(scene);
  const std::vector<std::array<int, 2>>& edges = table.edges;
  const std::vector<Vec3<Exact>>& vx = table.vx;

  std::vector<PerTriangle> per(n);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    const auto& t = scene.triangles[i];
    PerTriangle& r = per[i];
    const Vec3<Exact>& nt = fronts.fronts[i].outward;
    r.face = Q.trace(nt, dot(nt, vx[t.v[0]]));  // closure of the outer side
    if (constant(r.face) && r.face.C <= 0) return void(r.kind = Kind::Never);
    const auto& P = fronts.fronts[i].points;
    if (P.empty()) return;  // nothing in front: seen from the whole outer side
    const FrontHull hull = front_hull(P);
    // P_t = closure(S ∩ H_t) has interior when it is not empty (theory §10.5).
    if (!hull.full) throw std::logic_error("plane_aspect_graph: a non-empty front part is flat");
    std::vector<Half> cs{r.face};
    std::vector<Origin> origin{Origin{-2, 0, 0, {}}};
    bool free_corner = false;
    for (int k = 0; k < 3; ++k) {
      const Vec3<Exact>& a = vx[t.v[k]];
      if (hull.contains(a)) continue;  // [a, p] meets P_t at a: this corner is hidden for every p
      free_corner = true;
      // The cone from a over P_t: the supporting planes through a and a hull edge (theory §10.5).
      for (const auto& [u, w] : hull.edges) {
        const Vec3<Exact> nv = cross(P[u] - a, P[w] - a);
        if (nv.x == 0 && nv.y == 0 && nv.z == 0) continue;
        const int side = supporting_side(nv, a, P);
        if (side == 0) continue;
        const Vec3<Exact> alpha = side > 0 ? nv : -nv;
        cs.push_back(Q.trace(alpha, dot(alpha, a)));
        origin.push_back({k, u, w, alpha});
      }
      // The facets of P_t facing a: p must be on their inner closed side (beyond P_t, not before it).
      for (const auto& [nv, c] : hull.facets)
        if (dot(nv, a) > c) cs.push_back(Q.trace(-nv, -c)), origin.push_back(Origin{-1, 0, 0, {}});
    }
    if (!free_corner) return void(r.kind = Kind::Never);
    std::vector<std::size_t> kept;
    const PolygonKind pk = prune(cs, kept);
    if (pk == PolygonKind::Empty) return;
    if (pk == PolygonKind::Plane) return void(r.kind = Kind::Never);
    r.kind = Kind::Occludable;
    std::set<std::pair<ExactKey, int>> seen;
    for (std::size_t j : kept) {
      if (!seen.insert(canonical(cs[j])).second) continue;
      r.kept.push_back(cs[j]);
      Generator g{static_cast<int>(i), -1, {-1, -1}};
      if (origin[j].corner >= 0) {
        const int vtx = t.v[origin[j].corner];
        g.vertex = vtx;
        g.edge = ev_plane_edge(origin[j].normal, vtx, P[origin[j].u], P[origin[j].w], edges, vx);
      }
      r.generators.push_back(g);
    }
  });

  Setup s;
  s.rules.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = scene.triangles[i];
    Rule& rule = s.rules[i];
    rule.kind = per[i].kind;
    if (rule.kind == Kind::Never) continue;
    if (constant(per[i].face)) {
      rule.face_constant = CGAL::sign(per[i].face.C);
    } else {
      std::tie(rule.face_line, rule.face_o) = s.add(per[i].face);
      s.generators[rule.face_line].push_back(
          {static_cast<int>(i), t.v[0], {std::min(t.v[1], t.v[2]), std::max(t.v[1], t.v[2])}});
    }
    for (std::size_t j = 0; j < per[i].kept.size(); ++j) {
      const auto lo = s.add(per[i].kept[j]);
      rule.hidden.push_back(lo);
      if (per[i].generators[j].vertex >= 0) s.generators[lo.first].push_back(per[i].generators[j]);
    }
  }
  return s;
}

using K = CGAL::Simple_cartesian<CGAL::Lazy_exact_nt<mpq_class>>;
using SegmentTraits = CGAL::Arr_segment_traits_2<K>;
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<SegmentTraits, int>;
using Arr = CGAL::Arrangement_2<Traits>;

K::FT ft(const Exact& x) { return K::FT(mpq_class(x.mpq())); }
Exact ex(const K::FT& x) {
  const mpq_class v = CGAL::exact(x);
  return Exact(v.get_mpq_t());
}

// The two points where the line (A, B, C) leaves the box [-R, R]^2 (it passes through its interior).
std::pair<K::Point_2, K::Point_2> clip(const ExactKey& l, const Exact& R) {
  std::vector<std::pair<Exact, Exact>> pts;
  for (const Exact& c : {-R, R}) {
    if (l[1] != 0) {
      const Exact y = -(l[2] + l[0] * c) / l[1];
      if (CGAL::abs(y) <= R) pts.push_back({c, y});
    }
    if (l[0] != 0) {
      const Exact x = -(l[2] + l[1] * c) / l[0];
      if (CGAL::abs(x) <= R) pts.push_back({x, c});
    }
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() != 2) throw std::logic_error("plane_aspect_graph: a line does not cross the box twice");
  return {K::Point_2(ft(pts[0].first), ft(pts[0].second)), K::Point_2(ft(pts[1].first), ft(pts[1].second))};
}

char sign_char(int s) { return s > 0 ? '+' : (s < 0 ? '-' : '0'); }

}  // namespace

std::size_t plane_aspect_lines(const Scene& scene, const ClosedSolidFronts& fronts, const Vec3<Exact>& normal,
                               const Exact& offset) {
  if (normal.x == 0 && normal.y == 0 && normal.z == 0) throw std::invalid_argument("plane_aspect_lines: zero normal");
  return setup(scene, fronts, Chart(normal, offset)).lines.size();
}

std::size_t plane_aspect_lines(const Scene& scene, const ClosedSolidFronts& fronts, const Exact& height) {
  return plane_aspect_lines(scene, fronts, Vec3<Exact>(0, 0, 1), height);
}

AspectGraph3 plane_aspect_graph(const Scene& scene, const ClosedSolidFronts& fronts, const Exact& height,
                                void (*progress)(double), bool with_cells) {
  return plane_aspect_graph(scene, fronts, Vec3<Exact>(0, 0, 1), height, progress, with_cells);
}

AspectGraph3 plane_aspect_graph(const Scene& scene, const ClosedSolidFronts& fronts, const Vec3<Exact>& normal,
                                const Exact& offset, void (*progress)(double), bool with_cells) {
  if (normal.x == 0 && normal.y == 0 && normal.z == 0) throw std::invalid_argument("plane_aspect_graph: zero normal");
  const Chart Q(normal, offset);
  const Setup s = setup(scene, fronts, Q);
  const std::size_t L = s.lines.size(), n = scene.triangles.size();
  if (progress) progress(0.1);

  // The box [-R, R]^2 holds every crossing of two lines and every line's point nearest the origin strictly
  // inside, so each cell of the line arrangement meets the box in one cell of the clipped arrangement.
  Exact big(1);
  for (const auto& p : scene.vertices) {
    const double c[3] = {p.x, p.y, p.z};
    big = std::max({big, CGAL::abs(Exact(c[Q.i])), CGAL::abs(Exact(c[Q.j]))});
  }
  for (std::size_t i = 0; i < L; ++i) {
    const ExactKey& a = s.lines[i];
    const Exact nn = a[0] * a[0] + a[1] * a[1];
    big = std::max({big, CGAL::abs(a[0] * a[2] / nn), CGAL::abs(a[1] * a[2] / nn)});
    for (std::size_t j = i + 1; j < L; ++j) {
      const ExactKey& b = s.lines[j];
      const Exact det = a[0] * b[1] - a[1] * b[0];
      if (det == 0) continue;
      big = std::max({big, CGAL::abs((a[1] * b[2] - b[1] * a[2]) / det), CGAL::abs((a[2] * b[0] - b[2] * a[0]) / det)});
    }
  }
  const Exact R(CGAL::Gmpz(big.numerator() / big.denominator()) + 2);  // an integer > big
  std::vector<Traits::Curve_2> curves;
  for (std::size_t i = 0; i < L; ++i) {
    const auto [p, q] = clip(s.lines[i], R);
    curves.emplace_back(SegmentTraits::Curve_2(p, q), static_cast<int>(i));
  }
  const K::Point_2 c00(ft(-R), ft(-R)), c10(ft(R), ft(-R)), c11(ft(R), ft(R)), c01(ft(-R), ft(R));
  for (const auto& [p, q] : {std::pair{c00, c10}, std::pair{c10, c11}, std::pair{c11, c01}, std::pair{c01, c00}})
    curves.emplace_back(SegmentTraits::Curve_2(p, q), -1);
  Arr arr;
  CGAL::insert(arr, curves.begin(), curves.end());
  if (progress) progress(0.4);

  // Cells: vertices, edges and faces inside the box, with exact samples and the lines holding them.
  const auto on_box = [](Arr::Halfedge_const_handle h) {
    for (int d : h->curve().data())
      if (d < 0) return true;
    return false;
  };
  std::vector<AspectCell> cells;
  std::vector<std::pair<Exact, Exact>> samples;
  std::unordered_map<const void*, int> cell_of;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    bool box = false;
    auto h = v->incident_halfedges(), first = h;
    do box |= on_box(h);
    while (++h != first);
    if (box) continue;
    cell_of[&*v] = static_cast<int>(cells.size());
    cells.push_back({0, 0, {}});
    samples.push_back({ex(v->point().x()), ex(v->point().y())});
  }
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    if (on_box(e)) continue;
    const int id = static_cast<int>(cells.size());
    cell_of[&*e] = id;
    cell_of[&*e->twin()] = id;
    AspectCell c{1, 0, {}};
    for (const void* end : {static_cast<const void*>(&*e->source()), static_cast<const void*>(&*e->target())})
      if (const auto it = cell_of.find(end); it != cell_of.end()) c.facets.push_back(it->second);
    cells.push_back(std::move(c));
    const auto m = CGAL::midpoint(e->source()->point(), e->target()->point());
    samples.push_back({ex(m.x()), ex(m.y())});
  }
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (f->is_unbounded()) continue;
    AspectCell c{2, 0, {}};
    Exact sx(0), sy(0);
    int count = 0;
    auto h = f->outer_ccb(), first = h;
    do {
      if (const auto it = cell_of.find(&*h); it != cell_of.end()) c.facets.push_back(it->second);
      sx += ex(h->target()->point().x());
      sy += ex(h->target()->point().y());
      ++count;
    } while (++h != first);
    cells.push_back(std::move(c));
    // The mean of a convex polygon's vertices lies in its interior.
    samples.push_back({sx / count, sy / count});
  }
  const int nc = static_cast<int>(cells.size());

  // Per cell: the sign vector against the lines, then each triangle's visibility from it (exact).
  // Signs: interval arithmetic first (the coefficients and the sample as enclosing double intervals), exact
  // rationals only when the interval holds 0 (mostly the lines holding the cell, whose sign is 0).
  const auto enclosure = [](const Exact& v) {
    const auto [lo, hi] = tight_interval(v);
    return Interval(lo, hi);
  };
  std::vector<std::array<Interval, 3>> coef(L);
  {
    CGAL::Protect_FPU_rounding<true> guard;
    for (std::size_t k = 0; k < L; ++k)
      coef[k] = {enclosure(s.lines[k][0]), enclosure(s.lines[k][1]), enclosure(s.lines[k][2])};
  }
  std::vector<std::string> signs(nc, std::string(L, '0'));
  std::vector<std::string> seen(nc, std::string(n, '0'));
  tbb::parallel_for(0, nc, [&](int c) {
    const auto& [x, y] = samples[c];
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const Interval ix = enclosure(x), iy = enclosure(y);
      for (std::size_t k = 0; k < L; ++k) {
        const Interval v = coef[k][0] * ix + coef[k][1] * iy + coef[k][2];
        signs[c][k] = v.inf() > 0 ? '+' : (v.sup() < 0 ? '-' : 'x');
      }
    }
    for (std::size_t k = 0; k < L; ++k)
      if (signs[c][k] == 'x')
        signs[c][k] = sign_char(CGAL::sign(s.lines[k][0] * x + s.lines[k][1] * y + s.lines[k][2]));
    const auto sg = [&](int line, int o) {
      const char ch = signs[c][line];
      return ch == '0' ? 0 : (ch == '+' ? o : -o);
    };
    for (std::size_t t = 0; t < n; ++t) {
      const Rule& r = s.rules[t];
      if (r.kind == Kind::Never) continue;
      if (r.face_line >= 0 ? sg(r.face_line, r.face_o) <= 0 : r.face_constant <= 0) continue;
      bool visible = r.kind == Kind::Plain;
      for (const auto& [line, o] : r.hidden)
        if (sg(line, o) < 0) { visible = true; break; }
      if (visible) seen[c][t] = '1';
    }
  });
  if (progress) progress(0.8);
  std::unordered_map<std::string, int> aspect_ids;
  std::vector<bool> keep(nc);
  std::vector<const std::string*> aspect_of_id;
  for (int c = 0; c < nc; ++c) {
    const auto [it, fresh] = aspect_ids.emplace(seen[c], static_cast<int>(aspect_of_id.size()));
    if (fresh) aspect_of_id.push_back(&it->first);
    cells[c].aspect = it->second;
    keep[c] = seen[c].find('1') != std::string::npos;  // empty exactly inside the solid (theory §10.8)
  }
  const AspectRegions regions = aspect_regions(cells, keep);

  AspectGraph3 out;
  out.view = ViewModel::Plane;
  for (int c = 0; c < nc; ++c)
    if (keep[c]) ++out.cells[cells[c].dimension];
  const auto point = [&](int c) { return Q.point(samples[c].first, samples[c].second); };
  for (std::size_t r = 0; r < regions.members.size(); ++r) {
    AspectRegion3 region;
    region.dimension = regions.dimension[r];
    const int best = region_sample_cell(regions, r, cells);
    for (std::size_t t = 0; t < n; ++t)
      if (seen[best][t] == '1') region.aspect.push_back(scene.triangles[t].id);
    std::sort(region.aspect.begin(), region.aspect.end());
    region.sample = point(best);
    out.regions.push_back(std::move(region));
  }
  for (const auto& adj : regions.adjacency) {
    AspectAdjacency3 a;
    a.a = adj.a;
    a.b = adj.b;
    // Generators of the lines holding the lower cell and not the upper one, for triangles that differ.
    std::map<std::pair<int, std::array<int, 2>>, std::set<std::int64_t>> events;
    for (std::size_t k = 0; k < L; ++k) {
      if (signs[adj.lower][k] != '0' || signs[adj.upper][k] == '0') continue;
      for (const Generator& g : s.generators[k])
        if (seen[adj.lower][g.triangle] != seen[adj.upper][g.triangle])
          events[{g.vertex, g.edge}].insert(scene.triangles[g.triangle].id);
    }
    a.events = ev_events_of(events);
    out.adjacency.push_back(std::move(a));
  }
  if (with_cells) {
    for (const auto& l : s.lines) out.circles.push_back({l[0], l[1], l[2]});
    for (int c = 0; c < nc; ++c)
      out.sampled_cells.push_back({regions.region_of[c], cells[c].dimension, point(c), std::move(signs[c])});
  }
  if (progress) progress(1);
  return out;
}

}  // namespace exactvis
