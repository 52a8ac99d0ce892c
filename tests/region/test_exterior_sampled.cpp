// region/exterior_sampled (the seed-003 sampling pipeline): what it keeps on models whose answer is known,
// its known miss (a slit narrower than its sampling), determinism, and bad options.
#include "region/exterior_sampled.hpp"

#include "tests/region/exterior_test_scenes.hpp"

#include <gtest/gtest.h>

using namespace exactvis;
using namespace exactvis::region;
using exterior_test::ModelBuilder;

namespace {

SampledExteriorOptions small_options() {
  SampledExteriorOptions o;
  o.views = 32;
  o.resolution = 64;
  o.mc_rays = 32;
  return o;
}

TEST(ExteriorSampled, BoxInBoxKeepsTheOuterBox) {
  ModelBuilder b;
  b.box({-2, -2, -2}, {3, 3, 3});
  b.box({0, 0, 0}, {1, 1, 1});
  const FloatRayCaster caster(b.scene);
  const SampledExterior s = sampled_exterior_visibility(b.scene, caster, small_options());
  for (int i = 0; i < 24; ++i) EXPECT_EQ(s.kept[i], i < 12) << "triangle " << i;
  EXPECT_EQ(s.kept_count, 12);
  EXPECT_EQ(s.kept_by_views + s.kept_by_rays, 12);
  EXPECT_GT(s.rays_cast, 32 * 64 * 64 - 1);
}

TEST(ExteriorSampled, MissesTheTargetBehindANarrowSlit) {
  // Exactly visible through a slit 2^-20 wide (test_exterior_visibility); the sampler does not find it.
  const Scene scene = exterior_test::slit_box(std::ldexp(1.0, -21));
  const FloatRayCaster caster(scene);
  const SampledExterior s = sampled_exterior_visibility(scene, caster, small_options());
  EXPECT_FALSE(s.kept.back());
  // The outside faces are all found.
  for (std::size_t i = 0; i + 1 < scene.triangles.size(); ++i) EXPECT_TRUE(s.kept[i]) << "triangle " << i;
}

TEST(ExteriorSampled, WideOpeningIsFoundByTheRayTest) {
  // A target inside a box whose lid is half missing: no camera sees it only when it is under the lid; the
  // ray tracing test from the target finds the opening.
  ModelBuilder b;
  b.box({0, 0, 0}, {1, 1, 1}, false);
  b.quad({0, 0, 1}, {0.5, 0, 1}, {0.5, 1, 1}, {0, 1, 1});
  b.triangle({0.1, 0.1, 0.5}, {0.3, 0.1, 0.5}, {0.2, 0.3, 0.5});
  const FloatRayCaster caster(b.scene);
  SampledExteriorOptions o = small_options();
  const SampledExterior s = sampled_exterior_visibility(b.scene, caster, o);
  EXPECT_TRUE(s.kept.back());
  o.mc_rays = 0;
  o.views = 1;
  o.resolution = 1;
  EXPECT_FALSE(sampled_exterior_visibility(b.scene, caster, o).kept.back());
}

TEST(ExteriorSampled, DeterministicAcrossThreadsAndBadOptions) {
  ModelBuilder b;
  b.box({0, 0, 0}, {1, 1, 1}, false);
  b.box({0.2, 0.2, 0.2}, {0.8, 0.8, 0.8});
  const FloatRayCaster caster(b.scene);
  SampledExteriorOptions o = small_options();
  o.threads = 1;
  const auto one = sampled_exterior_visibility(b.scene, caster, o).kept;
  o.threads = 2;
  EXPECT_EQ(sampled_exterior_visibility(b.scene, caster, o).kept, one);
  o.views = 0;
  EXPECT_THROW(sampled_exterior_visibility(b.scene, caster, o), std::invalid_argument);
  o.views = 4;
  o.threads = -1;
  EXPECT_THROW(sampled_exterior_visibility(b.scene, caster, o), std::invalid_argument);
}

}  // namespace
