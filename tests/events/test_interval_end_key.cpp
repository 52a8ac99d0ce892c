// The key of every interval end (events/interval_end_key.hpp) names its line: on generic scenes, two ends
// have equal keys iff their lines are equal, whichever families (EV or EEE) they come from. The oracle is
// exact line equality (normalised Plücker coordinates compared exactly, also across square roots), which
// shares nothing with how keys are built. A scene built for it reaches one VEE line from an EV end, from an
// EEE end and by direct construction.
#include "events/eee_enumeration.hpp"
#include "events/ev_events.hpp"
#include "events/interval_end_key.hpp"
#include "kernel/predicates.hpp"
#include "tests/events/event_test_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace exactvis {
namespace {

using Coords = std::array<RootNumber, 6>;

Coords normalised(const Vec3<RootNumber>& d, const Vec3<RootNumber>& p) {
  const Vec3<RootNumber> m = cross(p, d);
  Coords c{d.x, d.y, d.z, m.x, m.y, m.z};
  for (int i = 0; i < 6; ++i)
    if (!CGAL::is_zero(c[i])) {
      const RootNumber f = c[i];
      for (int j = 0; j < 6; ++j) c[j] = c[j] / f;
      break;
    }
  return c;
}

bool same_line(const Coords& a, const Coords& b) {
  for (int i = 0; i < 6; ++i)
    if (a[i] < b[i] || b[i] < a[i]) return false;
  return true;
}

Vec3<RootNumber> root_vec(const Vec3<Exact>& v) { return {RootNumber(v.x), RootNumber(v.y), RootNumber(v.z)}; }

struct End {
  ExtremalLineKey key;
  Coords line;
  std::array<double, 6> approx;
  std::string where;
  bool ev;
};

std::vector<End> all_ends(const Scene& s, const EvResult& ev, const EeeResult& eee) {
  std::vector<End> out;
  auto add = [&](const ExtremalLineKey& key, const Coords& c, std::string where, bool is_ev) {
    End e{key, c, {}, std::move(where), is_ev};
    for (int i = 0; i < 6; ++i) e.approx[i] = CGAL::to_double(c[i]);
    out.push_back(std::move(e));
  };
  for (const auto& e : ev.events) {
    const Vec3<Exact> V = to_rational(s.vertices[e.vertex]);
    for (const auto& iv : e.intervals)
      for (const auto* end : {&iv.end0, &iv.end1}) {
        const Exact t = rational_parameter(end == &iv.end0 ? iv.t0 : iv.t1);
        add(end->line, normalised(root_vec(ev_edge_point(s, e.edge, t) - V), root_vec(V)),
            "EV v" + std::to_string(e.vertex) + " e[" + std::to_string(e.edge[0]) + "," + std::to_string(e.edge[1]) +
                "] t=" + to_rational_string(t),
            true);
      }
  }
  for (const auto& e : eee.events)
    for (const auto& iv : e.intervals)
      for (const auto* end : {&iv.end0, &iv.end1}) {
        const RootNumber& t = end == &iv.end0 ? iv.t0 : iv.t1;
        const EeeLinePoints l = eee_line_points(s, e, t);
        std::string where = "EEE";
        for (const auto& ed : e.edges) where += " [" + std::to_string(ed[0]) + "," + std::to_string(ed[1]) + "]";
        add(end->line, normalised(l.direction, l.on_e1), where + " t=" + root_number_to_string(t), false);
      }
  return out;
}

struct Matches {
  int ev_ev = 0, ev_eee = 0, eee_eee = 0;
};

// Checks key equality <=> line equality over all pairs of ends; counts the pairs of equal lines.
Matches check_keys_name_lines(const std::vector<End>& ends, const std::string& scene) {
  Matches m;
  // Equal keys -> equal lines.
  std::map<ExtremalLineKey, std::size_t> first;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const auto [it, fresh] = first.emplace(ends[i].key, i);
    if (!fresh) {
      EXPECT_TRUE(same_line(ends[it->second].line, ends[i].line))
          << scene << ": key " << to_string(ends[i].key) << " names two lines: " << ends[it->second].where << " and "
          << ends[i].where;
    }
  }
  // Equal lines -> equal keys: candidates from the sorted approximations, decided exactly.
  std::vector<std::size_t> order(ends.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ends[a].approx < ends[b].approx; });
  for (std::size_t a = 0; a < order.size(); ++a)
    for (std::size_t b = a + 1; b < order.size(); ++b) {
      const End &x = ends[order[a]], &y = ends[order[b]];
      if (std::abs(y.approx[0] - x.approx[0]) > 1e-6 * (1 + std::abs(x.approx[0]))) break;
      if (!same_line(x.line, y.line)) continue;
      EXPECT_EQ(x.key, y.key) << scene << ": one line, keys " << to_string(x.key) << " (" << x.where << ") and "
                              << to_string(y.key) << " (" << y.where << ")";
      (x.ev && y.ev ? m.ev_ev : x.ev != y.ev ? m.ev_eee : m.eee_eee) += 1;
    }
  return m;
}

