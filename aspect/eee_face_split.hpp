#pragma once
// The components of a face of the great circles minus the free EEE curves in it (docs/theory.md 10.11, "Faces"):
// the sub-arcs of the face, cut at their crossings (aspect/eee_crossings) into *segments*, and the face's
// boundary form a plane graph; its faces are traced from the cyclic order of the darts at each node (boundary
// points: the tangents of the ends there, swept through the face; crossings: the sign of the tangents' cross
// product; arc ends inside the face: one dart). Each component gets its facets (boundary pieces and segments on
// its boundary) and a rational sample strictly inside it.
#include "aspect/direction_event_arcs.hpp"
#include "aspect/eee_arc_insertion.hpp"
#include "aspect/eee_crossings.hpp"
#include "aspect/great_circle_arrangement.hpp"
#include "kernel/scene.hpp"

#include <string>
#include <vector>

namespace exactvis {

// One segment of a sub-arc: from node `from` to node `to` (cell ids: boundary points, arc ends inside the face,
// crossings) along increasing parameter, its cell, and a rational parameter strictly inside it.
struct EeeFaceSegment {
  int subarc = -1;
  int cell = -1;
  int from = -1, to = -1;
  Exact t;
};

struct EeeFaceComponent {
  Vec3<Exact> sample;          // rational, strictly inside the component
  std::vector<int> facets;     // cell ids of the boundary pieces and segments in its closure
};

struct EeeFaceSplit {
  std::string problem;         // non-empty: outside the subset (one line)
  std::vector<EeeFaceComponent> components;
};

// Input: face f, its boundary `ring` (cell ids in counter-clockwise order about the sphere's outside: vertex,
// piece, vertex, ...) with the rational samples of those cells, the segments of every sub-arc (indices into
// `segments` in increasing parameter order per sub-arc), the cell of every cut point and of every crossing.
// Output: one component per face of the plane graph. Exact. Cost: O(k log k) per boundary point of k ends, then
// linear in the darts, and per component one sample (O(s) quadratic sign tests for the s sub-arcs of f).
EeeFaceSplit split_eee_face(const Scene& scene, const DirectionEventArcs& events, const GreatCircleArrangement& arr,
                            const std::vector<Vec3<Exact>>& normals, const EeeArcInsertion& ins, const EeeCrossings& xs,
                            int f, const std::vector<int>& ring, const std::vector<Vec3<Exact>>& ring_samples,
                            const std::vector<EeeFaceSegment>& segments,
                            const std::vector<std::vector<int>>& segments_of_subarc, const std::vector<int>& point_cell,
                            const std::vector<int>& crossing_cell);

}  // namespace exactvis
