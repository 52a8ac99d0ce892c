#include "events/eee_events.hpp"

#include "events/eee_line_miss_filter.hpp"
#include "events/eee_occluder_filter.hpp"
#include "events/eee_occluder_pattern.hpp"
#include "events/interval_end_key.hpp"
#include "kernel/predicate_counters.hpp"
#include "kernel/ray_first_hit.hpp"
#include "kernel/predicates.hpp"
#include "kernel/quadratic_polynomial.hpp"
#include "kernel/rational_between.hpp"
#include "kernel/segment_triangle_intersection.hpp"
#include "kernel/triangle_index.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace exactvis {
namespace {

// Every quantity of the EEE family used here is a polynomial of degree <= 2 in t (docs/theory.md section 6).
using Poly = QuadraticPolynomial;
using Root = RealRoot;

using PVec = Vec3<Poly>;
PVec pconst(const Vec3<Exact>& v) { return {Poly(v.x), Poly(v.y), Poly(v.z)}; }
// Dot product with a constant vector (no polynomial products).
Poly dotc(const PVec& a, const Vec3<Exact>& b) {
  Poly r;
  for (int k = 0; k < 3; ++k) r.c[k] = a.x.c[k] * b.x + a.y.c[k] * b.y + a.z.c[k] * b.z;
  return r;
}
Vec3<Exact> eval(const PVec& v, const Exact& t) { return {v.x(t), v.y(t), v.z(t)}; }

// A parameter where validity may change, with the cause reported if a free interval ends there.
struct Breakpoint {
  RootNumber t;
  bool rational = true;
  Exact q;
  CriticalEnd cause;
};

// Sorts by t (exact) and keeps the first breakpoint of each value (stable: earlier entries win the cause).
void sort_unique(std::vector<Breakpoint>& b) {
  std::stable_sort(b.begin(), b.end(), [](const Breakpoint& x, const Breakpoint& y) { return x.t < y.t; });
  b.erase(std::unique(b.begin(), b.end(), [](const Breakpoint& x, const Breakpoint& y) { return x.t == y.t; }),
          b.end());
}

// A closed parameter interval where lines are invalid, with the causes at its ends.
struct Invalid {
  RootNumber lo, hi;
  CriticalEnd lo_end, hi_end;
};

CriticalEnd endpoint_end(int edge, int vertex) {
  CriticalEnd e;
  e.cause = CriticalEnd::Cause::EdgeEndpoint;
  e.generator = edge;
  e.vertex = vertex;
  return e;
}

CriticalEnd singular_end(int edge) {
  CriticalEnd e;
  e.cause = CriticalEnd::Cause::Singular;
  e.generator = edge;
  return e;
}

// The EEE family of three pairwise skew lines l_i = A_i + s (B_i - A_i): P(t) on l1, the homogeneous points
// (num_k(t) : den_k(t)) where L(t) meets l2 and l3 (s_k = sn_k / den_k along l_k), and L(t)'s Plücker
// coordinates, all polynomial in t (docs/theory.md section 6).
struct Family {
  Vec3<Exact> A[3], B[3], D[3];
  PVec P;
  Poly den[3], sn[3];  // index 1, 2 used
  PVec num[3];
  PVec Ld, Lm;  // L(t) = line through P(t) then (num2 : den2); set by compute_line()

