#pragma once
// The occlusion-free visual events of an orthographic aspect graph, as arcs of directions on the viewing
// sphere (docs/theory.md §10.9): for all lines of a direction, not only those between generators.
//
// Families of critical lines, t in [0, 1]:
//   EV  (vertex V, edge E = (A, B)):  the line through V and P(t) = A + t (B - A); family direction
//       f(t) = P(t) - V (a great-circle arc: the plane of V and E);
//   EEE (edges E1, E2, E3, lines pairwise skew): the line through P(t) = A1 + t (B1 - A1) meeting the lines
//       of E2 and E3, at Q2(t), Q3(t) inside both segments; family direction f(t) = n2(t) x n3(t) of
//       aspect/eee_direction_cone (a conic arc: the cone q(d) = 0 of §10.7).
// Each family gives two sets of directions, orientation +1 (d = f(t)) and -1 (d = -f(t)); the viewer is at
// infinity along +d. The line of parameter t is *free* for orientation o when the part of it from its farthest
// generator point (the smallest position along d) to infinity towards the viewer, the generator points
// themselves excepted, crosses the relative interior of no scene triangle at a single point (a triangle in a
// plane holding the line never blocks, one met at its boundary neither). No tangency rule is applied: every
// vertex and every edge is a generator, since a triangle's own edges (even between coplanar triangles) bound
// its visible part. The reported arcs are the closures of the free open parameter intervals (isolated free
// parameters are dropped: the line there pierces the union of the blockers of both sides, theory §10.9).
// The aspect of §10.1 is constant on each connected set of directions that meets no reported arc (proof in
// theory §10.9).
#include "kernel/number_types.hpp"
#include "kernel/root_number.hpp"
#include "kernel/scene.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace exactvis {

// What ends an arc at one of its parameters (the first cause found at that value).
struct ArcEnd {
  enum class Cause {
    FamilyEnd,     // t = 0 or t = 1 (EV: the line through an endpoint of E; EEE: through an endpoint of E1)
    EdgeEndpoint,  // EEE: the line passes through `vertex`, an endpoint of E2 or E3
    Singular,      // EEE: the line becomes parallel to E2's or E3's line, or the family direction vanishes
    Occluder,      // triangle `triangle` (stable id) starts or stops blocking
  };
  Cause cause = Cause::FamilyEnd;
  int vertex = -1;
  std::int64_t triangle = -1;
};

struct DirectionEventArc {
  enum class Type { EV, EEE };
  Type type = Type::EV;
  int vertex = -1;                              // EV: V (scene vertex id)
  std::array<std::array<int, 2>, 3> edges{};    // EV: edges[0] = E; EEE: E1, E2, E3 (vertex ids, each sorted)
  int orientation = 1;                          // +1: d = f(t); -1: d = -f(t)
  RootNumber t0, t1;                            // 0 <= t0 < t1 <= 1 (EV: rational; EEE: degree <= 2)
  Exact sample_t;                               // a rational strictly inside (t0, t1) whose line is free
  ArcEnd end0, end1;
};

struct DirectionEventOptions {
  bool eee = true;       // also the EEE families (O(edges^3) triples)
  bool parallel = true;  // oneTBB over vertices (EV) and first edges (EEE); the result is the same either way
};

struct DirectionEventArcs {
  std::vector<DirectionEventArc> arcs;  // EV first (by vertex, edge), then EEE (by edges); orientation +1 first
  std::uint64_t ev_pairs = 0, eee_triples = 0, eee_valid_triples = 0;
};

// Input: a model whose triangles meet only in shared corners and edges. Output: every free arc, exact.
// Cost: EV, per (vertex, edge) pair O(k log k) for the k triangles crossing their plane (O(1) cuts each);
// EEE, per triple O(1) for the validity, then O(n log n) for the n triangles of the scene.
DirectionEventArcs direction_event_arcs(const Scene& scene, const DirectionEventOptions& options = {});

// The direction of an arc's line at a rational parameter: orientation * f(t) (exact; zero only at a
// singular parameter of an EEE family).
Vec3<Exact> arc_direction(const Scene& scene, const DirectionEventArc& arc, const Exact& t);

// The exact critical line at a rational t of an arc: its farthest generator point `from` (the line is free
// from there towards the viewer, +d) and d. std::nullopt when the family has no line at t (EEE: not meeting
// E2 or E3, or singular).
struct ArcLine {
  Vec3<Exact> from, direction;
};
std::optional<ArcLine> arc_line(const Scene& scene, const DirectionEventArc& arc, const Exact& t);

}  // namespace exactvis
