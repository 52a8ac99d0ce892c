#pragma once
// Consistency of a 3D visibility skeleton with its definition (docs/theory.md section 9): the graph (every
// arc has two end nodes and is listed at both, every node has an arc) and the adjacency catalogue (which
// families' arcs meet at a node of each kind, and how many).
#include "kernel/scene.hpp"
#include "skeleton/visibility_skeleton_3d.hpp"

#include <string>
#include <vector>

namespace exactvis {

struct SkeletonCheck {
  std::vector<std::string> problems;  // one line each, naming the node (key) or arc; empty when consistent
  std::size_t nodes_checked = 0;      // nodes whose degree was checked against the catalogue
};

// Input: the scene and its skeleton. Output: the problems found. The catalogue is checked at the valid
// nodes of kinds VV, VEE, EEEE, FVE and FEE (the table of section 9 holds in general position; degenerate
// scenes may legitimately differ, so callers decide how to treat problems there). Exact. Cost: linear in
// the number of arc ends, one exact line-edge meeting per generator.
SkeletonCheck validate_skeleton(const Scene& scene, const Skeleton3D& skeleton);

}  // namespace exactvis