  Family(const std::array<Vec3<Exact>, 3>& a, const std::array<Vec3<Exact>, 3>& b) {
    for (int i = 0; i < 3; ++i) A[i] = a[i], B[i] = b[i], D[i] = b[i] - a[i];
    P = PVec(Poly::linear(A[0].x, D[0].x), Poly::linear(A[0].y, D[0].y), Poly::linear(A[0].z, D[0].z));
    for (int k = 1; k <= 2; ++k) {
      const int o = 3 - k;  // the other edge: Q_k = l_k meets plane(P(t), l_o)
      // Normal n(t) = D_o x (P(t) - A_o) = n0 + t n1 (linear; scalar arithmetic only).
      const Vec3<Exact> n0 = cross(D[o], A[0] - A[o]), n1 = cross(D[o], D[0]);
      const Vec3<Exact> ako = A[k] - A[o];
      den[k] = Poly::linear(dot(n0, D[k]), dot(n1, D[k]));
      sn[k] = Poly::linear(-dot(n0, ako), -dot(n1, ako));
      for (int j = 0; j < 3; ++j)
        num[k][j] = Poly::linear(den[k].c[0] * A[k][j] + sn[k].c[0] * D[k][j],
                                 den[k].c[1] * A[k][j] + sn[k].c[1] * D[k][j]);
    }
  }
  // Plücker coordinates of L(t) (degree 2), needed only once the base conditions hold somewhere.
  void compute_line() {
    Ld = num[1] - den[1] * P;
    Lm = cross(P, num[1]);
  }
  // Homogeneous plane-side polynomial of the generator point k (0: P, 1: Q2, 2: Q3) w.r.t. plane n.x = c:
  // its sign times sign(den_k) (den_0 = 1) is the side of the actual point.
  Poly height(int k, const Vec3<Exact>& n, const Exact& c) const {
    if (k == 0) return dotc(P, n) - Poly(c);
    return dotc(num[k], n) - scaled(den[k], c);
  }
};

bool has_vertex(const SceneTriangle& t, int v) { return t.v[0] == v || t.v[1] == v || t.v[2] == v; }
bool has_edge(const SceneTriangle& t, const std::array<int, 2>& e) { return has_vertex(t, e[0]) && has_vertex(t, e[1]); }

// The three generator points of L(t) at a rational t (both den nonzero), and the two outermost ones.
struct RationalLine {
  Vec3<Exact> pts[3];
  int lo = 0, hi = 1;  // indices of the outermost points along d = Q2 - P (lo first)
};
RationalLine rational_line(const Family& f, const Exact& t) {
  RationalLine r;
  r.pts[0] = eval(f.P, t);
  for (int k = 1; k <= 2; ++k) {
    const Exact dk = f.den[k](t);
    const Vec3<Exact> nk = eval(f.num[k], t);
    r.pts[k] = {nk.x / dk, nk.y / dk, nk.z / dk};
  }
  const Vec3<Exact> d = r.pts[1] - r.pts[0];
  const Exact lambda = dot(r.pts[2] - r.pts[0], d) / dot(d, d);  // positions 0, 1, lambda along d
  if (lambda < 0) r.lo = 2;
  if (lambda > 1) r.hi = 2;
  return r;
}

// [0, 1] minus the union of the closed invalid pieces (sorted here): the closures of the components of
// positive length, with the causes of their ends (end_at_0 / end_at_1 at t = 0 / 1). sample_t is not set.
std::vector<CriticalInterval> free_components(std::vector<Invalid>& invalid, const CriticalEnd& end_at_0,
                                         const CriticalEnd& end_at_1) {
  std::stable_sort(invalid.begin(), invalid.end(), [](const Invalid& x, const Invalid& y) { return x.lo < y.lo; });
  std::vector<CriticalInterval> out;
  RootNumber pos(0);
  CriticalEnd pos_end = end_at_0;
  auto emit = [&](const RootNumber& t1, const CriticalEnd& end1) {
    CriticalInterval iv;
    iv.t0 = pos;
    iv.t1 = t1;
    iv.end0 = pos_end;
    iv.end1 = end1;
    out.push_back(std::move(iv));
  };
  for (const auto& iv : invalid) {
    if (iv.lo > pos) emit(iv.lo, iv.lo_end);
    if (iv.hi >= pos) {
      pos = iv.hi;
      pos_end = iv.hi_end;
    }
  }
  if (pos < RootNumber(1)) emit(RootNumber(1), end_at_1);
  return out;
}

Breakpoint breakpoint_at(const RootNumber& t, const CriticalEnd& cause) {
  Breakpoint b{t, true, Exact(0), cause};
  b.rational = root_number_rational(t, &b.q);
  return b;
}

struct Occluder {
  int index;
  std::int64_t id;
  std::array<int, 3> ids;
  std::array<Vec3<Exact>, 3> c;
};

// The invalid pieces of occluder T over (vmin, vmax) from its certified pattern (events/eee_occluder_pattern):
// the pieces the exact analysis of eee_event would append, in its order (each blocked gap, then the next
// breakpoint when it is blocked and rational), with exact ends. Exact roots are computed only for the
// polynomials of breakpoints that end a piece and for those the pattern asks to check; a polynomial's roots
// inside (vmin, vmax), sorted, correspond one to one to the pattern's enclosures of it. Returns false (and
// appends nothing) when a check refutes the pattern: the caller runs the exact analysis. Throws
// std::logic_error if an unchecked polynomial disagrees with its enclosures (a defect, never rounding).
bool add_pattern_pieces(const Family& f, const Occluder& T, const Scene& scene, const EeeOccluderPattern& pattern,
                        const Breakpoint& vmin, const Breakpoint& vmax, std::vector<Invalid>& invalid) {
  static PredicateCounter counter("eee_occluder_pattern_check");
  constexpr int kSlots = 8;  // q0, q1, q2, h0, h1, h2, den1, den2
  auto slot_of = [](const EeeOccluderBreakpoint& b) {
    return b.poly == EeeOccluderPoly::Side ? b.index : b.poly == EeeOccluderPoly::Height ? 3 + b.index : 5 + b.index;
  };
  int expected[kSlots] = {};
  for (const auto& b : pattern.inner) ++expected[slot_of(b)];
  std::array<std::optional<std::vector<Breakpoint>>, kSlots> roots;
  std::array<Vec3<Exact>, 3> c;
  bool have_corners = false;
  auto corners = [&]() -> const std::array<Vec3<Exact>, 3>& {
    if (!have_corners) {
      const auto& tr = scene.triangles[T.index];
      for (int k = 0; k < 3; ++k) c[k] = to_rational(scene.corner(tr, k));
      have_corners = true;
    }
    return c;
  };
  // The exact roots of a polynomial strictly inside (vmin, vmax), sorted, with the exact analysis' causes.
  auto exact_roots = [&](const EeeOccluderBreakpoint& b) -> const std::vector<Breakpoint>& {
    const int slot = slot_of(b);
    if (!roots[slot]) {
      Poly p;
      CriticalEnd cause;
      cause.cause = CriticalEnd::Cause::Occluder;
      cause.triangle = T.id;
      if (b.poly == EeeOccluderPoly::Side) {
        const auto& cc = corners();
        const PluckerLine<Exact> el = line_through(cc[b.index], cc[(b.index + 1) % 3]);
        p = dotc(f.Ld, el.m) + dotc(f.Lm, el.d);
        cause.feature.kind = OccluderFeature::Kind::Edge;
        cause.feature.ids = {T.ids[b.index], T.ids[(b.index + 1) % 3]};
      } else if (b.poly == EeeOccluderPoly::Height) {
        const auto& cc = corners();
        const Vec3<Exact> n = cross(cc[1] - cc[0], cc[2] - cc[0]);
        p = f.height(b.index, n, dot(n, cc[0]));
        cause.feature.kind = OccluderFeature::Kind::Face;
        cause.feature.ids = {T.ids[0], T.ids[1], T.ids[2]};
      } else {
        p = f.den[b.index];
        cause = singular_end(b.index);
      }
      std::vector<Breakpoint> r;
      for (const Root& x : real_roots(p))
        if (x.t > vmin.t && x.t < vmax.t) r.push_back({x.t, x.rational, x.q, cause});
      std::sort(r.begin(), r.end(), [](const Breakpoint& x, const Breakpoint& y) { return x.t < y.t; });
      roots[slot] = std::move(r);
    }
    return *roots[slot];
  };
  if (!pattern.verify.empty()) {
    std::atomic<std::uint64_t>* counts = counter.thread_counts();
    detail::bump(counts[0]);
    for (const auto& b : pattern.verify)
      if (static_cast<int>(exact_roots(b).size()) != expected[slot_of(b)]) {
        detail::bump(counts[1 + static_cast<int>(FilterLayer::Exact)]);
        return false;
      }
    detail::bump(counts[1 + static_cast<int>(FilterLayer::Interval)]);
  }
  auto exact_breakpoint = [&](const EeeOccluderBreakpoint& b) -> const Breakpoint& {
    const std::vector<Breakpoint>& r = exact_roots(b);
    if (static_cast<int>(r.size()) != expected[slot_of(b)])
      throw std::logic_error("eee_event: occluder pattern and exact roots disagree");
    return r[b.rank];
  };
  const std::size_t nb = pattern.inner.size();
  auto at = [&](std::size_t i) -> const Breakpoint& {
    return i == 0 ? vmin : i == nb + 1 ? vmax : exact_breakpoint(pattern.inner[i - 1]);
  };
  for (std::size_t g = 0; g <= nb; ++g) {
    if (pattern.gap_blocked[g]) {
      const Breakpoint& lo = at(g);
      const Breakpoint& hi = at(g + 1);
      invalid.push_back({lo.t, hi.t, lo.cause, hi.cause});
    }
    if (g < nb && pattern.inner[g].blocked) {
      const Breakpoint& b = at(g + 1);
      if (b.rational) invalid.push_back({b.t, b.t, b.cause, b.cause});
    }
  }
  return true;
}

}  // namespace

