#pragma once
// Proofs of exterior invisibility by enclosure (docs/theory.md §5.6, Lemma 5.6.4): a closed shell of the
// scene that a triangle T lies inside blocks every ray from T.
//
// A *shell* is a connected component of the scene's triangles (linked through shared vertex positions,
// compared exactly); it is *closed* when every edge (a pair of vertex positions) is an edge of an even
// number of the shell's triangles: a mod-2 2-cycle, self-intersections and non-manifold edges allowed. For a
// point x off a closed shell, the number of the shell's triangles a generic ray from x crosses (transversally,
// through their relative interiors, missing every edge) has a parity independent of the ray; when it is odd,
// every ray from x meets the shell. If the relative interior of T misses the shell, the parity is the same
// at all of its points, so one exact count at the centroid proves T hidden.
#include "kernel/predicates.hpp"
#include "kernel/scene.hpp"
#include "kernel/triangle_index.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace exactvis::region {

// The shells of a scene, built once (O(n log n)); queries are const and thread-safe.
class SceneShells {
 public:
  explicit SceneShells(const Scene& scene);

  int shell_of(std::int64_t triangle_index) const { return shell_of_[static_cast<std::size_t>(triangle_index)]; }
  int shells() const { return static_cast<int>(closed_.size()); }
  bool closed(int shell) const { return closed_[static_cast<std::size_t>(shell)]; }
  int closed_shells() const;
  // The bounding box of the shell's triangles.
  const Box3& box(int shell) const { return box_[static_cast<std::size_t>(shell)]; }
  // The closed shells, in increasing order.
  const std::vector<int>& closed_list() const { return closed_list_; }

 private:
  std::vector<int> shell_of_;
  std::vector<bool> closed_;
  std::vector<Box3> box_;
  std::vector<int> closed_list_;
};

// The certificate: the closed shell, the ray from q (the centroid of T) in direction d, and the number of the
// shell's triangles it crosses (odd). Re-checkable by any exact ray-triangle code.
struct EnclosureProof {
  int shell = -1;
  RationalPoint3 q;
  Vec3<Exact> d;
  int crossings = 0;
};

// Input: scene, its index, bounding_box(scene), its shells, a triangle (index into Scene::triangles).
// Output: a proof that T is hidden by a closed shell other than its own whose triangles all miss relint T,
// or std::nullopt when no such shell encloses T (the caller decides T otherwise). Exact: closed-triangle
// meeting tests, exact clipping for contacts with T, segment_crosses_triangle_interior for the count; a ray
// touching an edge or a vertex of the shell is discarded for another one (up to 8 directions). Cost: per
// candidate shell (box containing T's box), the triangles meeting T plus one ray's candidates.
std::optional<EnclosureProof> enclosing_shell(const Scene& scene, const TriangleIndex& index, const Box3& scene_box,
                                              const SceneShells& shells, std::int64_t triangle_index);

// True iff the closed triangle `other` meets the relative interior of the non-degenerate triangle `t`.
// Exact (clipping `other` by plane(t) and by the planes through t's edges, then one relative-interior test).
bool meets_relative_interior(const std::array<RationalPoint3, 3>& other, const std::array<RationalPoint3, 3>& t);

}  // namespace exactvis::region
