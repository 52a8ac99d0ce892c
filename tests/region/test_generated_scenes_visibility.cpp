// From-region visibility on the generated town and forest (closed box buildings with windows, ground plane
// coplanar with building bottoms, many small crown triangles): every answer checked by the independent
// oracle (witness re-check; refutation sampling of hidden answers).
#include "kernel/scene_generators.hpp"
#include "kernel/triangle_index.hpp"
#include "oracles/visibility_oracle.hpp"
#include "tests/region/oracle_input.hpp"
#include "region/from_region_visibility.hpp"

#include <gtest/gtest.h>

using namespace exactvis;
using namespace exactvis::region;

namespace {

using region_test::qv;

struct Tally {
  int visible = 0, hidden = 0;
};

Tally check_scene(const Scene& scene, const Box3& cell, int stride) {
  const TriangleIndex index(scene);
  const CandidateFinder finder = [&index](const Box3& b) { return index.candidates_in_box(b); };
  const std::vector<oracle::Triangle> os = region_test::oracle_scene(scene);
  const oracle::Source src = region_test::oracle_box(cell.lo, cell.hi);
  Tally tally;
  for (std::size_t i = 0; i < scene.triangles.size(); i += stride) {
    const VisibilityResult r = visible_from_box(scene, finder, cell, static_cast<std::int64_t>(i));
    if (r.visible) {
      ++tally.visible;
      std::string why;
      EXPECT_TRUE(oracle::witness_is_valid(os, i, src, qv(r.witness->p), qv(r.witness->q), &why)) << i << ": " << why;
    } else {
      ++tally.hidden;
      EXPECT_FALSE(oracle::find_robust_free_segment(os, i, src, 200, i).has_value())
          << "triangle index " << i << " reported hidden, oracle found a free segment";
    }
  }
  return tally;
}

}  // namespace

TEST(GeneratedScenesVisibility, TownAgreesWithOracle) {
  const Scene scene = generate_scene("town", 600, 7);
  const Box3 b = bounding_box(scene);
  // A street-level cell near one corner of the town.
  const Box3 cell{{b.lo.x + 0.25, b.lo.y + 0.25, 1}, {b.lo.x + 1.5, b.lo.y + 1.5, 2}};
  const Tally t = check_scene(scene, cell, 3);
  EXPECT_GT(t.visible, 5);
  EXPECT_GT(t.hidden, 5);
}

TEST(GeneratedScenesVisibility, ForestAgreesWithOracle) {
  const Scene scene = generate_scene("forest", 600, 11);
  const Box3 b = bounding_box(scene);
  const Box3 cell{{b.lo.x, b.lo.y, 1}, {b.lo.x + 1, b.lo.y + 1, 2}};
  const Tally t = check_scene(scene, cell, 3);
  EXPECT_GT(t.visible, 5);
  EXPECT_GT(t.hidden, 5);
}
