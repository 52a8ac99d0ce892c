// Visibility of many triangles from one cell (region/cell_visibility.hpp): every witness re-checked by the
// independent oracle, hidden answers attacked by its refutation sampling, exact rational cells, answers
// independent of the thread count, the progress callback once per target, and refused thread counts.
#include "kernel/scene_generators.hpp"
#include "oracles/visibility_oracle.hpp"
#include "tests/region/oracle_input.hpp"
#include "region/cell_visibility.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>

using namespace exactvis;
using namespace exactvis::region;

namespace {

using region_test::qv;

TEST(CellVisibility, AnswersCheckedByOracleAndIndependentOfThreads) {
  const Scene scene = generate_scene("town", 300, 4);
  const TriangleIndex index(scene);
  // A cell with exact rational corners (thirds are not doubles).
  const RationalBox3 cell{{Exact(1, 3), Exact(1, 3), Exact(1)}, {Exact(5, 3), Exact(5, 3), Exact(2)}};
  std::vector<std::int64_t> targets;
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(scene.triangles.size()); i += 5) targets.push_back(i);
  targets.push_back(targets.front());  // repeats are allowed
  CellVisibilityOptions options;
  options.threads = 1;
  std::atomic<int> done{0};
  options.on_target_done = [&done] { done.fetch_add(1); };
  const CellVisibility one = visibility_from_source(scene, index, {cell, {}}, targets, options);
  EXPECT_EQ(done.load(), static_cast<int>(targets.size()));
  options.threads = 0;
  options.on_target_done = nullptr;
  const CellVisibility all = visibility_from_source(scene, index, {cell, {}}, targets, options);
  ASSERT_EQ(one.results.size(), targets.size());
  ASSERT_EQ(all.results.size(), targets.size());

  const std::vector<oracle::Triangle> os = region_test::oracle_scene(scene);
  const oracle::Source src = region_test::oracle_box(cell.lo, cell.hi);
  std::int64_t visible = 0;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const VisibilityResult& r = one.results[i];
    EXPECT_EQ(r.triangle_index, targets[i]);
    EXPECT_EQ(r.visible, all.results[i].visible) << "target " << targets[i];
    if (r.visible) {
      ++visible;
      // Same seed per target: the same witness whatever the thread count.
      EXPECT_TRUE(r.witness->p == all.results[i].witness->p && r.witness->q == all.results[i].witness->q);
      std::string why;
      EXPECT_TRUE(oracle::witness_is_valid(os, static_cast<std::size_t>(targets[i]), src, qv(r.witness->p),
                                           qv(r.witness->q), &why))
          << targets[i] << ": " << why;
    } else {
      EXPECT_FALSE(oracle::find_robust_free_segment(os, static_cast<std::size_t>(targets[i]), src, 200, 7))
          << "hidden target " << targets[i] << " has a robust free segment";
    }
  }
  EXPECT_EQ(one.visible, visible);
  EXPECT_EQ(all.visible, visible);
  EXPECT_GT(visible, 3);
  EXPECT_LT(visible, static_cast<std::int64_t>(targets.size()));
  EXPECT_EQ(one.stats.stabbing_pairs, all.stats.stabbing_pairs);
  std::int64_t sampled = 0;
  for (const auto& r : one.results) sampled += r.stats.accepted_by_sampling ? 1 : 0;
  EXPECT_EQ(one.accepted_by_sampling, sampled);
}

TEST(CellVisibility, RefusesBadThreadCountsAndTargets) {
  const Scene scene = generate_scene("random", 20, 2);
  const TriangleIndex index(scene);
  const VisibilitySource source{exact_box({{0, 0, 0}, {1, 1, 1}}), {}};
  CellVisibilityOptions options;
  for (const int bad : {-3, kMaxThreads + 1, 100000}) {
    options.threads = bad;
    EXPECT_THROW(visibility_from_source(scene, index, source, {0}, options), std::invalid_argument) << bad;
  }
  options.threads = kMaxThreads;
  EXPECT_NO_THROW(visibility_from_source(scene, index, source, {0}, options));
  options.threads = 1;
  EXPECT_THROW(visibility_from_source(scene, index, source, {20}, options), std::invalid_argument);
  EXPECT_THROW(visibility_from_source(scene, index, source, {-1}, options), std::invalid_argument);
  EXPECT_TRUE(visibility_from_source(scene, index, source, {}, options).results.empty());
}

}  // namespace
