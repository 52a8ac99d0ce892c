#pragma once
// EEE critical line sets with occlusion (docs/theory.md section 6, "EEE critical line sets").
//
// For three scene edges E1 < E2 < E3 (SceneAdjacency order; pairwise no common vertex, supporting lines
// pairwise skew), the EEE set is the family of lines meeting all three edges. It is parameterised by the
// point P(t) = A1 + t (B1 - A1), t in [0, 1], on E1 (A1, B1 = the positions of E1's vertex ids v[0] < v[1]):
// L(t) is the unique line through P(t) meeting the supporting lines of E2 and E3. Line t is *valid* iff it
// meets E2 and E3 in their relative interiors, is tangent at all three edges (edge rule of
// events/tangency.hpp applied to each), and the open *generator segment* (the segment between the two
// outermost of its three meeting points) meets no occluder: a closed scene triangle having none of E1, E2,
// E3 as an edge. The valid set is a finite union of intervals whose ends are algebraic of degree <= 2 (VEE
// lines: rational; EEEE lines through an occluder edge: quadratic); reported are the closures of its
// components of positive length.
#include "events/critical_interval.hpp"
#include "events/ev_events.hpp"
#include "events/scene_adjacency.hpp"
#include "kernel/number_types.hpp"
#include "kernel/root_number.hpp"
#include "kernel/scene.hpp"
#include "kernel/vec3.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace exactvis {

class TriangleIndex;

// An EEE event: the free intervals (CriticalInterval: ends rational or a + b sqrt(D)) of the family of three
// edges. End causes are CriticalEnd's EEE causes (EdgeEndpoint with `generator` 0, 1, 2 and `vertex`;
// Occluder; Tangency with `generator` and the face `triangle`; Singular with `generator` 1 or 2), each with
// its extremal line key. sample_t (a rational strictly inside (t0, t1)) is set by eee_event; the end objects
// (front_object: beyond the outermost generator point in direction d = Q2 - P; back_object: beyond the
// other outermost point in direction -d) are filled by eee_segment_ends (not by eee_event).
struct EeeEvent {
  std::array<std::array<int, 2>, 3> edges{};  // scene vertex ids of E1, E2, E3, each sorted; t runs along E1
  std::vector<CriticalInterval> intervals;     // sorted, disjoint except possibly sharing an end
};

struct EeeStats {
  std::uint64_t triples = 0;          // candidate triples examined
  std::uint64_t tangent_triples = 0;  // triples with a non-empty tangent, in-segment parameter set
  std::uint64_t occluder_tests = 0;   // exact occluder tests after culling
};

// The one EEE event of the edges adj.edges[e1], adj.edges[e2], adj.edges[e3] (indices into adj.edges, any
// order: they are sorted), or std::nullopt if it has no free interval (or the edges share a vertex, or two
// supporting lines are coplanar). Exact. Thread-safe (no shared mutable state besides `stats` if given).
// Throws std::out_of_range for an index outside adj.edges.
// Sets sample_t and the end keys of each interval; front_object/back_object are left at -1 (see
// eee_segment_ends).
std::optional<EeeEvent> eee_event(const Scene& scene, const SceneAdjacency& adj, const TriangleIndex& index,
                                  int e1, int e2, int e3, EeeStats* stats = nullptr);

// Fills front_object / back_object of every interval of `event` (rays from the sample line, see EeeEvent),
// exactly, with kernel/ray_first_hit.hpp. `box` = bounding_box(scene).
void eee_segment_ends(const Scene& scene, const TriangleIndex& spatial, const Box3& box, EeeEvent& event);

// The generator segment of L(t) at a rational t (for output): its outermost generator points `back` and
// `front` and the direction d = Q2 - P(t), front - back a positive multiple of d; std::nullopt where L(t)
// meets E2's or E3's line at infinity (a Singular parameter, never inside a free interval). Exact.
struct EeeGeneratorSegment {
  Vec3<Exact> back, front, direction;
};
std::optional<EeeGeneratorSegment> eee_generator_segment(const Scene& scene, const EeeEvent& event, const Exact& t);

// The exact points of the line L(t) of an EEE event (for output and re-checking): its point on E1, and its
// points on the supporting lines of E2 and E3 (std::nullopt when the line is parallel to that edge's line,
// t a Singular end). `direction` is Q2 - P scaled by a nonzero factor (always defined). Coordinates in the
// field of t (t rational: rational; else the Q(sqrt D) of t). Requires t in [0, 1] and the edges of a valid
// triple (as in an EeeEvent).
struct EeeLinePoints {
  Vec3<RootNumber> on_e1;
  std::optional<Vec3<RootNumber>> on_e2, on_e3;
  Vec3<RootNumber> direction;
};
EeeLinePoints eee_line_points(const Scene& scene, const EeeEvent& event, const RootNumber& t);

// The exact text of a parameter: "num/den" (or an integer) when rational, else "a+b*sqrt(c)" or
// "a-b*sqrt(c)" with rationals a, b > 0 written the same way and an integer c > 0 that is not a square.
// docs/cli.md documents this form.
std::string root_number_to_string(const RootNumber& x);

}  // namespace exactvis
