#pragma once
// Splitting EV free intervals where the objects at the ends of the maximal free segments change
// (docs/theory.md section 6, "Maximal free segments").
//
// For a free interval [t0, t1] of the EV pair (V, E), the front end object of L(t) (first closed triangle hit
// by the open ray from P(t) away from V) and the back end object (from V away from E) are piecewise constant
// in t. They can change only at rational t where L(t) passes through (a) an endpoint of the segment in which
// a candidate triangle meets the wedge plane (a triangle vertex in the plane, or a triangle edge crossing it;
// coplanar triangles contribute their edges), or (b) a crossing point of the current end object's segment
// with another candidate's segment. The split collects (a) from all triangles that can meet the swept
// regions (AABB query of an exact enclosure), evaluates the end objects exactly (kernel/ray_first_hit.hpp)
// at the midpoint of each piece, adds (b) for the object found there and recurses, and finally merges equal
// neighbours.
#include "events/ev_events.hpp"
#include "events/scene_adjacency.hpp"
#include "kernel/triangle_index.hpp"

#include <vector>

namespace exactvis {

// Input: the scene, its spatial index and bounding box, the vertex id V and edge (vertex ids) of an EV event,
// and one of its free intervals. Output: consecutive pieces covering [t0, t1] (at least one) with sample_t
// (the piece's midpoint), beyond_edge and behind_vertex filled; neighbours differ in at least one object.
// Outer ends keep the interval's end causes; inner ends have cause EndObjectChange, with the feature the line
// passes through there (a vertex or an edge of a triangle meeting the wedge plane, or a crossing of two
// triangles' sections) and its extremal line key. `adj` is the scene's adjacency. Exact.
std::vector<CriticalInterval> split_ev_interval(const Scene& scene, const SceneAdjacency& adj,
                                                const TriangleIndex& spatial, const Box3& box, int vertex,
                                                const std::array<int, 2>& edge, const CriticalInterval& interval);

}  // namespace exactvis
