#pragma once
// The 2D visibility complex of Pocchiola and Vegter for a polygonal scene (docs/theory.md, section 7).
//
// Vertices: the free bitangents (visibility_graph_2d.hpp), each with its maximal free segment.
// Edges: one-parameter families of maximal free segments tangent to one object. The lines tangent to an
//   object at a convex vertex v turn counterclockwise from the line of edge (prev v, v) to the line of edge
//   (v, next v); consecutive convex (or flat) vertices continue each other, a reflex vertex ends the family
//   ("terminal"). Each family ("chain") is cut at its bitangents; a piece is an edge. A closed chain without
//   bitangent is one closed edge.
// Faces: maximal free segments grouped by the (unordered) pair of objects at their two ends (-1 stands for
//   infinity). Slots of faces are glued across vertices by a local rule; every glued slot must carry the same
//   pair, which is checked against the end objects found by independent ray shots. Incidences: a bitangent with line objects A, Oa, Ob, B in order (A beyond a, B beyond b) touches exactly
//   4 edges (2 on the chain of a, 2 on the chain of b) and the 6 faces of pairs {A,Oa}, {A,Ob}, {A,B},
//   {Oa,Ob}, {Oa,B}, {Ob,B}, each through exactly 2 of its edges; an edge touches 3 faces (end-pivot,
//   pivot-end, end-end). When a bitangent's line continues along an edge of its endpoint a (empty
//   extension), A is the object met by the nearby segments that miss a's object: they run along the
//   collinear edges and re-enter a's object where the ring turns towards them, else go on to the first
//   contact beyond the last collinear vertex.
#include "skeleton/visibility_graph_2d.hpp"

#include <array>
#include <vector>

namespace exactvis {

struct ComplexEdge2D {
  int object = 0;
  int chain = 0;
  std::array<int, 2> vertices{-1, -1};  // bitangent ids at the start / end (-1: terminal or closed edge)
  int pivot = 0;                        // a scene vertex the sample segment is tangent at
  // every convex vertex of the chain whose tangent lines this edge contains (a non-empty sub-range of its
  // directions), in chain order; `pivot` is the first of them
  std::vector<int> pivots;
  Point2 sample_from, sample_to;        // direction of the sample tangent line (sample_to - sample_from)
  bool degenerate = false;              // zero length (two bitangents on one line through the pivot)
  // objects met by the sample line beyond the pivot, backwards and forwards (-1: infinity)
  std::array<int, 2> end_objects{-1, -1};
  std::array<int, 3> faces{-1, -1, -1};  // faces (back end, pivot), (pivot, front end), (back, front)
};

struct ComplexVertex2D {
  int bitangent = 0;
  std::array<int, 4> edges{-1, -1, -1, -1};  // chain of a: before, after; chain of b: before, after
  // faces of the pairs {A,Oa}, {A,Ob}, {A,B}, {Oa,Ob}, {Oa,B}, {Ob,B}
  std::array<int, 6> faces{-1, -1, -1, -1, -1, -1};
};

struct ComplexFace2D {
  std::array<int, 2> objects{-1, -1};  // objects at the ends of its segments (-1: infinity), sorted
};

struct VisibilityComplex2D {
  VisibilityGraph2D graph;             // visibility graph and bitangents (the vertices)
  std::vector<ComplexVertex2D> vertices;  // vertices[i] is bitangent i
  std::vector<ComplexEdge2D> edges;
  std::vector<ComplexFace2D> faces;
  int chains = 0;
  // True iff every pair of slots glued by the local vertex rule carries the same end objects. Holds in
  // general position (tested on random convex and non-convex scenes); it can be false when several
  // bitangents lie on one line through a common vertex (zero-length edges), where the local picture of
  // the complex is not the generic one. Faces still group segments by end objects, slot by slot.
  bool gluing_consistent = true;
};

// Builds the complex. Input: a scene without frame. Cost with the default `method` (the output-sensitive
// rotational sweep): O((n + K) log n) for K visible vertex pairs: the graph sweep, then one more sweep
// answering the two rays of every edge's sample line (the objects at its ends). With PerVertexSweep:
// O(n^2 log n) plus one exact O(n) ray shot per ray. Throws std::logic_error if a bitangent does not get
// its 4 edges (a bug, never bad input).
VisibilityComplex2D visibility_complex(const Scene2D& scene, void (*progress)(double) = nullptr,
                                       VisibilityGraphMethod method = VisibilityGraphMethod::RotationalSweep);

// First boundary point on the ray from scene vertex v in direction d1 - d0 (v's own edges are ignored;
// the ray must not run along them). Exact, O(n); with `edges` (ids of ring edges) only those are tested,
// O(edges.size()).
SegmentEnd2D first_contact(const Scene2D& scene, int v, const Point2& d0, const Point2& d1,
                           const std::vector<int>* edges = nullptr);
// The same contact without its point (kind, id and object only): orientation tests, no construction.
SegmentEnd2D first_contact_feature(const Scene2D& scene, int v, const Point2& d0, const Point2& d1,
                                   const std::vector<int>* edges = nullptr);

}  // namespace exactvis
