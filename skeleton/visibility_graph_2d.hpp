#pragma once
// Visibility graph and free bitangents of a 2D scene (the vertices of the visibility complex).
//
// Definitions (docs/theory.md, section 7):
// - Vertices p, q see each other (strictly) iff the open segment (p,q) lies in the open free space: it meets
//   no object and no boundary point. Ring edges are added separately (`ring_edges`); strict pairs plus ring
//   edges contain every shortest path (a path touching a boundary splits at the vertices it touches).
// - A free bitangent is a strict pair (p,q) whose line does not enter an object near p nor near q (the
//   objects at p and at q each lie in a closed half-plane of the line). Only convex vertices of an object
//   qualify. In a collinear chain p, r, q of tangent vertices the bitangents are pr and rq, never pq.
// - Its maximal free segment extends the segment beyond each endpoint to the first boundary point met
//   (a vertex, an edge interior, or infinity); if an edge of the endpoint continues the line, the
//   extension on that side is empty and ends at the endpoint itself.
#include "planar/scene2d.hpp"

#include <string>
#include <utility>
#include <vector>

namespace exactvis {

// End of a maximal free segment beyond a bitangent's endpoint.
struct SegmentEnd2D {
  enum Kind { Infinity = 0, Vertex = 1, EdgeInterior = 2 };
  Kind kind = Infinity;
  int id = -1;       // vertex id (Vertex) or edge id (EdgeInterior)
  int object = -1;   // object met, or -1 at infinity
  Point2 point;      // exact contact point (undefined at infinity)
};

struct Bitangent2D {
  int a = 0, b = 0;               // vertex ids, a < b; the bitangent is directed a -> b
  int object_a = 0, object_b = 0;
  char side_a = 'L', side_b = 'L';  // side of the directed line a->b on which object_a / object_b lies
  SegmentEnd2D end_a, end_b;      // maximal free segment: end_a, a, b, end_b along the line
  std::string kind() const { return std::string{side_a, side_b}; }
};

struct VisibilityGraph2D {
  std::vector<std::pair<int, int>> strict_pairs;  // (p, q), p < q, open segment in the open free space
  std::vector<std::pair<int, int>> ring_edges;    // (e, next[e]) for every ring edge
  std::vector<Bitangent2D> bitangents;            // sorted by (a, b)
};

// A vertex w seen strictly from a vertex p, as found from p: whether the line p-w is tangent at both ends
// (a free bitangent) and, if so, the end of the maximal free segment beyond w.
struct VisibleFrom2D {
  int w = -1;
  bool tangent = false;
  SegmentEnd2D beyond;
};

// How the visible pairs are found. Both give exactly the same graph (tests compare them with each other
// and with an O(n^3) brute force).
enum class VisibilityGraphMethod {
  RotationalSweep,  // one output-sensitive sweep of all views, O((n + K) log n), K = visible pairs
  PerVertexSweep,   // one angular sweep per vertex, O(n^2 log n), on all cores (the reference)
};

// Input: a scene (a frame, if present, takes part like any ring). Output: the visibility graph with its
// free bitangents. `progress` (may be null) is called with the fraction done.
VisibilityGraph2D visibility_graph(const Scene2D& scene, void (*progress)(double) = nullptr,
                                   VisibilityGraphMethod method = VisibilityGraphMethod::RotationalSweep);

// Local tests at a scene vertex v for the direction d = d1 - d0 (exact):
// d points into the open free wedge at v,
bool in_free_wedge(const Scene2D& scene, int v, const Point2& d0, const Point2& d1);
// d points into the open object wedge at v.
bool in_object_wedge(const Scene2D& scene, int v, const Point2& d0, const Point2& d1);

}  // namespace exactvis
