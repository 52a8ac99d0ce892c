#include "events/eee_events.hpp"

#include "events/occluder_index.hpp"
#include "events/ray_first_hit.hpp"
#include "kernel/predicates.hpp"
#include "kernel/rational_between.hpp"
#include "kernel/segment_triangle_intersection.hpp"
#include "kernel/spatial_index.hpp"

#include <gmp.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace exactvis {
namespace {

// A polynomial of degree <= 2 in the family parameter t, exact rational coefficients c[0] + c[1] t + c[2] t^2.
// Every quantity of the EEE family used here has degree <= 2 (docs/theory.md section 6).
struct Poly {
  std::array<Exact, 3> c{Exact(0), Exact(0), Exact(0)};
  Poly() = default;
  Poly(int v) { c[0] = Exact(v); }  // NOLINT: Vec3<Poly> default-constructs from 0
  Poly(const Exact& v) { c[0] = v; }  // NOLINT
  static Poly linear(const Exact& c0, const Exact& c1) {
    Poly p;
    p.c[0] = c0;
    p.c[1] = c1;
    return p;
  }
  int degree() const {
    for (int k = 2; k >= 0; --k)
      if (!CGAL::is_zero(c[k])) return k;
    return -1;  // identically zero
  }
  Exact operator()(const Exact& t) const { return (c[2] * t + c[1]) * t + c[0]; }
};
Poly operator+(const Poly& a, const Poly& b) {
  Poly r;
  for (int k = 0; k < 3; ++k) r.c[k] = a.c[k] + b.c[k];
  return r;
}
Poly operator-(const Poly& a, const Poly& b) {
  Poly r;
  for (int k = 0; k < 3; ++k) r.c[k] = a.c[k] - b.c[k];
  return r;
}
Poly operator-(const Poly& a) { return Poly() - a; }
Poly operator*(const Poly& a, const Poly& b) {
  const int da = a.degree(), db = b.degree();
  if (da < 0 || db < 0) return Poly();
  if (da + db > 2) throw std::logic_error("eee_events: polynomial degree above 2");
  Poly r;
  for (int i = 0; i <= da; ++i)
    for (int j = 0; j <= db; ++j) r.c[i + j] += a.c[i] * b.c[j];
  return r;
}

using PVec = Vec3<Poly>;
PVec pconst(const Vec3<Exact>& v) { return {Poly(v.x), Poly(v.y), Poly(v.z)}; }
Vec3<Exact> eval(const PVec& v, const Exact& t) { return {v.x(t), v.y(t), v.z(t)}; }

// One real root of a polynomial: exact, with its rational value when it is rational.
struct Root {
  RootNumber t;
  bool rational = true;
  Exact q;
};

bool perfect_square(const ExactInt& z, ExactInt* root) {
  if (CGAL::sign(z) < 0 || !mpz_perfect_square_p(z.mpz())) return false;
  mpz_t r;
  mpz_init(r);
  mpz_sqrt(r, z.mpz());
  *root = ExactInt(r);
  mpz_clear(r);
  return true;
}

// All distinct real roots of p (none when p is identically zero or constant). Rational roots are returned as
// rational RootNumbers, irrational ones as a0 + a1 sqrt(R) with R a positive non-square integer.
std::vector<Root> real_roots(const Poly& p) {
  std::vector<Root> out;
  const int deg = p.degree();
  auto rational = [&](const Exact& q) { out.push_back({RootNumber(q), true, q}); };
  if (deg == 1) {
    rational(-p.c[0] / p.c[1]);
  } else if (deg == 2) {
    const Exact disc = p.c[1] * p.c[1] - Exact(4) * p.c[2] * p.c[0];
    const int s = CGAL::sign(disc);
    const Exact a0 = -p.c[1] / (Exact(2) * p.c[2]);
    if (s == 0) {
      rational(a0);
    } else if (s > 0) {
      const ExactInt num = disc.numerator(), den = disc.denominator();
      ExactInt rn, rd;
      if (perfect_square(num, &rn) && perfect_square(den, &rd)) {
        const Exact w = Exact(rn) / Exact(rd) / (Exact(2) * p.c[2]);
        rational(a0 - w);
        rational(a0 + w);
      } else {
        // sqrt(num/den) = sqrt(num*den) / den.
        const Exact root(num * den);
        const Exact a1 = Exact(1) / (Exact(den) * Exact(2) * p.c[2]);
        out.push_back({RootNumber(a0, -a1, root), false, Exact(0)});
        out.push_back({RootNumber(a0, a1, root), false, Exact(0)});
      }
    }
  }
  return out;
}

// A parameter where validity may change, with the cause reported if a free interval ends there.
struct Breakpoint {
  RootNumber t;
  bool rational = true;
  Exact q;
  EeeEnd cause;
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
  EeeEnd lo_end, hi_end;
};

EeeEnd endpoint_end(int edge, int vertex) {
  EeeEnd e;
  e.cause = EeeEnd::Cause::EdgeEndpoint;
  e.edge = edge;
  e.vertex = vertex;
  return e;
}

EeeEnd singular_end(int edge) {
  EeeEnd e;
  e.cause = EeeEnd::Cause::Singular;
  e.edge = edge;
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
  PVec Ld, Lm;  // L(t) = line through P(t) then (num2 : den2)

  Family(const std::array<Vec3<Exact>, 3>& a, const std::array<Vec3<Exact>, 3>& b) {
    for (int i = 0; i < 3; ++i) A[i] = a[i], B[i] = b[i], D[i] = b[i] - a[i];
    P = PVec(Poly::linear(A[0].x, D[0].x), Poly::linear(A[0].y, D[0].y), Poly::linear(A[0].z, D[0].z));
    for (int k = 1; k <= 2; ++k) {
      const int o = 3 - k;  // the other edge: Q_k = l_k meets plane(P(t), l_o)
      const PVec n = cross(pconst(D[o]), P - pconst(A[o]));
      den[k] = dot(n, pconst(D[k]));
      sn[k] = -dot(n, pconst(A[k] - A[o]));
      num[k] = den[k] * pconst(A[k]) + sn[k] * pconst(D[k]);
    }
    Ld = num[1] - den[1] * P;
    Lm = cross(P, num[1]);
  }
  // Homogeneous plane-side polynomial of the generator point k (0: P, 1: Q2, 2: Q3) w.r.t. plane n.x = c:
  // its sign times sign(den_k) (den_0 = 1) is the side of the actual point.
  Poly height(int k, const Vec3<Exact>& n, const Exact& c) const {
    if (k == 0) return dot(pconst(n), P) - Poly(c);
    return dot(pconst(n), num[k]) - den[k] * Poly(c);
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

struct Occluder {
  int index;
  std::int64_t id;
  std::array<int, 3> ids;
  std::array<Vec3<Exact>, 3> c;
};

}  // namespace

std::optional<EeeEvent> eee_event(const Scene& scene, const SceneAdjacency& adj, const OccluderIndex& index,
                                  int e1, int e2, int e3, EeeStats* stats) {
  std::array<int, 3> ei{e1, e2, e3};
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
      if (orient3d(A[i], B[i], A[j], B[j]) == Sign::Zero) return std::nullopt;  // coplanar supporting lines
  const Family f(A, B);

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
      tangency.back().edge = i;
    }
  }
  std::vector<std::int64_t> tangency_triangle;
  for (int i = 0; i < 3; ++i)
    for (int ti : E[i]->triangles) tangency_triangle.push_back(scene.triangles[ti].id);

