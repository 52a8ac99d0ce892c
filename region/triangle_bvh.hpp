#pragma once
// A bounding volume hierarchy over a scene's triangles for the PVS traversal (region/exact_pvs.hpp): binary;
// a node holding several objects splits between objects (sorted by object-box centre on the axis of their
// widest spread, cut at the object boundary nearest the median), so every object is one subtree whose box is
// the object's box (a building, a tree: the natural unit to prove hidden); inside one object, median split
// on the longest axis of the triangle centroids; leaves of a few triangles. Every node's box is
// the exact bounding box of its triangles (min/max of their double corners: no rounding), and a node's
// triangles are the contiguous range order[begin, end).
#include "kernel/scene.hpp"

#include <cstdint>
#include <vector>

namespace exactvis::region {

struct BvhNode {
  Box3 box;                  // closed; contains every triangle of the node
  int left = -1, right = -1; // children (indices into TriangleBvh::nodes), -1 for a leaf
  int begin = 0, end = 0;    // the node's triangles: order[begin, end)
};

struct TriangleBvh {
  std::vector<BvhNode> nodes;        // nodes[0] is the root (empty scene: no nodes)
  std::vector<std::int64_t> order;   // triangle indices in node order
  std::vector<int> position;         // position[t]: where triangle t is in `order`
};

// Input: the scene, the largest leaf (>= 1). Output: the hierarchy. Cost: O(n log n) per object level
// (a sort), O(n log^2 n) in all.
TriangleBvh build_triangle_bvh(const Scene& scene, int leaf_size = 8);

}  // namespace exactvis::region
