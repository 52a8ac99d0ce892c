#pragma once
// Independent brute-force oracle for the nodes of the 3D visibility skeleton (tests/skeleton): GMP
// rationals and its own Q(sqrt r) arithmetic, no exactvis header. It enumerates every candidate generator
// set (all vertex pairs, vertex-edge-edge triples, 4-edge sets) of a small triangle mesh, constructs the
// line(s) by its own methods (VEE: intersection of the planes (v, e1), (v, e2); EEEE: the ruled quadric
// through three edge lines cut with the fourth, then the line through that point meeting two of them), and
// decides validity as docs/theory.md section 9 defines it:
//   - the line passes through each vertex generator and meets each edge generator's relative interior;
//   - edge rule at each edge: the opposite vertices of the edge's triangles lie strictly on one side of the
//     plane spanned by the line and the edge;
//   - vertex rule at each vertex: (a) the line meets no triangle at the vertex in more than the vertex, and
//     (b) when every link vertex has two link neighbours, for each link cycle the points v + d and v - d are
//     both inside or both outside the cone over that cycle (ray-crossing parity: the winding number of the
//     cycle around the line is even; the code under test counts it exactly with Sunday's rule);
//   - the open segment between the outermost generator points meets no closed triangle that has no vertex
//     generator as a corner and no edge generator as an edge.
// Generator sets with a repeated vertex id, and degenerate constructions (v, e1, e2 coplanar; four lines
// with infinitely many transversals; no three pairwise skew lines among the four) are skipped and counted.
#include <gmpxx.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace skeleton_oracle {

using Q = mpq_class;

// x = a + b sqrt(r), r >= 0 shared by the values of one computation.
struct QS {
  Q a, b;
};
using QS3 = std::array<QS, 3>;

struct Mesh {
  std::vector<std::array<Q, 3>> v;
  std::vector<std::array<int, 3>> t;
};

// A line with its point `p` and direction `d` in Q(sqrt r)^3.
struct Line {
  QS3 p, d;
  Q r = 0;
};

// Generators, as vertex ids; edges as sorted pairs.
struct Generators {
  std::vector<int> vertices;
  std::vector<std::array<int, 2>> edges;
  std::vector<int> faces;  // triangle indices (face kinds): f and every triangle sharing a vertex with f are
                           // incident to f
};

// The validity of `line` for `gens` (see the header comment). `why` (optional) says what failed.
bool valid_line(const Mesh& m, const Generators& gens, const Line& line, std::string* why = nullptr);

// Line incidences (exact): passes through point x (rational), lies in the plane of triangle t.
bool passes_through(const Line& line, const std::array<Q, 3>& x);
bool lies_in_plane(const Mesh& m, const Line& line, int triangle);
bool meets_edge_interior(const Mesh& m, const Line& line, const std::array<int, 2>& e);
// The open segment between the outermost of the given points of the line (vertices, and the points where
// the line meets the given edges' lines) misses every closed triangle not incident to them.
bool segment_free(const Mesh& m, const Generators& gens, const Line& line, std::string* why = nullptr);

// Valid nodes by key "VV v0 v1", "VEE v e1a e1b e2a e2b", "EEEE e1a e1b ... e4b" (sorted generators) ->
// number of valid lines with those generators (EEEE: up to 2).
struct Result {
  std::map<std::string, int> nodes;
  int skipped_degenerate = 0;
};
Result valid_nodes(const Mesh& m, bool with_vv, bool with_vee, bool with_eeee);

}  // namespace skeleton_oracle
