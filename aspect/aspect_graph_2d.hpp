#pragma once
// The aspect graph of a planar scene: viewpoints (in free space, inside a frame) partitioned into regions
// of equal aspect, the aspect being the set of object edges of which a part of positive length is visible.
//
// Construction (docs/theory.md, section 7): candidate event segments are the free extensions of every
// visibility-graph segment and every ring edge beyond an endpoint where the line is tangent (the only places
// where a vertex can start hiding another vertex or an edge, or an edge turn edge-on). They are inserted with
// all ring edges into a CGAL Arrangement_2 (exact kernel); every bounded face gets an exact interior sample
// point and its aspect (one exact angular sweep); adjacent free faces with equal aspects are merged into
// regions, so every remaining boundary is a real event. Cost: O(m^2) arrangement of m = O(n^2) segments in
// the worst case, plus one O(n log n) sweep per face: meant for small and medium scenes.
#include "planar/scene2d.hpp"

#include <array>
#include <functional>
#include <utility>
#include <vector>

namespace exactvis {

struct AspectFace2D {
  std::vector<Point2> outer;               // counterclockwise boundary (exact arrangement vertices)
  std::vector<std::vector<Point2>> holes;  // inner boundaries
  Point2 sample;                           // exact point in the face's interior
  int region = -1;                         // region index, or -1 for faces inside objects
};

struct AspectRegion2D {
  std::vector<int> aspect;  // visible scene edge ids (edge e goes from vertex e to next[e]), sorted
  std::vector<int> faces;   // indices into AspectGraph2D::faces
};

struct AspectGraph2D {
  Scene2D framed;                                     // the scene plus the viewpoint frame (last ring)
  std::vector<AspectFace2D> faces;
  std::vector<AspectRegion2D> regions;
  std::vector<std::pair<int, int>> adjacency;         // region pairs sharing a boundary of positive length
  std::vector<std::array<Point2, 2>> boundaries;      // arrangement edges separating two regions
  std::size_t event_segments = 0;                     // candidate event segments inserted
  std::size_t arrangement_faces = 0;                  // bounded faces of the arrangement
};

// Input: a scene (without frame); margin of the viewpoint frame as in with_frame (throws Scene2DError when
// that frame is not representable). Output: the partition. `progress`: draw progress bars on stderr for the
// three long stages (event segments, arrangement sweep, one visibility sweep per face). Uses all cores
// (oneTBB) for the event segments and the faces.
// `before_faces` (may be empty) is called once the arrangement is built, with its number of bounded faces
// (each costs one O(n log n) visibility sweep next), e.g. to warn about the remaining cost.
AspectGraph2D aspect_graph(const Scene2D& scene, double margin_ratio = 0.25, bool progress = false,
                           const std::function<void(std::size_t faces)>& before_faces = {});

// Region containing p (exact point location over the faces): the region index, -1 inside an object or
// outside the frame, -2 on an arrangement edge or vertex.
int region_of(const AspectGraph2D& g, const Point2& p);

}  // namespace exactvis
