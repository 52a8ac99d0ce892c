#include "events/eee_enumeration.hpp"

#include "events/eee_prefilter.hpp"
#include "kernel/segment_tetrahedron_intersection.hpp"
#include "kernel/triangle_index.hpp"
#include "util/for_each_index.hpp"
#include "util/progress_bar.hpp"

#include <CGAL/Interval_nt.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace exactvis {
namespace {

using Triple = std::array<int, 3>;
using I = CGAL::Interval_nt<>;

Triple sorted(int a, int b, int c) {
  Triple t{a, b, c};
  std::sort(t.begin(), t.end());
  return t;
}

// A box containing every point X of the scene box `box` for which some segment [P, X], P on edge `from`,
// passes through edge `mid` (X beyond mid as seen from P): the "shadow" of mid lit by `from`. With
// X = P + λ (Q - P), Q on mid, λ >= 1: λ <= diam(box) / dist(lines) =: Λ for X in the box, and the points with
// 1 <= λ <= Λ lie in the hull of mid and the four points P_a + Λ (Q_b - P_a) (corners move affinely in λ).
// Computed in interval arithmetic, rounded outwards. Requires the supporting lines to be skew.
Box3 shadow_box(const Scene& scene, const SceneEdge& from, const SceneEdge& mid, const Box3& box) {
  auto iv = [](const Point3& p) { return std::array<I, 3>{I(p.x), I(p.y), I(p.z)}; };
  const auto p0 = iv(scene.vertices[from.v[0]]), p1 = iv(scene.vertices[from.v[1]]);
  const auto q0 = iv(scene.vertices[mid.v[0]]), q1 = iv(scene.vertices[mid.v[1]]);
  std::array<I, 3> u, v, w;
  for (int k = 0; k < 3; ++k) u[k] = p1[k] - p0[k], v[k] = q1[k] - q0[k], w[k] = q0[k] - p0[k];
  const std::array<I, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const I det = n[0] * w[0] + n[1] * w[1] + n[2] * w[2];  // dist(lines) = |det| / |n|
  const I n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  const I diam2 = CGAL::square(I(box.hi.x) - I(box.lo.x)) + CGAL::square(I(box.hi.y) - I(box.lo.y)) +
                  CGAL::square(I(box.hi.z) - I(box.lo.z));
  const I det2 = CGAL::square(det);
  if (!(det2.inf() > 0)) return box;  // cannot bound λ: the whole box
  const double lambda = CGAL::sqrt(diam2 * n2 / det2).sup() + 1.0;
  if (!std::isfinite(lambda)) return box;
  std::array<double, 3> lo{}, hi{};
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min(q0[k].inf(), q1[k].inf());
    hi[k] = std::max(q0[k].sup(), q1[k].sup());
  }
  for (const auto* p : {&p0, &p1})
    for (const auto* q : {&q0, &q1})
      for (int k = 0; k < 3; ++k) {
        const I y = (*p)[k] + I(lambda) * ((*q)[k] - (*p)[k]);
        lo[k] = std::min(lo[k], y.inf());
        hi[k] = std::max(hi[k], y.sup());
      }
  return intersection({{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}, box);
}

}  // namespace