  std::vector<Breakpoint> base;
  base.push_back({RootNumber(0), true, Exact(0), endpoint_end(0, E[0]->v[0])});
  base.push_back({RootNumber(1), true, Exact(1), endpoint_end(0, E[0]->v[1])});
  auto add_roots = [&](std::vector<Breakpoint>& out, const Poly& p, const EeeEnd& cause, const RootNumber& lo,
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
    EeeEnd c;
    c.cause = EeeEnd::Cause::Tangency;
    c.edge = tangency[j].edge;
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
  auto invalid_pieces = [](const std::vector<Breakpoint>& b, auto&& invalid_at, std::vector<Invalid>& out) {
    for (std::size_t i = 0; i + 1 < b.size(); ++i) {
      if (invalid_at(rational_strictly_between(b[i].t, b[i + 1].t)))
        out.push_back({b[i].t, b[i + 1].t, b[i].cause, b[i + 1].cause});
      if (i + 2 < b.size() && b[i + 1].rational && invalid_at(b[i + 1].q))
        out.push_back({b[i + 1].t, b[i + 1].t, b[i + 1].cause, b[i + 1].cause});
    }
  };
  std::vector<Invalid> invalid;
  invalid_pieces(base, [&](const Exact& t) { return !base_valid(t); }, invalid);

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
  const Breakpoint vmin = base[*first_valid], vmax = base[*last_valid];

  // ---- Occluders: closed scene triangles without E1, E2, E3 as an edge, meeting the box of the three edges
  // (which contains every generator segment of a base-valid line).
  Box3 box{scene.vertices[E[0]->v[0]], scene.vertices[E[0]->v[0]]};
  for (int i = 0; i < 3; ++i)
    for (int v : E[i]->v) {
      const Point3& p = scene.vertices[v];
      box.lo = {std::min(box.lo.x, p.x), std::min(box.lo.y, p.y), std::min(box.lo.z, p.z)};
      box.hi = {std::max(box.hi.x, p.x), std::max(box.hi.y, p.y), std::max(box.hi.z, p.z)};
    }
  for (int ti : index.triangles_in_box(box)) {
    const auto& tr = scene.triangles[ti];
    if (has_edge(tr, E[0]->v) || has_edge(tr, E[1]->v) || has_edge(tr, E[2]->v)) continue;
    if (stats) ++stats->occluder_tests;
    Occluder T{ti, tr.id, tr.v, {}};
    for (int k = 0; k < 3; ++k) T.c[k] = to_rational(scene.corner(tr, k));
    const Vec3<Exact> n = cross(T.c[1] - T.c[0], T.c[2] - T.c[0]);
    const Exact c = dot(n, T.c[0]);
    // Quick exact rejection: T strictly on one side of plane(T) is impossible; instead reject when all
    // six edge endpoints lie strictly on one side of T's plane (then so does every generator segment).
    {
      int s0 = 0;
      bool separated = true;
      for (int i = 0; i < 3 && separated; ++i)
        for (const auto* p : {&A[i], &B[i]}) {
          const int s = CGAL::sign(dot(n, *p) - c);
          if (s == 0 || (s0 != 0 && s != s0)) {
            separated = false;
            break;
          }
          s0 = s;
        }
      if (separated) continue;
    }
    std::vector<Breakpoint> b;
    b.push_back(vmin);
    b.push_back(vmax);
    // VEE lines through T's vertices (for the cause; also roots of the edge polynomials below).
    for (int k = 0; k < 3; ++k) {
      const Poly p = dot(cross(pconst(f.D[1]), f.P - pconst(A[1])), pconst(T.c[k] - A[1]));
      for (const Root& r : real_roots(p)) {
        if (!(r.t > vmin.t && r.t < vmax.t)) continue;
        const Vec3<Exact> d = eval(f.Ld, r.q), x = T.c[k] - eval(f.P, r.q);
        const Vec3<Exact> z = cross(d, x);
        if (!(CGAL::is_zero(z.x) && CGAL::is_zero(z.y) && CGAL::is_zero(z.z))) continue;
        EeeEnd cause;
        cause.cause = EeeEnd::Cause::Occluder;
        cause.triangle = T.id;
        cause.feature.kind = OccluderFeature::Kind::Vertex;
        cause.feature.ids = {T.ids[k]};
        b.push_back({r.t, true, r.q, cause});
      }
    }
    // EEEE lines meeting an edge line of T: side(L(t), edge line) = 0, a quadratic in t.
    for (int k = 0; k < 3; ++k) {
      const PluckerLine<Exact> el = line_through(T.c[k], T.c[(k + 1) % 3]);
      const Poly q = dot(f.Ld, pconst(el.m)) + dot(pconst(el.d), f.Lm);
      EeeEnd cause;
      cause.cause = EeeEnd::Cause::Occluder;
      cause.triangle = T.id;
      cause.feature.kind = OccluderFeature::Kind::Edge;
      cause.feature.ids = {T.ids[k], T.ids[(k + 1) % 3]};
      add_roots(b, q, cause, vmin.t, vmax.t);
    }
    // A generator point crossing T's plane (the blocked part starts/stops at the segment's end).
    {
      EeeEnd cause;
      cause.cause = EeeEnd::Cause::Occluder;
      cause.triangle = T.id;
      cause.feature.kind = OccluderFeature::Kind::Face;
      cause.feature.ids = {T.ids[0], T.ids[1], T.ids[2]};
      for (int k = 0; k < 3; ++k) add_roots(b, f.height(k, n, c), cause, vmin.t, vmax.t);
      for (int k = 1; k <= 2; ++k) add_roots(b, f.den[k], singular_end(k), vmin.t, vmax.t);
    }
    sort_unique(b);
    auto blocked = [&](const Exact& t) {
      if (CGAL::is_zero(f.den[1](t)) || CGAL::is_zero(f.den[2](t))) return false;  // base-invalid anyway
      const RationalLine l = rational_line(f, t);
      return open_segment_meets_closed_triangle(l.pts[l.lo], l.pts[l.hi], T.c[0], T.c[1], T.c[2]);
    };
    invalid_pieces(b, blocked, invalid);
  }

  // ---- Free components: [0, 1] minus the union of the closed invalid pieces, components of positive length.
  std::sort(invalid.begin(), invalid.end(), [](const Invalid& x, const Invalid& y) { return x.lo < y.lo; });
  EeeEvent ev;
  for (int i = 0; i < 3; ++i) ev.edges[i] = E[i]->v;
  RootNumber pos(0);
  EeeEnd pos_end = endpoint_end(0, E[0]->v[0]);
  auto emit = [&](const RootNumber& t1, const EeeEnd& end1) {
    EeeInterval iv;
    iv.t0 = pos;
    iv.t1 = t1;
    iv.end0 = pos_end;
    iv.end1 = end1;
    iv.sample_t = rational_strictly_between(pos, t1);
    ev.intervals.push_back(std::move(iv));
  };
  for (const auto& iv : invalid) {
    if (iv.lo > pos) emit(iv.lo, iv.lo_end);
    if (iv.hi >= pos) {
      pos = iv.hi;
      pos_end = iv.hi_end;
    }
  }
  if (pos < one) emit(one, endpoint_end(0, E[0]->v[1]));
  if (ev.intervals.empty()) return std::nullopt;
  return ev;
}

EeeLinePoints eee_line_points(const Scene& scene, const EeeEvent& event, const RootNumber& t) {
  std::array<Vec3<Exact>, 3> A, B;
  for (int i = 0; i < 3; ++i) {
    A[i] = to_rational(scene.vertices[event.edges[i][0]]);
    B[i] = to_rational(scene.vertices[event.edges[i][1]]);
  }
  const Family f(A, B);
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

void eee_segment_ends(const Scene& scene, const SpatialIndex& spatial, const Box3& box, EeeEvent& event) {
  std::array<Vec3<Exact>, 3> A, B;
  for (int i = 0; i < 3; ++i) {
    A[i] = to_rational(scene.vertices[event.edges[i][0]]);
    B[i] = to_rational(scene.vertices[event.edges[i][1]]);
  }
  const Family f(A, B);
  for (auto& iv : event.intervals) {
    const RationalLine l = rational_line(f, iv.sample_t);
    const Vec3<Exact> d = l.pts[1] - l.pts[0];
    const RayHit front = ray_first_hit(scene, spatial, box, l.pts[l.hi], d);
    const RayHit back = ray_first_hit(scene, spatial, box, l.pts[l.lo], -d);
    iv.end_object_front = front.triangle >= 0 ? scene.triangles[front.triangle].id : -1;
    iv.end_object_back = back.triangle >= 0 ? scene.triangles[back.triangle].id : -1;
  }
}

std::string root_number_to_string(const RootNumber& x) {
  Exact q;
  if (root_number_rational(x, &q)) return to_rational_string(q);
  std::string s = to_rational_string(x.a0());
  const Exact b = x.a1();
  s += CGAL::sign(b) < 0 ? "-" : "+";
  s += to_rational_string(CGAL::sign(b) < 0 ? Exact(-b) : b);
  s += "*sqrt(" + to_rational_string(x.root()) + ")";
  return s;
}

}  // namespace exactvis
