#include "region/triangle_bvh.hpp"

#include <algorithm>
#include <limits>

namespace exactvis::region {

TriangleBvh build_triangle_bvh(const Scene& scene, int leaf_size) {
  TriangleBvh bvh;
  const int n = static_cast<int>(scene.triangles.size());
  if (n == 0) return bvh;
  std::vector<Box3> boxes(n);
  std::vector<Point3> centre(n);
  for (int i = 0; i < n; ++i) {
    const auto& t = scene.triangles[i];
    Box3 b{scene.corner(t, 0), scene.corner(t, 0)};
    for (int c = 1; c < 3; ++c)
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::min(b.lo[k], scene.corner(t, c)[k]);
        b.hi[k] = std::max(b.hi[k], scene.corner(t, c)[k]);
      }
    boxes[i] = b;
    for (int k = 0; k < 3; ++k) centre[i][k] = b.lo[k] / 2 + b.hi[k] / 2;  // only orders the split
  }
  bvh.order.resize(n);
  for (int i = 0; i < n; ++i) bvh.order[i] = i;
  struct Task {
    int node, begin, end;
  };
  bvh.nodes.push_back({});
  std::vector<Task> tasks{{0, 0, n}};
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    const double inf = std::numeric_limits<double>::infinity();
    Box3 box{{inf, inf, inf}, {-inf, -inf, -inf}}, cbox = box;
    for (int i = task.begin; i < task.end; ++i) {
      const auto t = bvh.order[i];
      for (int k = 0; k < 3; ++k) {
        box.lo[k] = std::min(box.lo[k], boxes[t].lo[k]);
        box.hi[k] = std::max(box.hi[k], boxes[t].hi[k]);
        cbox.lo[k] = std::min(cbox.lo[k], centre[t][k]);
        cbox.hi[k] = std::max(cbox.hi[k], centre[t][k]);
      }
    }
    BvhNode& node = bvh.nodes[task.node];
    node.box = box;
    node.begin = task.begin;
    node.end = task.end;
    if (task.end - task.begin <= std::max(1, leaf_size)) continue;
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (cbox.hi[k] - cbox.lo[k] > cbox.hi[axis] - cbox.lo[axis]) axis = k;
    const int mid = task.begin + (task.end - task.begin) / 2;
    std::nth_element(bvh.order.begin() + task.begin, bvh.order.begin() + mid, bvh.order.begin() + task.end,
                     [&](std::int64_t a, std::int64_t b) {
                       return centre[a][axis] < centre[b][axis] || (centre[a][axis] == centre[b][axis] && a < b);
                     });
    const int left = static_cast<int>(bvh.nodes.size());
    bvh.nodes.push_back({});
    bvh.nodes.push_back({});
    bvh.nodes[task.node].left = left;
    bvh.nodes[task.node].right = left + 1;
    tasks.push_back({left, task.begin, mid});
    tasks.push_back({left + 1, mid, task.end});
  }
  bvh.position.resize(n);
  for (int i = 0; i < n; ++i) bvh.position[bvh.order[i]] = i;
  return bvh;
}

}  // namespace exactvis::region
