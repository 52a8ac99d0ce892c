#pragma once
// Validity of a skeleton node's line (docs/theory.md section 9, "Nodes"): the definition the node counts
// use. A line found as an arc end is *valid* iff
//   - it passes through every vertex generator and meets every edge generator in its relative interior;
//   - edge rule at each edge generator (opposite vertices of the edge's triangles strictly on one side of
//     the plane spanned by the line and the edge); vertex rule at each vertex generator
//     (events/tangency.hpp) -- except, for the face kinds FVE and FEE, that the line lies in the plane of
//     the face f (their defining incidence) instead of the vertex rule at FVE's vertex;
//   - the open segment between its outermost generator points meets no closed triangle other than those
//     incident to a generator (a corner at a vertex generator, an edge generator as an edge; for a face
//     generator f: f and the triangles sharing a vertex with f).
// The contact kinds VEF, EEEF, EEP, VEFF (interpenetration, lines parallel to an edge) are valid by
// definition when found. Arc ends that fail the test are the *degenerate* nodes (lines lying in the plane
// of a face at a generator, lines through an edge's endpoint, ...): they stay in the graph as arc ends but
// are counted apart.
#include "events/scene_adjacency.hpp"
#include "kernel/triangle_index.hpp"
#include "skeleton/visibility_skeleton_3d.hpp"

#include <optional>

namespace exactvis {

// The parameter u of the point a + u (b - a) where the line {o + s d} meets the line of (a, b); nullopt
// when they are parallel. Exact when the two lines meet; for skew lines some u (callers know the lines
// meet, or check that a + u (b - a) is on the line). Cost: about 4 products and one division in Q(sqrt D).
std::optional<RootNumber> edge_meeting_parameter(const Vec3<RootNumber>& o, const Vec3<RootNumber>& d,
                                                 const Vec3<RootNumber>& a, const Vec3<RootNumber>& b);

// Whether x (in Q or Q(sqrt D)) is zero: a0 = a1 = 0 decides at once, else the filtered exact sign.
bool is_zero_root(const RootNumber& x);
// Whether every coordinate is zero (is_zero_root).
bool is_zero_vector(const Vec3<RootNumber>& v);

// Input: the scene, its adjacency and spatial index, a node with its key and spanned segment (from, to),
// and the line's direction (to - from when from != to). Output: whether the node is valid (above). Exact.
// Cost: one spatial query and the exact tests on the triangles whose boxes meet the segment's box.
bool node_line_valid(const Scene& scene, const SceneAdjacency& adj, const TriangleIndex& index,
                     const SkeletonNode& node, const Vec3<RootNumber>& dir);

}  // namespace exactvis
