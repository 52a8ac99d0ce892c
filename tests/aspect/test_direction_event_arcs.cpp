// The occlusion-free event arcs of the orthographic aspect graph (aspect/direction_event_arcs) against an
// oracle of the test's own (tests/oracles geometry only): the critical line at a parameter is built
// independently (EV: through V and the edge point; EEE: the point of E2's line on the plane through P(t) and
// E3's line, then checked to meet E3's line by the oracle's Plücker side), and it is free for a viewer along
// +D iff the segment from its farthest generator point to a point beyond the whole scene crosses no triangle's
// interior (oracle_segment_crosses_triangle_interior). Soundness: random parameters inside every reported
// arc give free lines along the arc's direction. Completeness: random parameters of every family whose line
// is free in one orientation lie in a reported arc of that orientation.
#include "aspect/direction_event_arcs.hpp"

#include "tests/aspect/aspect_test_models.hpp"
#include "tests/exact_to_mpq.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <tuple>

namespace {

using namespace exactvis;
using namespace exactvis::aspect_test;
using exact_to_mpq::q;
using exact_to_mpq::qv;
using oracle::QVec;

// Three triangles in the planes z = 0, 1, 2 whose edges E1 (along x), E2 (along y) and E3 (diagonal) are
// pairwise skew and all met by the vertical line x = y = 0: a free EEE family.
Scene three_skew_edges() {
  return make_scene({{-1, 0, 0}, {1, 0, 0}, {0, -3, 0}, {0, -1, 1}, {0, 1, 1}, {3, 0, 1}, {-1, -1, 2}, {1, 1, 2}, {2, -2, 2}},
                    {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
}

QVec vq(const Scene& s, int id) { return oracle::qvec(s.vertices[id].x, s.vertices[id].y, s.vertices[id].z); }

struct OracleLine {
  QVec p, d;                       // the line {p + lambda d}
  std::vector<mpq_class> gens;     // positions of its generator points
  std::vector<int> vertex;         // per generator: a vertex id (EV's V) or -1
  std::vector<std::array<int, 2>> edge;  // per generator: its edge (vertex ids) when vertex == -1
};

// The triangles (indices) having both ids of `e` / having vertex id v.
std::vector<int> incident(const Scene& s, std::initializer_list<int> ids) {
  std::vector<int> out;
  for (std::size_t m = 0; m < s.triangles.size(); ++m) {
    bool all = true;
    for (int id : ids) all &= std::find(s.triangles[m].v.begin(), s.triangles[m].v.end(), id) != s.triangles[m].v.end();
    if (all) out.push_back(static_cast<int>(m));
  }
  return out;
}

// The line pierces the surface of the triangles at a generator: at an edge with exactly two triangles, their
// third corners strictly on both sides of the plane through the edge and d (the oracle's orient3d); at a
// vertex, every point of a small ring around it in the plane orthogonal to d has its parallel line meeting a
// triangle of the vertex's fan (the fan's image covers a neighbourhood of the vertex's image).
bool oracle_pierced(const Scene& s, const OracleLine& l, std::size_t g) {
  if (l.vertex[g] < 0) {
    const auto tris = incident(s, {l.edge[g][0], l.edge[g][1]});
    if (tris.size() != 2) return false;
    const QVec a = vq(s, l.edge[g][0]), b = vq(s, l.edge[g][1]);
    int sg[2];
    for (int k = 0; k < 2; ++k) {
      const auto& t = s.triangles[tris[k]];
      int c = 0;
      while (t.v[c] == l.edge[g][0] || t.v[c] == l.edge[g][1]) ++c;
      sg[k] = oracle::orient3d(a, b, a + l.d, vq(s, t.v[c]));
    }
    return sg[0] * sg[1] < 0;
  }
  const QVec v = vq(s, l.vertex[g]);
  const QVec axis = l.d.x != 0 || l.d.y != 0 ? QVec{0, 0, 1} : QVec{1, 0, 0};
  const QVec e1 = cross(l.d, axis), e2 = cross(l.d, e1);
  const mpq_class eps(1, 1 << 20);
  const mpq_class n1 = abs(e1.x) + abs(e1.y) + abs(e1.z), n2 = abs(e2.x) + abs(e2.y) + abs(e2.z);
  const mpq_class dn = abs(l.d.x) + abs(l.d.y) + abs(l.d.z);
  const auto fan = incident(s, {l.vertex[g]});
  for (int i : {-1, 0, 1})
    for (int j : {-1, 0, 1}) {
      if (i == 0 && j == 0) continue;
      const QVec x = v + mpq_class(i) * (eps / n1) * e1 + mpq_class(j) * (eps / n2) * e2;
      const QVec lo = x - (mpq_class(1000) / dn) * l.d, hi = x + (mpq_class(1000) / dn) * l.d;
      bool hit = false;
      for (int f : fan) {
        const auto& t = s.triangles[f];
        hit |= oracle::oracle_closed_segment_meets_closed_triangle(lo, hi, vq(s, t.v[0]), vq(s, t.v[1]), vq(s, t.v[2]));
      }
      if (!hit) return false;
    }
  return true;
}

// Free for a viewer along +o d: from the farthest generator, beyond everything.
bool oracle_free(const Scene& s, const OracleLine& l, int o) {
  mpq_class reach = 1;
  for (const auto& p : s.vertices) reach += abs(mpq_class(p.x)) + abs(mpq_class(p.y)) + abs(mpq_class(p.z));
  const QVec d = mpq_class(o) * l.d;
  const mpq_class dn = abs(d.x) + abs(d.y) + abs(d.z);
  mpq_class far = o > 0 ? *std::min_element(l.gens.begin(), l.gens.end()) : *std::max_element(l.gens.begin(), l.gens.end());
  const QVec from = l.p + far * l.d;
  const QVec to = from + (4 * reach / dn) * d;
  for (std::size_t g = 0; g < l.gens.size(); ++g)
    if (l.gens[g] != far && oracle_pierced(s, l, g)) return false;
  for (const auto& u : oracle_model(s))
    if (oracle::oracle_segment_crosses_triangle_interior(from, to, u[0], u[1], u[2])) return false;
  return true;
}

std::optional<OracleLine> oracle_ev(const Scene& s, int v, const std::array<int, 2>& e, const mpq_class& t) {
  const QVec V = vq(s, v), a = vq(s, e[0]), b = vq(s, e[1]);
  const QVec p = a + t * (b - a);
  return OracleLine{V, p - V, {0, 1}, {v, -1}, {std::array<int, 2>{}, e}};
}

std::optional<OracleLine> oracle_eee(const Scene& s, const std::array<std::array<int, 2>, 3>& es, const mpq_class& t) {
  const QVec a1 = vq(s, es[0][0]), b1 = vq(s, es[0][1]);
  const QVec p = a1 + t * (b1 - a1);
  // Q_j on line j in the plane through p and the other line k.
  std::array<QVec, 3> qpt;
  std::array<mpq_class, 3> sj;
  for (int j = 1; j < 3; ++j) {
    const int k = 3 - j;
    const QVec aj = vq(s, es[j][0]), uj = vq(s, es[j][1]) - aj;
    const QVec ak = vq(s, es[k][0]), uk = vq(s, es[k][1]) - ak;
    const QVec nk = cross(uk, ak - p);
    const mpq_class den = dot(nk, uj);
    if (den == 0) return std::nullopt;
    sj[j] = dot(nk, p - aj) / den;
    qpt[j] = aj + sj[j] * uj;
  }
  for (int j = 1; j < 3; ++j)
    if (sj[j] <= 0 || sj[j] >= 1) return std::nullopt;
  const QVec d = qpt[1] - p;
  if (oracle::is_zero(d) || oracle::is_zero(cross(d, qpt[2] - p))) {
    if (oracle::is_zero(d)) return std::nullopt;
  }
  // The line through p and Q2 must meet line 3 at Q3 (Plücker side zero), and Q3 lie on it.
  const oracle::QLine l = oracle::line_through(p, qpt[1]);
  const oracle::QLine l3 = oracle::line_through(vq(s, es[2][0]), vq(s, es[2][1]));
  EXPECT_EQ(oracle::side(l, l3), 0);
  EXPECT_TRUE(oracle::is_zero(cross(d, qpt[2] - p)));
  const mpq_class g3 = dot(qpt[2] - p, d) / dot(d, d);
  return OracleLine{p, d, {0, 1, g3}, {-1, -1, -1}, {es[0], es[1], es[2]}};
}

using Key = std::tuple<int, int, int, int, int, int, int>;  // vertex or -1, edges
Key key_of(const DirectionEventArc& a) {
  if (a.type == DirectionEventArc::Type::EV) return {a.vertex, a.edges[0][0], a.edges[0][1], -1, -1, -1, -1};
  return {-1, a.edges[0][0], a.edges[0][1], a.edges[1][0], a.edges[1][1], a.edges[2][0], a.edges[2][1]};
}

bool positively_parallel(const QVec& a, const QVec& b) { return oracle::is_zero(cross(a, b)) && dot(a, b) > 0; }

// t in [t0, t1] (exact comparisons only).
bool in_arc(const DirectionEventArc& a, const Exact& t) {
  const RootNumber r(t);
  return !(r < a.t0) && !(a.t1 < r);
}

void check_soundness(const Scene& s, const DirectionEventArcs& arcs, unsigned seed) {
  std::mt19937 rng(seed);
  for (const auto& a : arcs.arcs) {
    EXPECT_TRUE(a.t0 < a.t1);
    ASSERT_TRUE(in_arc(a, a.sample_t));
    std::vector<Exact> ts{a.sample_t};
    // Points between the sample and a rational end.
    Exact e;
    for (const RootNumber* end : {&a.t0, &a.t1})
      if (CGAL::is_zero(end->a1())) {
        e = end->a0();
        ts.push_back((a.sample_t + e) / Exact(2));
        ts.push_back((Exact(7) * a.sample_t + e) / Exact(8));
      }
    for (const Exact& t : ts) {
      const auto line = a.type == DirectionEventArc::Type::EV ? oracle_ev(s, a.vertex, a.edges[0], q(t))
                                                              : oracle_eee(s, a.edges, q(t));
      ASSERT_TRUE(line.has_value());
      const QVec dir = qv(arc_direction(s, a, t));
      EXPECT_TRUE(positively_parallel(dir, line->d) || positively_parallel(dir, mpq_class(-1) * line->d));
      const int o = dot(dir, line->d) > 0 ? 1 : -1;
      EXPECT_TRUE(oracle_free(s, *line, o)) << (a.type == DirectionEventArc::Type::EV ? "EV" : "EEE") << " t=" << t;
    }
  }
}

// Random parameters of every family: a free line must lie in a reported arc of its orientation.
void check_completeness(const Scene& s, const DirectionEventArcs& arcs, unsigned seed, bool eee, int per_family) {
  std::map<Key, std::vector<const DirectionEventArc*>> by;
  for (const auto& a : arcs.arcs) by[key_of(a)].push_back(&a);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> num(1, 96);
  std::set<std::array<int, 2>> es;
  std::set<int> vs;
  for (const auto& t : s.triangles)
    for (int k = 0; k < 3; ++k) {
      vs.insert(t.v[k]);
      es.insert({std::min(t.v[k], t.v[(k + 1) % 3]), std::max(t.v[k], t.v[(k + 1) % 3])});
    }
  const std::vector<std::array<int, 2>> edges(es.begin(), es.end());
  auto check = [&](const Key& k, const std::optional<OracleLine>& line, const Exact& t, const char* what) {
    if (!line) return;
    for (int o : {1, -1}) {
      if (!oracle_free(s, *line, o)) continue;
      bool found = false;
      for (const DirectionEventArc* a : by[k])
        if (in_arc(*a, t) && positively_parallel(qv(arc_direction(s, *a, t)), mpq_class(o) * line->d)) found = true;
      EXPECT_TRUE(found) << what << " free line not reported, t=" << t << " o=" << o;
    }
  };
  std::size_t ev_checked = 0, eee_checked = 0;
  for (int v : vs)
    for (const auto& e : edges) {
      const QVec V = vq(s, v), a = vq(s, e[0]), b = vq(s, e[1]);
      if (oracle::is_zero(cross(a - V, b - V))) continue;
      for (int r = 0; r < per_family; ++r) {
        const Exact t(num(rng), 97);
        check({v, e[0], e[1], -1, -1, -1, -1}, oracle_ev(s, v, e, q(t)), t, "EV");
        ++ev_checked;
      }
    }
  if (eee)
    for (std::size_t i = 0; i < edges.size(); ++i)
      for (std::size_t j = i + 1; j < edges.size(); ++j)
        for (std::size_t k = j + 1; k < edges.size(); ++k) {
          const std::array<std::array<int, 2>, 3> t3{edges[i], edges[j], edges[k]};
          bool coplanar = false;
          for (int x = 0; x < 3; ++x)
            for (int y = x + 1; y < 3; ++y)
              coplanar |= oracle::orient3d(vq(s, t3[x][0]), vq(s, t3[x][1]), vq(s, t3[y][0]), vq(s, t3[y][1])) == 0;
          if (coplanar) continue;
          for (int r = 0; r < per_family; ++r) {
            const Exact t(num(rng), 97);
            const auto line = oracle_eee(s, t3, q(t));
            if (line) ++eee_checked;
            check({-1, t3[0][0], t3[0][1], t3[1][0], t3[1][1], t3[2][0], t3[2][1]}, line, t, "EEE");
          }
        }
  EXPECT_GT(ev_checked, 0u);
  if (eee) {
    EXPECT_GT(eee_checked, 0u);
  }
}

TEST(DirectionEventArcs, EvArcsOfHandModelsAreSoundAndComplete) {
  unsigned seed = 1;
  for (const Scene& s : {cube(), l_prism(), two_boxes(), notched_box(), three_boxes()}) {
    DirectionEventOptions o;
    o.eee = false;
    const DirectionEventArcs arcs = direction_event_arcs(s, o);
    EXPECT_GT(arcs.arcs.size(), 0u);
    check_soundness(s, arcs, seed);
    check_completeness(s, arcs, seed, false, 3);
    ++seed;
  }
}

TEST(DirectionEventArcs, CubeArcsLieInFacePlanes) {
  // A convex model: the free EV lines are those in face planes (V and E on one face of [-1, 1]^3, i.e. all
  // three points share a coordinate equal to +-1), each free over all of [0, 1] in both orientations; a
  // line through V and the far side of the cube enters the solid at a generator (pierced) and is not free.
  const Scene s = cube();
  DirectionEventOptions o;
  o.eee = false;
  const auto arcs = direction_event_arcs(s, o);
  ASSERT_GT(arcs.arcs.size(), 0u);
  for (const auto& a : arcs.arcs) {
    const Point3 &v = s.vertices[a.vertex], &p = s.vertices[a.edges[0][0]], &r = s.vertices[a.edges[0][1]];
    bool face = false;
    for (int k = 0; k < 3; ++k) face |= std::abs(v[k]) == 1 && v[k] == p[k] && p[k] == r[k];
    EXPECT_TRUE(face) << a.vertex << " " << a.edges[0][0] << "-" << a.edges[0][1];
    EXPECT_TRUE(a.t0 == RootNumber(Exact(0)) && a.t1 == RootNumber(Exact(1)));
  }
}

TEST(DirectionEventArcs, EeeArcsOfSmallModelsAreSoundAndComplete) {
  unsigned seed = 11;
  for (const Scene& s : {three_skew_edges(), l_prism(), two_boxes()}) {
    const DirectionEventArcs arcs = direction_event_arcs(s);
    std::size_t eee = 0;
    for (const auto& a : arcs.arcs) eee += a.type == DirectionEventArc::Type::EEE;
    EXPECT_GT(arcs.eee_valid_triples, 0u);
    check_soundness(s, arcs, seed);
    check_completeness(s, arcs, seed, true, 2);
    ++seed;
    if (seed == 12) EXPECT_GT(eee, 0u);  // the skew edges' family is free (both orientations)
  }
}

}  // namespace

namespace {

TEST(DirectionEventArcs, ParallelRunEqualsTheSequentialOne) {
  const Scene s = exactvis::aspect_test::l_prism();
  exactvis::DirectionEventOptions seq, par;
  seq.parallel = false;
  const auto a = exactvis::direction_event_arcs(s, seq), b = exactvis::direction_event_arcs(s, par);
  ASSERT_EQ(a.arcs.size(), b.arcs.size());
  EXPECT_EQ(a.ev_pairs, b.ev_pairs);
  EXPECT_EQ(a.eee_valid_triples, b.eee_valid_triples);
  for (std::size_t i = 0; i < a.arcs.size(); ++i) {
    EXPECT_EQ(key_of(a.arcs[i]), key_of(b.arcs[i]));
    EXPECT_EQ(a.arcs[i].orientation, b.arcs[i].orientation);
    EXPECT_TRUE(a.arcs[i].t0 == b.arcs[i].t0 && a.arcs[i].t1 == b.arcs[i].t1);
    EXPECT_EQ(a.arcs[i].sample_t, b.arcs[i].sample_t);
  }
}

}  // namespace
