// The PVS hierarchy (region/triangle_bvh.hpp): structural invariants checked by brute force on generated
// scenes — each node's box is exactly the min/max of its triangles' corners, children partition their parent's
// range, `position` inverts `order`, leaves are small, and a node holding several objects never splits one
// object between its children (each object is one subtree).
#include "kernel/scene_generators.hpp"
#include "region/triangle_bvh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace exactvis;
using namespace exactvis::region;

namespace {

void check_bvh(const Scene& scene, int leaf_size) {
  const TriangleBvh bvh = build_triangle_bvh(scene, leaf_size);
  const int n = static_cast<int>(scene.triangles.size());
  ASSERT_EQ(static_cast<int>(bvh.order.size()), n);
  ASSERT_EQ(static_cast<int>(bvh.position.size()), n);
  std::vector<int> seen(n, 0);
  for (int i = 0; i < n; ++i) {
    ++seen[bvh.order[i]];
    EXPECT_EQ(bvh.position[bvh.order[i]], i);
  }
  for (int t = 0; t < n; ++t) EXPECT_EQ(seen[t], 1);
  ASSERT_FALSE(bvh.nodes.empty());
  EXPECT_EQ(bvh.nodes[0].begin, 0);
  EXPECT_EQ(bvh.nodes[0].end, n);
  for (const BvhNode& node : bvh.nodes) {
    ASSERT_LT(node.begin, node.end);
    Box3 b{scene.corner(scene.triangles[bvh.order[node.begin]], 0), scene.corner(scene.triangles[bvh.order[node.begin]], 0)};
    std::set<int> objects;
    for (int i = node.begin; i < node.end; ++i) {
      const SceneTriangle& t = scene.triangles[bvh.order[i]];
      objects.insert(t.object);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) {
          b.lo[k] = std::min(b.lo[k], scene.corner(t, c)[k]);
          b.hi[k] = std::max(b.hi[k], scene.corner(t, c)[k]);
        }
    }
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(node.box.lo[k], b.lo[k]);
      EXPECT_EQ(node.box.hi[k], b.hi[k]);
    }
    if (node.left < 0) {
      EXPECT_LE(node.end - node.begin, leaf_size);
      EXPECT_LT(node.right, 0);
      continue;
    }
    const BvhNode& l = bvh.nodes[node.left];
    const BvhNode& r = bvh.nodes[node.right];
    EXPECT_EQ(l.begin, node.begin);
    EXPECT_EQ(l.end, r.begin);
    EXPECT_EQ(r.end, node.end);
    if (objects.size() > 1) {
      std::set<int> left_objects, right_objects;
      for (int i = l.begin; i < l.end; ++i) left_objects.insert(scene.triangles[bvh.order[i]].object);
      for (int i = r.begin; i < r.end; ++i) right_objects.insert(scene.triangles[bvh.order[i]].object);
      for (int o : left_objects) EXPECT_EQ(right_objects.count(o), 0u) << "object " << o << " split between children";
    }
  }
}

TEST(TriangleBvh, ObjectsStayWholeAndBoxesAreExact) {
  check_bvh(generate_scene("town", 3000, 2), 8);
  check_bvh(generate_scene("forest", 1000, 3), 8);
  check_bvh(generate_scene("room", 500, 4), 4);
  check_bvh(generate_scene("random", 300, 5), 1);
}

}  // namespace