std::optional<EeeEvent> eee_event(const Scene& scene, const SceneAdjacency& adj, const TriangleIndex& index,
                                  int e1, int e2, int e3, EeeStats* stats) {
  std::array<int, 3> ei{e1, e2, e3};
  for (int e : ei)
    if (e < 0 || e >= static_cast<int>(adj.edges.size()))
      throw std::out_of_range("eee_event: edge index " + std::to_string(e) + " out of range");
  std::sort(ei.begin(), ei.end());
  if (ei[0] == ei[1] || ei[1] == ei[2]) return std::nullopt;
  const SceneEdge* E[3] = {&adj.edges[ei[0]], &adj.edges[ei[1]], &adj.edges[ei[2]]};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      for (int a : E[i]->v)
        for (int b : E[j]->v)
          if (a == b) return std::nullopt;  // generators sharing a vertex: covered by EV sets
  if (stats) ++stats->triples;
  std::array<Vec3<Exact>, 3> A, B;
  for (int i = 0; i < 3; ++i) {
    A[i] = to_rational(scene.vertices[E[i]->v[0]]);
    B[i] = to_rational(scene.vertices[E[i]->v[1]]);
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (orient3d(scene.vertices[E[i]->v[0]], scene.vertices[E[i]->v[1]], scene.vertices[E[j]->v[0]],
                   scene.vertices[E[j]->v[1]]) == Sign::Zero)
        return std::nullopt;  // coplanar supporting lines (exact filtered test on the input doubles)
  Family f(A, B);

  // ---- Segment bounds and tangency: rational breakpoints, decided exactly at each and between them.
  struct TangencyPoly {
    int edge;
    Poly p;
  };
  std::vector<TangencyPoly> tangency;
  for (int i = 0; i < 3; ++i) {
    for (int ti : E[i]->triangles) {
      const auto& tr = scene.triangles[ti];
      const int w = tr.v[0] + tr.v[1] + tr.v[2] - E[i]->v[0] - E[i]->v[1];
      const PVec W = pconst(to_rational(scene.vertices[w]) - A[i]);
      // Plane of L(t) and l_i: through l_i and another point of L(t): Q2 for E1, P(t) for E2 and E3.
      const PVec other = i == 0 ? f.num[1] - f.den[1] * pconst(A[0]) : f.P - pconst(A[i]);
      tangency.push_back({i, dot(cross(pconst(f.D[i]), other), W)});
    }
  }
  std::vector<std::int64_t> tangency_triangle;
  for (int i = 0; i < 3; ++i)
    for (int ti : E[i]->triangles) tangency_triangle.push_back(scene.triangles[ti].id);

  std::vector<Breakpoint> base;
  base.push_back({RootNumber(0), true, Exact(0), endpoint_end(0, E[0]->v[0])});
  base.push_back({RootNumber(1), true, Exact(1), endpoint_end(0, E[0]->v[1])});
  auto add_roots = [&](std::vector<Breakpoint>& out, const Poly& p, const CriticalEnd& cause, const RootNumber& lo,
                       const RootNumber& hi) {
    for (const Root& r : real_roots(p))
      if (r.t > lo && r.t < hi) out.push_back({r.t, r.rational, r.q, cause});
  };
  const RootNumber zero(0), one(1);
  for (int k = 1; k <= 2; ++k) {
    add_roots(base, f.sn[k], endpoint_end(k, E[k]->v[0]), zero, one);
    add_roots(base, f.den[k] - f.sn[k], endpoint_end(k, E[k]->v[1]), zero, one);
    add_roots(base, f.den[k], singular_end(k), zero, one);
  }
  for (std::size_t j = 0; j < tangency.size(); ++j) {
    CriticalEnd c;
    c.cause = CriticalEnd::Cause::Tangency;
    c.generator = tangency[j].edge;
    c.triangle = tangency_triangle[j];
    add_roots(base, tangency[j].p, c, zero, one);
  }
  sort_unique(base);

  auto base_valid = [&](const Exact& t) {
    if (t <= 0 || t >= 1) return false;
    for (int k = 1; k <= 2; ++k) {
      const int sd = CGAL::sign(f.den[k](t));
      if (sd == 0) return false;
      const Exact s = f.sn[k](t);
      if (CGAL::sign(s) != sd || CGAL::sign(f.den[k](t) - s) != sd) return false;
    }
    int side[3] = {0, 0, 0};
    for (const auto& tp : tangency) {
      const int s = CGAL::sign(tp.p(t));
      if (s == 0 || (side[tp.edge] != 0 && s != side[tp.edge])) return false;
      side[tp.edge] = s;
    }
    return true;
  };

  // Invalid pieces from a sorted breakpoint list over [b.front(), b.back()]: each open gap decided at a
  // rational sample (the status is constant there), each rational interior breakpoint decided itself.
  // Irrational breakpoints need no decision (docs/theory.md: an irrational parameter is blocked only if an
  // adjacent gap is blocked by the same occluder, so it lies in a closed invalid gap already).
  // `gap_invalid` is only called strictly inside gaps, `invalid_at` at rational breakpoints.
  auto invalid_pieces = [](const std::vector<Breakpoint>& b, auto&& gap_invalid, auto&& invalid_at,
                           std::vector<Invalid>& out) {
    for (std::size_t i = 0; i + 1 < b.size(); ++i) {
      if (gap_invalid(rational_strictly_between(b[i].t, b[i + 1].t)))
        out.push_back({b[i].t, b[i + 1].t, b[i].cause, b[i + 1].cause});
      if (i + 2 < b.size() && b[i + 1].rational && invalid_at(b[i + 1].q))
        out.push_back({b[i + 1].t, b[i + 1].t, b[i + 1].cause, b[i + 1].cause});
    }
  };
  std::vector<Invalid> invalid;
  auto base_invalid = [&](const Exact& t) { return !base_valid(t); };
  invalid_pieces(base, base_invalid, base_invalid, invalid);

  // The hull [vmin, vmax] of the base-valid set: occlusion matters only there.
  std::optional<std::size_t> first_valid, last_valid;
  for (std::size_t i = 0; i + 1 < base.size(); ++i) {
    bool gap_invalid = false;
    for (const auto& iv : invalid)
      if (iv.lo == base[i].t && iv.hi == base[i + 1].t) gap_invalid = true;
    if (!gap_invalid) {
      if (!first_valid) first_valid = i;
      last_valid = i + 1;
    }
  }
  if (!first_valid) return std::nullopt;
  if (stats) ++stats->tangent_triples;
  Breakpoint vmin = base[*first_valid], vmax = base[*last_valid];
  f.compute_line();

  // ---- Occluders: closed scene triangles without E1, E2, E3 as an edge. For base-valid t the generator
  // points lie on P([vmin, vmax]) and on the parts of E2, E3 that Q2, Q3 sweep for t in [vmin, vmax] (when
  // den_k keeps its sign there s_k is monotone, so that part is [s_k(vmin), s_k(vmax)] clipped to [0, 1];
  // else all of E_k), so every generator segment lies in the convex hull of the six points H below:
  // candidates are the triangles meeting H's bounding box (rounded outward), minus those the interval filter
  // proves disjoint from conv(H) (events/eee_occluder_filter.hpp).
  auto swept_part = [&](int k, Vec3<Exact>* lo, Vec3<Exact>* hi) {
    *lo = A[k];
    *hi = B[k];
    const Exact d0 = f.den[k](vmin.q), d1 = f.den[k](vmax.q);
    if (CGAL::sign(d0) == 0 || CGAL::sign(d0) != CGAL::sign(d1)) return;  // den is linear: no root inside
    const Exact s0 = f.sn[k](vmin.q) / d0, s1 = f.sn[k](vmax.q) / d1;
    const Exact a = std::max(Exact(0), std::min(s0, s1)), b = std::min(Exact(1), std::max(s0, s1));
    if (a > b) return;  // cannot happen for a base-valid range; keep the whole edge
    *lo = A[k] + a * f.D[k];
    *hi = A[k] + b * f.D[k];
  };
  std::array<Vec3<Exact>, 6> H{eval(f.P, vmin.q), eval(f.P, vmax.q), A[1], B[1], A[2], B[2]};
  swept_part(1, &H[2], &H[3]);
  swept_part(2, &H[4], &H[5]);
  Box3 box;
  {
    auto down = [](const Exact& x) { const double d = CGAL::to_interval(x).first; return std::nextafter(d, -HUGE_VAL); };
    auto up = [](const Exact& x) { const double d = CGAL::to_interval(x).second; return std::nextafter(d, HUGE_VAL); };
    box.lo = {down(H[0].x), down(H[0].y), down(H[0].z)};
    box.hi = {up(H[0].x), up(H[0].y), up(H[0].z)};
    for (const auto& p : H) {
      box.lo = {std::min(box.lo.x, down(p.x)), std::min(box.lo.y, down(p.y)), std::min(box.lo.z, down(p.z))};
      box.hi = {std::max(box.hi.x, up(p.x)), std::max(box.hi.y, up(p.y)), std::max(box.hi.z, up(p.z))};
    }
  }
  // Normal of plane(P(t), l2) (a VEE line through a point W has W in it).
  const PVec plane_p_l2 = cross(pconst(f.D[1]), f.P - pconst(A[1]));
  // Occluders disjoint from conv(H) block nothing: proved by interval certificates (the filter), the others
  // get the exact analysis below.
  const EeeOccluderFilter hull_filter(H);
  // Occluders that every line L(t) of the current range [vmin, vmax] misses block nothing: proved by the side
  // signs of L(t) against their edge lines in interval arithmetic (events/eee_line_miss_filter.hpp).
  const EeeLineMissFilter line_filter = [&] {
    std::array<std::array<Exact, 3>, 3> d, m;
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) d[k][j] = f.Ld[k].c[j], m[k][j] = f.Lm[k].c[j];
    return EeeLineMissFilter(d, m);
  }();
  // The interval layer of the exact analysis below (events/eee_occluder_pattern.hpp): the same invalid pieces
  // from certified root enclosures and signs, exact roots only where a piece ends.
  const EeeOccluderPatternFilter pattern_filter = [&] {
    auto vec = [](const PVec& v) {
      EeeOccluderPatternFilter::VecPoly r;
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) r[k][j] = v[k].c[j];
      return r;
    };
    auto scalar = [](const Poly& p) { return EeeOccluderPatternFilter::ScalarPoly{p.c[0], p.c[1], p.c[2]}; };
    return EeeOccluderPatternFilter(vec(f.P), vec(f.num[1]), scalar(f.den[1]), vec(f.num[2]), scalar(f.den[2]),
                                    vec(f.Ld), vec(f.Lm));
  }();
  std::pair<double, double> vmin_enclosure = CGAL::to_interval(vmin.t), vmax_enclosure = CGAL::to_interval(vmax.t);
  // Large candidates first (a floating-point heuristic for the order only): every few occluders the free set
  // is recomputed; the search stops when it is empty and later occluders only look inside its hull.
  std::vector<std::pair<double, int>> cand;
  for (int ti : index.triangles_meeting_box(box)) {
    const auto& tr = scene.triangles[ti];
    if (has_edge(tr, E[0]->v) || has_edge(tr, E[1]->v) || has_edge(tr, E[2]->v)) continue;
    const Point3 &p0 = scene.corner(tr, 0), &p1 = scene.corner(tr, 1), &p2 = scene.corner(tr, 2);
    const Point3 cr = cross(p1 - p0, p2 - p0);
    cand.emplace_back(-dot(cr, cr), ti);
  }
  std::sort(cand.begin(), cand.end());
  int since_check = 0;
  for (const auto& [key, ti] : cand) {
    if (since_check >= 4) {
      since_check = 0;
      std::vector<CriticalInterval> comps =
          free_components(invalid, endpoint_end(0, E[0]->v[0]), endpoint_end(0, E[0]->v[1]));
      if (comps.empty()) return std::nullopt;
      vmin = breakpoint_at(comps.front().t0, comps.front().end0);
      vmax = breakpoint_at(comps.back().t1, comps.back().end1);
      vmin_enclosure = CGAL::to_interval(vmin.t);
      vmax_enclosure = CGAL::to_interval(vmax.t);
    }
    const auto& tr = scene.triangles[ti];
    if (hull_filter.separated(scene.corner(tr, 0), scene.corner(tr, 1), scene.corner(tr, 2))) continue;
    if (line_filter.misses(scene.corner(tr, 0), scene.corner(tr, 1), scene.corner(tr, 2),
                           vmin_enclosure.first, vmax_enclosure.second))
      continue;
    if (stats) ++stats->occluder_tests;
    Occluder T{ti, tr.id, tr.v, {}};
    const std::optional<EeeOccluderPattern> pattern = pattern_filter.pattern(
        scene.corner(tr, 0), scene.corner(tr, 1), scene.corner(tr, 2), vmin_enclosure, vmax_enclosure);
    if (pattern && pattern->blocks_nothing() && pattern->verify.empty()) continue;
    if (pattern) {
      const std::size_t before = invalid.size();
      if (add_pattern_pieces(f, T, scene, *pattern, vmin, vmax, invalid)) {
        if (invalid.size() > before) ++since_check;
        continue;
      }
    }
    for (int k = 0; k < 3; ++k) T.c[k] = to_rational(scene.corner(tr, k));
    const Vec3<Exact> n = cross(T.c[1] - T.c[0], T.c[2] - T.c[0]);
    const Exact c = dot(n, T.c[0]);
    std::vector<Breakpoint> b;
    b.push_back(vmin);
    b.push_back(vmax);
    // VEE lines through T's vertices (for the cause; also roots of the edge polynomials below).
    for (int k = 0; k < 3; ++k) {
      const Poly p = dotc(plane_p_l2, T.c[k] - A[1]);
      for (const Root& r : real_roots(p)) {
        if (!(r.t > vmin.t && r.t < vmax.t)) continue;
        const Vec3<Exact> d = eval(f.Ld, r.q), x = T.c[k] - eval(f.P, r.q);
        const Vec3<Exact> z = cross(d, x);
        if (!(CGAL::is_zero(z.x) && CGAL::is_zero(z.y) && CGAL::is_zero(z.z))) continue;
        CriticalEnd cause;
        cause.cause = CriticalEnd::Cause::Occluder;
        cause.triangle = T.id;
        cause.feature.kind = OccluderFeature::Kind::Vertex;
        cause.feature.ids = {T.ids[k]};
        b.push_back({r.t, true, r.q, cause});
      }
    }
    // EEEE lines meeting an edge line of T: side(L(t), edge line) = 0, a quadratic in t.
    std::array<Poly, 3> q, h;
    for (int k = 0; k < 3; ++k) {
      const PluckerLine<Exact> el = line_through(T.c[k], T.c[(k + 1) % 3]);
      q[k] = dotc(f.Ld, el.m) + dotc(f.Lm, el.d);
      CriticalEnd cause;
      cause.cause = CriticalEnd::Cause::Occluder;
      cause.triangle = T.id;
      cause.feature.kind = OccluderFeature::Kind::Edge;
      cause.feature.ids = {T.ids[k], T.ids[(k + 1) % 3]};
      add_roots(b, q[k], cause, vmin.t, vmax.t);
    }
    // A generator point crossing T's plane (the blocked part starts/stops at the segment's end).
    {
      CriticalEnd cause;
      cause.cause = CriticalEnd::Cause::Occluder;
      cause.triangle = T.id;
      cause.feature.kind = OccluderFeature::Kind::Face;
      cause.feature.ids = {T.ids[0], T.ids[1], T.ids[2]};
      for (int k = 0; k < 3; ++k) {
        h[k] = f.height(k, n, c);
        add_roots(b, h[k], cause, vmin.t, vmax.t);
      }
      for (int k = 1; k <= 2; ++k) add_roots(b, f.den[k], singular_end(k), vmin.t, vmax.t);
    }
    sort_unique(b);
    auto blocked = [&](const Exact& t) {
      if (CGAL::is_zero(f.den[1](t)) || CGAL::is_zero(f.den[2](t))) return false;  // base-invalid anyway
      const RationalLine l = rational_line(f, t);
      return open_segment_meets_closed_triangle(l.pts[l.lo], l.pts[l.hi], T.c[0], T.c[1], T.c[2]);
    };
    // Inside a gap L(t) is not in T's plane and the status is the sign function of docs/theory.md: generator
    // points strictly on both sides of the plane, and side signs w.r.t. T's edge lines all >= 0 or all <= 0.
    auto blocked_in_gap = [&](const Exact& t) {
      const int d1 = CGAL::sign(f.den[1](t)), d2 = CGAL::sign(f.den[2](t));
      if (d1 == 0 || d2 == 0) return false;  // not inside a gap
      const int hs[3] = {CGAL::sign(h[0](t)), CGAL::sign(h[1](t)) * d1, CGAL::sign(h[2](t)) * d2};
      const bool above = hs[0] > 0 || hs[1] > 0 || hs[2] > 0, below = hs[0] < 0 || hs[1] < 0 || hs[2] < 0;
      if (!above || !below) return false;
      bool pos = false, neg = false;
      for (int k = 0; k < 3; ++k) {
        const int sk = CGAL::sign(q[k](t));
        pos = pos || sk > 0;
        neg = neg || sk < 0;
      }
      return !(pos && neg);
    };
    const std::size_t before = invalid.size();
    invalid_pieces(b, blocked_in_gap, blocked, invalid);
    if (invalid.size() > before) ++since_check;
  }

  // ---- Free components: [0, 1] minus the union of the closed invalid pieces, components of positive length.
  EeeEvent ev;
  for (int i = 0; i < 3; ++i) ev.edges[i] = E[i]->v;
  ev.intervals = free_components(invalid, endpoint_end(0, E[0]->v[0]), endpoint_end(0, E[0]->v[1]));
  if (ev.intervals.empty()) return std::nullopt;
  for (auto& iv : ev.intervals) {
    iv.sample_t = rational_strictly_between(iv.t0, iv.t1);
    iv.end0.line = eee_end_key(scene, adj, ev, iv.t0, iv.end0);
    iv.end1.line = eee_end_key(scene, adj, ev, iv.t1, iv.end1);
  }
  return ev;
}

