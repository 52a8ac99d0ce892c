// The visibility façade (api/visible.hpp): answers by stable triangle id, every witness re-checked by the
// independent oracle and hidden answers attacked by its refutation sampling, the progress callback
// (done, total) once per triangle and never concurrently, and the command line's messages for bad input.
#include "api/visible.hpp"
#include "io/load_scene.hpp"
#include "kernel/scene_generators.hpp"
#include "oracles/visibility_oracle.hpp"
#include "tests/region/oracle_input.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>

using namespace exactvis;

namespace {

TEST(ApiVisible, AnswersByIdCheckedByOracle) {
  const Scene scene = generate_scene("town", 200, 5);
  api::VisibleRequest request;
  request.source.cell = api::cell_box(Exact(1, 3), Exact(1, 3), Exact(1), Exact(5, 3), Exact(5, 3), Exact(2));
  std::vector<std::int64_t> ids;
  for (std::size_t i = 0; i < scene.triangles.size(); i += 3) ids.push_back(scene.triangles[i].id);
  request.triangle_ids = ids;
  std::vector<std::int64_t> seen;
  std::atomic<int> inside{0};
  bool overlapped = false;
  request.progress = [&](std::int64_t done, std::int64_t total) {
    overlapped |= inside.fetch_add(1) != 0;
    EXPECT_EQ(total, static_cast<std::int64_t>(ids.size()));
    seen.push_back(done);
    inside.fetch_sub(1);
  };
  const api::VisibleAnswer a = api::visible(scene, request);
  EXPECT_FALSE(overlapped);
  ASSERT_EQ(seen.size(), ids.size());
  for (std::size_t k = 0; k < seen.size(); ++k) EXPECT_EQ(seen[k], static_cast<std::int64_t>(k + 1));
  ASSERT_EQ(a.triangles.size(), ids.size());
  const auto os = region_test::oracle_scene(scene);
  const auto src = region_test::oracle_box(request.source.cell->lo, request.source.cell->hi);
  std::int64_t visible = 0;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const api::VisibleTriangle& t = a.triangles[k];
    EXPECT_EQ(t.id, ids[k]);
    const auto index = static_cast<std::size_t>(scene.index_of_id(t.id));
    EXPECT_EQ(t.visible, t.witness.has_value());
    if (t.visible) {
      ++visible;
      std::string why;
      EXPECT_TRUE(oracle::witness_is_valid(os, index, src, region_test::qv(t.witness->p), region_test::qv(t.witness->q),
                                           &why))
          << "id " << t.id << ": " << why;
    } else {
      EXPECT_FALSE(oracle::find_robust_free_segment(os, index, src, 100, 11)) << "id " << t.id << " is visible";
    }
  }
  EXPECT_EQ(a.visible, visible);
  EXPECT_GT(visible, 0);
  EXPECT_LT(visible, static_cast<std::int64_t>(ids.size()));
}

TEST(ApiVisible, AllTrianglesInIdOrderAndArraysScene) {
  // A unit square at z = 2 over the cell hides the small triangle above it; the far triangle is visible.
  const std::vector<Point3> V{{-1, -1, 2}, {2, -1, 2}, {2, 2, 2}, {-1, 2, 2}, {0.4, 0.4, 3},
                              {0.6, 0.4, 3}, {0.5, 0.6, 3}, {10, 0, 0}, {11, 0, 0}, {10, 1, 0}, {5, 5, 5}};
  const Scene scene = scene_from_arrays(V, {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {10, 10, 10}, {7, 8, 9}});
  api::VisibleRequest request;
  request.source.cell = api::cell_box(0, 0, 0, 1, 1, 1);
  const api::VisibleAnswer a = api::visible(scene, request);
  ASSERT_EQ(a.triangles.size(), 4u);  // face 3 has zero area: dropped, its id absent
  const std::int64_t ids[] = {0, 1, 2, 4};
  const bool vis[] = {true, true, false, true};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(a.triangles[k].id, ids[k]);
    EXPECT_EQ(a.triangles[k].visible, vis[k]) << k;
  }
  EXPECT_EQ(a.visible, 3);
}

TEST(ApiVisible, BadInputHasTheCommandLineMessages) {
  const Scene scene = generate_scene("random", 20, 1);
  auto message = [&](api::VisibleRequest r) -> std::string {
    try {
      api::visible(scene, r);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  api::VisibleRequest r;
  r.source.cell = api::cell_box(0, 0, 0, 1, 1, 1);
  r.triangle_ids = std::vector<std::int64_t>{0, 12345};
  EXPECT_EQ(message(r), "--triangles: triangle id 12345 is not in the scene (out of range, or dropped as degenerate)");
  r.triangle_ids.reset();
  r.threads = -1;
  EXPECT_EQ(message(r), "--threads: -1 is not a thread count (0 = all cores, or 1 .. 1024)");
  r.threads = 0;
  r.samples = -2;
  EXPECT_EQ(message(r), "--samples must be >= 0");
  api::VisibleRequest p;
  p.source.polygon = {RationalPoint3{0, 0, 0}, RationalPoint3{1, 0, 0}, RationalPoint3{2, 0, 0}};
  EXPECT_EQ(message(p).rfind("--source-polygon: ", 0), 0u) << message(p);
  EXPECT_THROW(api::cell_box(0, 0, 0, 1, 0, 1), std::invalid_argument);
}

}  // namespace
