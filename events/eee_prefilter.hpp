#pragma once
// Cheap exact necessary conditions for an EEE (or EV) line through two scene edges (docs/theory.md section 6,
// "Candidate generators"). They never reject a pair of edges that has a valid line through both.
#include "events/scene_adjacency.hpp"
#include "kernel/scene.hpp"

namespace exactvis {

// Can some point X of the open segment (c, d) satisfy the edge rule of edge `e` (the opposite vertices of all
// of e's triangles strictly on one side of the plane through e and X)? Conservative: each opposite vertex's
// constraint is checked on its own (a linear function of X that is <= 0 at both c and d is <= 0 on the
// whole segment); false only when no such X exists. Exact (orient3d).
bool edge_rule_possible(const Scene& scene, const SceneEdge& e, const Point3& c, const Point3& d);

// Edges a and b: no common vertex id, supporting lines skew (not coplanar), and the edge rule of each is
// possible on the other (edge_rule_possible both ways). Necessary for any EEE line through a and b. Exact.
bool eee_pair_possible(const Scene& scene, const SceneEdge& a, const SceneEdge& b);

}  // namespace exactvis
