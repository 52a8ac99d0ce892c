// region/exterior_enclosure: shells and their closedness on hand-built models (shared edges, T-junctions,
// duplicates, non-manifold edges), and every enclosure proof re-checked by the independent oracle: its ray
// crosses the shell an odd number of times, each crossing through a triangle's interior.
#include "region/exterior_enclosure.hpp"

#include "oracles/exterior_oracle.hpp"
#include "tests/region/exterior_test_scenes.hpp"
#include "tests/region/oracle_input.hpp"

#include <gtest/gtest.h>

using namespace exactvis;
using namespace exactvis::region;
using exterior_test::ModelBuilder;

namespace {

TEST(ExteriorEnclosure, ShellsAndClosedness) {
  ModelBuilder b;
  b.box({0, 0, 0}, {1, 1, 1});                 // closed
  b.box({2, 0, 0}, {3, 1, 1}, false);          // open (no lid)
  b.box({4, 0, 0}, {5, 1, 1});                 // closed, plus a duplicate face: an odd edge count
  b.scene.triangles.push_back(b.scene.triangles.back());
  b.scene.triangles.back().id = static_cast<std::int64_t>(b.scene.triangles.size()) - 1;
  const SceneShells shells(b.scene);
  ASSERT_EQ(shells.shells(), 3);
  EXPECT_TRUE(shells.closed(shells.shell_of(0)));
  EXPECT_FALSE(shells.closed(shells.shell_of(12)));
  EXPECT_FALSE(shells.closed(shells.shell_of(22)));
  EXPECT_EQ(shells.closed_shells(), 1);
  // The lid of the slit model at h = 0 is watertight, but its seam ends in the middle of the walls' top
  // edges (T-junctions): not closed as vertex pairs, so enclosure cannot be used (the query decides).
  const Scene closed_slit = exterior_test::slit_box(0);
  const SceneShells s2(closed_slit);
  EXPECT_FALSE(s2.closed(s2.shell_of(0)));
  const Scene open_slit = exterior_test::slit_box(std::ldexp(1.0, -21));
  const SceneShells s3(open_slit);
  EXPECT_FALSE(s3.closed(s3.shell_of(0)));
}

TEST(ExteriorEnclosure, ProofsAreRecheckedByTheOracle) {
  ModelBuilder b;
  b.box({-2, -2, -2}, {3, 3, 3});
  b.box({0, 0, 0}, {1, 1, 1});
  b.triangle({-1, -1, 2}, {2, -1, 2}, {0.5, 2, 2.5});  // loose, inside the outer box
  b.triangle({-1, -1, 4}, {2, -1, 4}, {0.5, 2, 4.5});  // outside
  const Scene& s = b.scene;
  const TriangleIndex index(s);
  const SceneShells shells(s);
  const auto os = region_test::oracle_scene(s);
  for (std::int64_t t = 0; t < static_cast<std::int64_t>(s.triangles.size()); ++t) {
    const auto proof = enclosing_shell(s, index, bounding_box(s), shells, t);
    const bool expect_hidden = t >= 12 && t < 25;
    ASSERT_EQ(proof.has_value(), expect_hidden) << "triangle " << t;
    if (!proof) continue;
    // Oracle: count the shell's triangles the ray crosses (transversally, through their interiors), and
    // check it touches no other part of the shell.
    const oracle::QVec q = region_test::qv(proof->q), d = region_test::qv(proof->d);
    oracle::QVec far = q + mpq_class(1000) * d;
    int crossings = 0;
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
      if (shells.shell_of(static_cast<std::int64_t>(i)) != proof->shell) continue;
      const auto& o = os[i];
      if (oracle::oracle_segment_crosses_triangle_interior(q, far, o[0], o[1], o[2])) ++crossings;
      else EXPECT_FALSE(oracle::oracle_open_segment_meets_closed_triangle(q, far, o[0], o[1], o[2]));
    }
    EXPECT_EQ(crossings, proof->crossings);
    EXPECT_EQ(crossings % 2, 1);
  }
}

}  // namespace
