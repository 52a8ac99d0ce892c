// The PVS façade (api/pvs.hpp): every cell's answer checked by the independent visibility oracle (each
// witness re-checked exactly, each hidden triangle attacked by refutation sampling), the JSON document of
// `pvs --json`, the progress callback, grid cells, and the command line's messages for bad input.
#include "api/pvs.hpp"
#include "io/load_scene.hpp"
#include "kernel/scene_generators.hpp"
#include "oracles/visibility_oracle.hpp"
#include "tests/region/oracle_input.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace exactvis;

namespace {

region::RationalBox3 box(Exact x0, Exact y0, Exact z0, Exact x1, Exact y1, Exact z1) {
  return region::RationalBox3{{x0, y0, z0}, {x1, y1, z1}};
}

TEST(ApiPvs, CellsCheckedByOracleAndJson) {
  const Scene scene = generate_scene("town", 120, 3);
  const Box3 b = bounding_box(scene);
  api::PvsRequest request;
  request.cells = {box(Exact(b.lo.x), Exact(b.lo.y), Exact(1, 4), Exact(b.lo.x) + 2, Exact(b.lo.y) + 2, Exact(1)),
                   box(Exact(b.hi.x) - 3, Exact(b.hi.y) - 3, Exact(1, 2), Exact(b.hi.x) - 1, Exact(b.hi.y) - 1, 2)};
  request.options.threads = 2;
  std::vector<std::int64_t> seen;
  request.progress = [&](std::int64_t decided, std::int64_t total) {
    EXPECT_EQ(total, 2 * static_cast<std::int64_t>(scene.triangles.size()));
    seen.push_back(decided);
  };
  const api::PvsAnswer a = api::pvs(scene, request);
  ASSERT_EQ(a.cells.size(), 2u);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), 2 * static_cast<std::int64_t>(scene.triangles.size()));
  for (std::size_t k = 1; k < seen.size(); ++k) EXPECT_LT(seen[k - 1], seen[k]) << "call " << k;
  const auto os = region_test::oracle_scene(scene);
  const nlohmann::ordered_json j = api::pvs_json(scene, a, "town.obj");
  EXPECT_EQ(j["scene"], "town.obj");
  EXPECT_EQ(j["triangles"], scene.triangles.size());
  ASSERT_EQ(j["cells"].size(), 2u);
  EXPECT_EQ(j["stats"]["cells"], 2);
  for (std::size_t c = 0; c < 2; ++c) {
    const region::RationalBox3& cell = request.cells[c];
    const auto src = region_test::oracle_box(cell.lo, cell.hi);
    std::vector<char> visible(scene.triangles.size(), 0);
    const nlohmann::ordered_json& cj = j["cells"][c];
    EXPECT_EQ(cj["cell"], c);
    ASSERT_EQ(cj["visible"].size(), a.cells[c].visible.size());
    for (std::size_t k = 0; k < a.cells[c].visible.size(); ++k) {
      const region::VisibleTriangle& v = a.cells[c].visible[k];
      visible[v.index] = 1;
      EXPECT_EQ(cj["visible"][k], scene.triangles[v.index].id);
      ASSERT_TRUE(v.witness.has_value());
      std::string why;
      EXPECT_TRUE(oracle::witness_is_valid(os, v.index, src, region_test::qv(v.witness->p),
                                           region_test::qv(v.witness->q), &why))
          << "cell " << c << " triangle " << v.index << ": " << why;
    }
    for (std::size_t t = 0; t < scene.triangles.size(); t += 2)  // hidden answers attacked (every other one)
      if (!visible[t]) EXPECT_FALSE(oracle::find_robust_free_segment(os, t, src, 60, 5)) << "cell " << c << " " << t;
    EXPECT_GT(a.cells[c].visible.size(), 0u);
  }
  EXPECT_FALSE(api::pvs_json(scene, a, nullptr, false)["cells"][0].contains("witnesses"));
}

TEST(ApiPvs, GridCellsAndMessages) {
  const Scene scene = generate_scene("random", 20, 2);
  const auto cells = api::grid_view_cells(scene, {2, 3, 1});
  ASSERT_EQ(cells.size(), 6u);
  const region::RationalBox3 whole = region::exact_box(bounding_box(scene));
  EXPECT_EQ(cells[0].lo.x, whole.lo.x);
  EXPECT_EQ(cells[5].hi.y, whole.hi.y);
  EXPECT_EQ(api::grid_view_cells(scene, {1, 1, 1}, box(0, 0, 0, 1, 2, 3))[0].hi.z, Exact(3));
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message([] { api::grid_view_cells(Scene{}, {1, 1, 1}); }), "--grid: the scene is empty; give --box");
  const Scene flat = scene_from_arrays({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  EXPECT_EQ(message([&] { api::grid_view_cells(flat, {1, 1, 1}); }),
            "--grid: the scene's bounding box is flat in z; give --box");
  api::PvsRequest r;
  r.cells = {box(0, 0, 0, 1, 1, 1)};
  r.options.threads = 2000;
  EXPECT_EQ(message([&] { api::pvs(scene, r); }), "--threads: 2000 is not a thread count (0 = all cores, or 1 .. 1024)");
  r.options.threads = 0;
  r.options.query.samples = -1;
  EXPECT_EQ(message([&] { api::pvs(scene, r); }), "--samples must be >= 0");
  r.options.query.samples = 48;
  r.cells = {box(0, 0, 0, 1, 0, 1)};
  EXPECT_NE(message([&] { api::pvs(scene, r); }), "no error");
}

}  // namespace