EeeLinePoints eee_line_points(const Scene& scene, const EeeEvent& event, const RootNumber& t) {
  std::array<Vec3<Exact>, 3> A, B;
  for (int i = 0; i < 3; ++i) {
    A[i] = to_rational(scene.vertices[event.edges[i][0]]);
    B[i] = to_rational(scene.vertices[event.edges[i][1]]);
  }
  Family f(A, B);
  f.compute_line();
  auto ev = [&](const Poly& p) { return (RootNumber(p.c[2]) * t + RootNumber(p.c[1])) * t + RootNumber(p.c[0]); };
  auto evv = [&](const PVec& v) { return Vec3<RootNumber>(ev(v.x), ev(v.y), ev(v.z)); };
  EeeLinePoints out;
  out.on_e1 = evv(f.P);
  for (int k = 1; k <= 2; ++k) {
    const RootNumber d = ev(f.den[k]);
    if (CGAL::is_zero(d)) continue;
    const Vec3<RootNumber> n = evv(f.num[k]);
    (k == 1 ? out.on_e2 : out.on_e3) = Vec3<RootNumber>(n.x / d, n.y / d, n.z / d);
  }
  out.direction = evv(f.Ld);
  return out;
}

namespace {
Family event_family(const Scene& scene, const EeeEvent& event) {
  std::array<Vec3<Exact>, 3> A, B;
  for (int i = 0; i < 3; ++i) {
    A[i] = to_rational(scene.vertices[event.edges[i][0]]);
    B[i] = to_rational(scene.vertices[event.edges[i][1]]);
  }
  return Family(A, B);
}
}  // namespace