TEST(IntervalEndKey, EqualKeysIffEqualLinesOnGenericScenes) {
  Matches total;
  std::map<ExtremalLineKind, int> kinds;
  for (unsigned seed = 1; seed <= 2; ++seed) {
    const Scene s = event_test::random_soup(seed, 6, 1000000);
    EvOptions evo;
    evo.parallel = false;
    EeeOptions eo;
    eo.parallel = false;
    const EvResult ev = enumerate_ev_events(s, evo);
    const EeeResult eee = enumerate_eee_events(s, eo);
    const std::vector<End> ends = all_ends(s, ev, eee);
    for (const auto& e : ends) ++kinds[e.key.kind];
    const Matches m = check_keys_name_lines(ends, "soup " + std::to_string(seed));
    total.ev_ev += m.ev_ev;
    total.ev_eee += m.ev_eee;
    total.eee_eee += m.eee_eee;
  }
  // The scenes exercise lines found by several families, of both kinds.
  EXPECT_GT(total.ev_ev, 20);
  EXPECT_GT(total.ev_eee, 5);
  EXPECT_GT(total.eee_eee, 5);
  for (const auto k : {ExtremalLineKind::VV, ExtremalLineKind::VEE, ExtremalLineKind::EEEE})
    EXPECT_GT(kinds[k], 0) << kind_name(k);
}

// V = (0, 0, 0) a corner of a triangle; E1 = [3, 4] at y = 2, z = 1; E2 = [6, 7] at y = 4, x = 1/2. The line
// through V, (1/4, 2, 1) on E1 and (1/2, 4, 2) on E2 is a VEE line: it ends an EV interval of (V, E2) (T1
// blocks the wedge above E1) and an EEE interval of (E0, E1, E2) for the edges E0 of V's triangle (the
// family's lines through the points of E0 near V).
TEST(IntervalEndKey, OneVeeLineFromEvEeeAndDirectConstruction) {
  const Scene s = event_test::make_scene(
      {{0, 0, 0}, {0.2, -1, -0.5}, {-0.3, -1, 0.4},   // T0: V = 0
       {-1, 2, 1}, {1, 2, 1}, {0, 2, 3},              // T1: E1 = [3, 4]
       {0.5, 4, 1}, {0.5, 4, 3}, {3, 4, 2}},          // T2: E2 = [6, 7]
      {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
  const ExtremalLineKey key = vee_key(0, {3, 4}, {6, 7});
  const EvResult ev = enumerate_ev_events(s);
  const EeeResult eee = enumerate_eee_events(s);
  const std::vector<End> ends = all_ends(s, ev, eee);
  const Coords expected = normalised(root_vec(Vec3<Exact>(Exact(1, 4), Exact(2), Exact(1))), root_vec(Vec3<Exact>(0, 0, 0)));
  int from_ev = 0, from_eee = 0;
  for (const auto& e : ends) {
    if (e.key != key) continue;
    EXPECT_TRUE(same_line(e.line, expected)) << e.where;
    (e.ev ? from_ev : from_eee) += 1;
  }
  EXPECT_GE(from_ev, 1);
  EXPECT_GE(from_eee, 1);
  check_keys_name_lines(ends, "built VEE scene");
}

}  // namespace
}  // namespace exactvis
