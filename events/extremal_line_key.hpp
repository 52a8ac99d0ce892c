#pragma once
// One vocabulary for the critical lines of the toolkit (docs/theory.md section 6, "Extremal line keys"):
// an *extremal line key* names an extremal line by its kind and its generators as canonical scene ids, so
// that the same line found as an EV interval end, an EEE interval end or by a direct construction (the 3D
// visibility skeleton's nodes) compares equal (==, <, std::hash).
//
// Generators: vertex ids; edges as vertex-id pairs [a, b] with a < b; faces as stable triangle ids. Where
// generators play the same role they are sorted; unused slots are -1. The kinds (a line has 4 degrees of
// freedom; each generator takes some):
//   VV    vertices {a, b}                      the line through vertices a and b
//   VEE   vertex v, edges {e1, e2}             through v, meeting e1 and e2
//   EEEE  edges {e1, e2, e3, e4}, branch       meeting four edges; `branch` says which of the (at most two)
//                                              transversals of their supporting lines (see eeee_key)
//   FVE   vertex v, edge e, face f             in the plane of face f (incident to v), through v, meeting e
//                                              (an EV line stopping being tangent at v)
//   FEE   edges {e1, e2}, face f               in the plane of face f (incident to a third generator edge),
//                                              meeting e1 and e2 (an EEE line stopping being tangent there)
//   VEF   vertex v, edge e, face f             through v and the point where edge e meets the plane of face
//                                              f (contact: the occluder f touches the generator e)
//   EEEF  edges {e1, e2} then e3, face f       meeting e1 and e2 and through the point where e3 meets the
//                                              plane of face f (contact of the occluder f with e3)
//   EEP   edges {e1, e2} then e3               meeting e1 and e2, parallel to e3 (an EEE line meeting e3's
//                                              line at infinity)
//   VEFF  vertex v, edge e, faces {f1, f2}     through v, meeting e, and through a point common to faces f1
//                                              and f2 (where the objects at the ends of EV maximal free
//                                              segments change at a crossing of two faces)
// A key is canonical for a line in general position w.r.t. its kind (the line determined by exactly those
// generators). A line with more incidences than its kind needs (a VEE line also passing through a second
// vertex, four edges on one regulus, ...) may be found under several keys, one per minimal generator set;
// the rules for which key each interval end gets are in docs/theory.md.
#include "kernel/plucker_line.hpp"
#include "kernel/root_number.hpp"
#include "kernel/scene.hpp"

#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace exactvis {

enum class ExtremalLineKind : std::uint8_t { VV, VEE, EEEE, FVE, FEE, VEF, EEEF, EEP, VEFF };

// "VV", "VEE", ... (the JSON and text names).
const char* kind_name(ExtremalLineKind kind);

using EdgeIds = std::array<int, 2>;  // an edge as vertex ids, sorted

struct ExtremalLineKey {
  ExtremalLineKind kind = ExtremalLineKind::VV;
  std::array<int, 2> vertices{-1, -1};
  std::array<EdgeIds, 4> edges{{{-1, -1}, {-1, -1}, {-1, -1}, {-1, -1}}};
  std::array<std::int64_t, 2> faces{-1, -1};
  int branch = 0;  // EEEE only

  // How many of each generator the kind has (the first slots are used).
  int vertex_count() const;
  int edge_count() const;
  int face_count() const;

  friend auto operator<=>(const ExtremalLineKey&, const ExtremalLineKey&) = default;
  friend bool operator==(const ExtremalLineKey&, const ExtremalLineKey&) = default;
};

// Text form, e.g. "VEE(v 4; e [1,2] [7,9])", "EEEE(e [..] [..] [..] [..]; branch 1)", "FVE(v 3; e [5,6]; f 12)".
std::string to_string(const ExtremalLineKey& key);

// The edge {a, b} as a sorted pair.
inline EdgeIds edge_ids(int a, int b) { return a < b ? EdgeIds{a, b} : EdgeIds{b, a}; }

// ---- direct constructions (the canonical forms; generators in any order)
ExtremalLineKey vv_key(int a, int b);
ExtremalLineKey vee_key(int v, EdgeIds e1, EdgeIds e2);
ExtremalLineKey fve_key(std::int64_t face, int v, EdgeIds e);
ExtremalLineKey fee_key(std::int64_t face, EdgeIds e1, EdgeIds e2);
ExtremalLineKey vef_key(int v, EdgeIds e, std::int64_t face);
ExtremalLineKey eeef_key(EdgeIds e1, EdgeIds e2, EdgeIds contact_edge, std::int64_t face);
ExtremalLineKey eep_key(EdgeIds e1, EdgeIds e2, EdgeIds parallel_edge);
ExtremalLineKey veff_key(int v, EdgeIds e, std::int64_t f1, std::int64_t f2);

// The EEEE key of `line`, a line meeting the supporting lines of the four scene edges (any order). `branch`
// is the rank of `line` among the real transversals of the four supporting lines
// (kernel/lines_through_four_lines) in the lexicographic order of their Plücker coordinates (d, m)
// normalised so that the first non-zero coordinate is 1 (an intrinsic order: it depends only on the lines,
// not on the edge order or on how `line` was found). Exact (comparisons across different square roots are
// exact). Cost: one four-line construction. With infinitely many transversals (four edges on one regulus)
// branch is 0.
ExtremalLineKey eeee_key(const Scene& scene, const std::array<EdgeIds, 4>& edges, const PluckerLine<RootNumber>& line);

}  // namespace exactvis

template <>
struct std::hash<exactvis::ExtremalLineKey> {
  std::size_t operator()(const exactvis::ExtremalLineKey& k) const noexcept;
};