std::vector<Triple> eee_candidate_triples(const Scene& scene, const SceneAdjacency& adj, const EdgeIndex& edges,
                                          const EeeOptions& options, EeeEnumerationStats* stats) {
  const int m = static_cast<int>(adj.edges.size());
  std::vector<char> is_light(m, 0);
  std::vector<int> light_edges;
  for (int ti : options.light_triangles) {
    const auto& t = scene.triangles.at(ti);
    for (int k = 0; k < 3; ++k) {
      const int e = adj.edge_index(t.v[k], t.v[(k + 1) % 3]);
      if (e >= 0 && !is_light[e]) is_light[e] = 1, light_edges.push_back(e);
    }
  }
  std::sort(light_edges.begin(), light_edges.end());
  const bool restricted = !options.light_triangles.empty();
  const Box3 box = bounding_box(scene);
  auto P = [&](int e, int k) -> const Point3& { return scene.vertices[adj.edges[e].v[k]]; };

  struct Local {
    std::vector<Triple> triples;
    std::uint64_t pairs = 0, kept = 0;
  };
  tbb::enumerable_thread_specific<Local> locals;
  // Outer pair (i, j): middle edges from the tetrahedron query, each checked against both outers.
  auto outer_pair = [&](Local& loc, int i, int j) {
    ++loc.pairs;
    if (!eee_pair_possible(scene, adj.edges[i], adj.edges[j])) return;
    ++loc.kept;
    for (int k : edges.edges_meeting_tetrahedron(P(i, 0), P(i, 1), P(j, 0), P(j, 1))) {
      if (k == i || k == j) continue;
      if (!eee_pair_possible(scene, adj.edges[k], adj.edges[i]) ||
          !eee_pair_possible(scene, adj.edges[k], adj.edges[j]))
        continue;
      loc.triples.push_back(sorted(i, j, k));
    }
  };
  // Outer i and light middle l: the other outer from the shadow box of l lit by i, checked exactly.
  auto light_middle = [&](Local& loc, int i, int l) {
    ++loc.pairs;
    if (!eee_pair_possible(scene, adj.edges[i], adj.edges[l])) return;
    ++loc.kept;
    for (int j : edges.edges_meeting_box(shadow_box(scene, adj.edges[i], adj.edges[l], box))) {
      if (j == i || j == l) continue;
      if (!eee_pair_possible(scene, adj.edges[j], adj.edges[l]) ||
          !eee_pair_possible(scene, adj.edges[i], adj.edges[j]))
        continue;
      if (!segment_meets_tetrahedron(P(l, 0), P(l, 1), P(i, 0), P(i, 1), P(j, 0), P(j, 1))) continue;
      loc.triples.push_back(sorted(i, j, l));
    }
  };

  const int rows = restricted ? static_cast<int>(light_edges.size()) : m;
  ProgressBar bar(restricted ? "EEE light pairs" : "EEE outer pairs", static_cast<std::uint64_t>(rows),
                  options.progress);
  auto row = [&](int r) {
    Local& loc = locals.local();
    if (!restricted) {
      for (int j = r + 1; j < m; ++j) outer_pair(loc, r, j);
    } else {
      const int l = light_edges[r];
      for (int j = 0; j < m; ++j) {
        if (j == l) continue;
        if (!is_light[j] || j > l) outer_pair(loc, l, j);  // light-light outer pairs once
        light_middle(loc, j, l);
      }
    }
    bar.advance();
  };
  for_each_index(static_cast<std::size_t>(rows), options.parallel, 1, [&](std::size_t r) { row(static_cast<int>(r)); });
  std::vector<Triple> out;
  std::uint64_t pairs = 0, kept = 0;
  for (auto& loc : locals) {
    out.insert(out.end(), loc.triples.begin(), loc.triples.end());
    pairs += loc.pairs;
    kept += loc.kept;
  }
  tbb::parallel_sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  if (stats) {
    stats->outer_pairs += pairs;
    stats->outer_pairs_kept += kept;
    stats->candidate_triples += out.size();
  }
  return out;
}

EeeResult eee_events_of_triples(const Scene& scene, const SceneAdjacency& adj, const TriangleIndex& occluders,
                                const std::vector<Triple>& triples, bool parallel, std::size_t grain,
                                const std::string& label, bool progress,
                                const std::function<void(EeeEvent&)>& on_found) {
  struct Local {
    std::vector<EeeEvent> events;
    EeeStats stats;
  };
  tbb::enumerable_thread_specific<Local> locals;
  ProgressBar bar(label, triples.size(), progress);
  for_each_index(triples.size(), parallel, grain, [&](std::size_t i) {
    Local& loc = locals.local();
    const Triple& t = triples[i];
    if (auto ev = eee_event(scene, adj, occluders, t[0], t[1], t[2], &loc.stats)) {
      if (on_found) on_found(*ev);
      loc.events.push_back(std::move(*ev));
    }
    bar.advance();
  });
  EeeResult result;
  for (auto& loc : locals) {
    for (auto& ev : loc.events) result.events.push_back(std::move(ev));
    result.stats.eee.triples += loc.stats.triples;
    result.stats.eee.tangent_triples += loc.stats.tangent_triples;
    result.stats.eee.occluder_tests += loc.stats.occluder_tests;
  }
  // Per-thread lists arrive in any order: sort so the output does not depend on the scheduling.
  std::sort(result.events.begin(), result.events.end(),
            [](const EeeEvent& a, const EeeEvent& b) { return a.edges < b.edges; });
  return result;
}

EeeResult enumerate_eee_events(const Scene& scene, const EeeOptions& options) {
  const SceneAdjacency adj = build_scene_adjacency(scene);
  const EdgeIndex edges = scene_edge_index(scene, adj);
  const TriangleIndex occluders(scene);
  EeeResult result;
  const std::vector<Triple> triples = eee_candidate_triples(scene, adj, edges, options, &result.stats);

  EeeResult found = eee_events_of_triples(scene, adj, occluders, triples, options.parallel, 64, "EEE triples",
                                          options.progress);
  result.events = std::move(found.events);
  result.stats.eee = found.stats.eee;
  if (options.segment_ends && !result.events.empty()) {
    const TriangleIndex& spatial = occluders;
    const Box3 box = bounding_box(scene);
    ProgressBar ends_bar("EEE segment ends", result.events.size(), options.progress);
    auto ends = [&](EeeEvent& ev) {
      eee_segment_ends(scene, spatial, box, ev);
      ends_bar.advance();
    };
    for_each_index(result.events.size(), options.parallel, 16, [&](std::size_t i) { ends(result.events[i]); });
  }
  return result;
}

}  // namespace exactvis