std::optional<EeeGeneratorSegment> eee_generator_segment(const Scene& scene, const EeeEvent& event, const Exact& t) {
  const Family f = event_family(scene, event);
  if (CGAL::is_zero(f.den[1](t)) || CGAL::is_zero(f.den[2](t))) return std::nullopt;
  const RationalLine l = rational_line(f, t);
  return EeeGeneratorSegment{l.pts[l.lo], l.pts[l.hi], l.pts[1] - l.pts[0]};
}

void eee_segment_ends(const Scene& scene, const TriangleIndex& spatial, const Box3& box, EeeEvent& event) {
  const Family f = event_family(scene, event);
  for (auto& iv : event.intervals) {
    const RationalLine l = rational_line(f, iv.sample_t);
    const Vec3<Exact> d = l.pts[1] - l.pts[0];
    // pts[k] is where the line meets edge k's line.
    const auto on = [&](int k) { return RayOriginOnEdgeLine{event.edges[k][0], event.edges[k][1]}; };
    const RayHit front = ray_first_hit(scene, spatial, box, l.pts[l.hi], d, on(l.hi));
    const RayHit back = ray_first_hit(scene, spatial, box, l.pts[l.lo], -d, on(l.lo));
    iv.front_object = front.triangle >= 0 ? scene.triangles[front.triangle].id : -1;
    iv.back_object = back.triangle >= 0 ? scene.triangles[back.triangle].id : -1;
  }
}

std::string root_number_to_string(const RootNumber& x) {
  Exact q;
  if (root_number_rational(x, &q)) return to_rational_string(q);
  // a0 + a1 sqrt(n/d) = a0 + (a1/d) sqrt(n d): written with an integer radicand.
  const Exact r = x.root();
  const Exact c(r.numerator() * r.denominator());
  const Exact b = x.a1() / Exact(r.denominator());
  std::string s = to_rational_string(x.a0());
  s += CGAL::sign(b) < 0 ? "-" : "+";
  s += to_rational_string(CGAL::sign(b) < 0 ? Exact(-b) : b);
  s += "*sqrt(" + to_rational_string(c) + ")";
  return s;
}

}  // namespace exactvis
