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
  // Object centres (of the objects' boxes): the upper levels split between objects, never through one.
  // (Object indices out of range, if any, share one key.)
  std::vector<Box3> object_box(scene.objects.size() + 1, Box3{});
  std::vector<char> object_seen(object_box.size(), 0);
  auto object_key = [&](std::int64_t t) {
    return std::min(static_cast<std::size_t>(std::max(0, scene.triangles[t].object)), object_box.size() - 1);
  };
  for (int i = 0; i < n; ++i) {
    const std::size_t o = object_key(i);
    Box3& ob = object_box[o];
    if (!object_seen[o]) ob = boxes[i], object_seen[o] = 1;
    for (int k = 0; k < 3; ++k) {
      ob.lo[k] = std::min(ob.lo[k], boxes[i].lo[k]);
      ob.hi[k] = std::max(ob.hi[k], boxes[i].hi[k]);
    }
  }
  std::vector<Point3> object_centre(object_box.size());
  for (std::size_t o = 0; o < object_box.size(); ++o)
    for (int k = 0; k < 3; ++k) object_centre[o][k] = object_box[o].lo[k] / 2 + object_box[o].hi[k] / 2;
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
    const std::size_t first_object = object_key(bvh.order[task.begin]);
    bool several_objects = false;
    for (int i = task.begin + 1; i < task.end && !several_objects; ++i)
      several_objects = object_key(bvh.order[i]) != first_object;
    int mid = task.begin + (task.end - task.begin) / 2;
    if (several_objects) {
      // Between objects: sort by object centre on the axis of their widest spread (ties: by object), then cut
      // at the object boundary nearest the middle, so each object stays inside one subtree.
      Box3 obox{{inf, inf, inf}, {-inf, -inf, -inf}};
      for (int i = task.begin; i < task.end; ++i) {
        const Point3& c = object_centre[object_key(bvh.order[i])];
        for (int k = 0; k < 3; ++k) {
          obox.lo[k] = std::min(obox.lo[k], c[k]);
          obox.hi[k] = std::max(obox.hi[k], c[k]);
        }
      }
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (obox.hi[k] - obox.lo[k] > obox.hi[axis] - obox.lo[axis]) axis = k;
      std::sort(bvh.order.begin() + task.begin, bvh.order.begin() + task.end, [&](std::int64_t a, std::int64_t b) {
        const std::size_t oa = object_key(a), ob = object_key(b);
        const double ca = object_centre[oa][axis], cb = object_centre[ob][axis];
        return ca < cb || (ca == cb && (oa < ob || (oa == ob && a < b)));
      });
      auto boundary = [&](int i) { return object_key(bvh.order[i - 1]) != object_key(bvh.order[i]); };
      for (int d = 0;; ++d) {
        if (mid - d > task.begin && boundary(mid - d)) {
          mid -= d;
          break;
        }
        if (mid + d < task.end && mid + d > task.begin && boundary(mid + d)) {
          mid += d;
          break;
        }
      }
    } else {
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (cbox.hi[k] - cbox.lo[k] > cbox.hi[axis] - cbox.lo[axis]) axis = k;
      std::nth_element(bvh.order.begin() + task.begin, bvh.order.begin() + mid, bvh.order.begin() + task.end,
                       [&](std::int64_t a, std::int64_t b) {
                         return centre[a][axis] < centre[b][axis] || (centre[a][axis] == centre[b][axis] && a < b);
                       });
    }
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
