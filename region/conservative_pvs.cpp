#include "region/conservative_pvs.hpp"

#include "region/back_face_culling.hpp"
#include "region/cell_visibility.hpp"
#include "region/single_occluder_culling.hpp"
#include "util/for_each_index.hpp"

#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <functional>

namespace exactvis::region {

CellPvs conservative_cell_pvs(const PvsContext& context, const RationalBox3& cell, const PvsOptions& options,
                              OccluderSearch search) {
  check_view_cell(cell);
  check_thread_count(options.threads);
  const auto start = std::chrono::steady_clock::now();
  const Scene& scene = context.scene();
  const std::size_t n = scene.triangles.size();
  // The wall and solid proofs (region/single_occluder_culling.hpp), prepared once for this cell.
  const SingleOccluderCulling proofs(context, cell, search);
  // Back faces of closed convex solids apart from the cell (region/back_face_culling.hpp): hidden by their own
  // solid, an exact proof the wall and solid proofs never make (they skip the target's own solid).
  const BackFaceCulling back_faces(context, cell);
  std::atomic<std::int64_t> nodes_tested{0}, nodes_hidden{0};

  std::vector<char> culled(n, 0);
  std::atomic<std::int64_t> decided{0};
  auto report = [&](std::int64_t k) {
    const std::int64_t d = decided.fetch_add(k) + k;
    if (options.on_progress) options.on_progress(d);
  };
  auto decide_triangle = [&](std::size_t i, std::ptrdiff_t& hint) {
    const auto t = static_cast<std::int64_t>(i);
    if (back_faces.hides_triangle(t) || proofs.hides_triangle(t, hint)) culled[i] = 1;
    report(1);
  };
  const TriangleBvh& bvh = context.bvh();
  std::function<void(int, std::ptrdiff_t)> visit = [&](int index, std::ptrdiff_t hint) {
    const BvhNode& node = bvh.nodes[static_cast<std::size_t>(index)];
    if (node.end - node.begin > 1) {
      nodes_tested.fetch_add(1, std::memory_order_relaxed);
      if (proofs.hides_node(node, hint)) {
        nodes_hidden.fetch_add(1, std::memory_order_relaxed);
        for (int i = node.begin; i < node.end; ++i) culled[static_cast<std::size_t>(bvh.order[static_cast<std::size_t>(i)])] = 1;
        report(node.end - node.begin);
        return;
      }
    }
    if (node.left < 0) {
      for (int i = node.begin; i < node.end; ++i) decide_triangle(static_cast<std::size_t>(bvh.order[static_cast<std::size_t>(i)]), hint);
      return;
    }
    if (options.threads == 1) {
      visit(node.left, hint);
      visit(node.right, hint);
    } else {
      tbb::parallel_invoke([&] { visit(node.left, hint); }, [&] { visit(node.right, hint); });
    }
  };
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  if (proofs.any() || back_faces.any()) {
    if (options.hierarchy && !bvh.nodes.empty()) arena.execute([&] { visit(0, -1); });
    else
      arena.execute([&] {
        for_each_index(n, options.threads != 1, 16, [&](std::size_t i) {
          std::ptrdiff_t hint = -1;
          decide_triangle(i, hint);
        });
      });
  }

  CellPvs out;
  out.cell = cell;
  out.stats.triangles = static_cast<std::int64_t>(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (culled[i]) ++out.stats.culled;
    else out.visible.push_back({static_cast<std::int64_t>(i), std::nullopt});
  }
  out.stats.visible = static_cast<std::int64_t>(out.visible.size());
  out.stats.exact_queries = proofs.exact_tests();
  out.stats.boxes_tested = nodes_tested.load();
  out.stats.boxes_culled = nodes_hidden.load();
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace exactvis::region
